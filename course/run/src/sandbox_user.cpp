#include "sandbox_user.hpp"

#include <fcntl.h>
#include <pwd.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <string>

namespace frob::course {

namespace {

// The folder of the ids' locks, made by root for root alone: /run's, else the temporary folder's.
// One that another user made or may change is refused, lest they hold or free ids.
Result<sandbox::Fd> lockFolder() {
  std::error_code ec;
  const std::filesystem::path temp = std::filesystem::temp_directory_path(ec);
  std::string why;
  for (const std::filesystem::path& dir : {std::filesystem::path("/run"), temp}) {
    if (dir.empty() || !std::filesystem::is_directory(dir, ec)) continue;
    const std::string folder = (dir / "frob-sandbox-users").string();
    if (::mkdir(folder.c_str(), 0700) != 0 && errno != EEXIST) {
      why = folder + ": " + std::strerror(errno);
      continue;
    }
    sandbox::Fd fd(::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC));
    struct stat st {};
    if (!fd.valid() || ::fstat(fd.get(), &st) != 0) {
      why = folder + ": " + std::strerror(errno);
    } else if (st.st_uid != 0 || (st.st_mode & 022) != 0) {
      why = folder + " belongs to another user, or others may change it";
    } else {
      return fd;
    }
  }
  return Status::failure("cannot keep the sandbox's users apart: " + why);
}

// Kills every process running as `uid` (as root): a child that becomes `uid` may signal exactly those,
// and kill(-1) does. A fork under way when the signal comes is undone by the kernel, so none is left
// to run; the second round checks. The child shares frob's memory (vfork), so it makes system calls only.
void killEveryProcessOf(std::uint32_t uid) {
  for (int round = 0; round < 2; ++round) {
    const pid_t pid = ::vfork();
    if (pid == 0) {
      const bool became =
          ::syscall(SYS_setgroups, 0, nullptr) == 0 && ::syscall(SYS_setresgid, uid, uid, uid) == 0 && ::syscall(SYS_setresuid, uid, uid, uid) == 0;
      ::_exit(became && ::syscall(SYS_kill, -1, SIGKILL) == 0 ? 0 : 1);
    }
    int status = 0;
    while (pid > 0 && ::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    if (pid < 0 || !WIFEXITED(status) || WEXITSTATUS(status) != 0) return;  // none was left (or frob cannot fork: its run fails anyway)
  }
}

}  // namespace

SandboxUser::~SandboxUser() {
  if (lock_.valid()) killEveryProcessOf(uid_);
}

SandboxUser::SandboxUser(SandboxUser&& o) noexcept : uid_(o.uid_), lock_(std::move(o.lock_)) {}

SandboxUser& SandboxUser::operator=(SandboxUser&& o) noexcept {
  if (this != &o) {
    if (lock_.valid()) killEveryProcessOf(uid_);
    uid_ = o.uid_;
    lock_ = std::move(o.lock_);
  }
  return *this;
}

Result<SandboxUser> SandboxUser::take() {
  SandboxUser user;
  if (::geteuid() != 0) return user;
  Result<sandbox::Fd> folder = lockFolder();
  if (!folder) return folder.status();
  for (std::uint32_t uid = kFirstSandboxUid; uid < kEndSandboxUid; ++uid) {
    passwd entry{};
    passwd* account = nullptr;
    char text[4096];
    if (::getpwuid_r(uid, &entry, text, sizeof text, &account) == 0 && account != nullptr) continue;  // an account's
    sandbox::Fd lock(::openat(folder.value().get(), std::to_string(uid).c_str(), O_RDWR | O_CREAT | O_NOFOLLOW | O_CLOEXEC, 0600));
    if (!lock.valid()) return Status::failure("cannot keep the sandbox's users apart: lock " + std::to_string(uid) + ": " + std::strerror(errno));
    if (::flock(lock.get(), LOCK_EX | LOCK_NB) != 0) continue;  // another sandboxed program's
    user.uid_ = uid;
    user.lock_ = std::move(lock);
    return user;
  }
  return Status::failure("cannot keep the sandbox's users apart: all " + std::to_string(kEndSandboxUid - kFirstSandboxUid) + " user ids from " +
                         std::to_string(kFirstSandboxUid) + " are in use");
}

}  // namespace frob::course
