#include "sandbox_user.hpp"

#include <dirent.h>
#include <fcntl.h>
#include <pwd.h>
#include <sys/file.h>
#include <sys/prctl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

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

// The text of /proc/<pid>/<file>, at most `bytes` of it ("" when it cannot be read).
std::string procText(int proc, const char* pid, const char* file, std::size_t bytes) {
  const std::string path = std::string(pid) + "/" + file;
  const sandbox::Fd fd(::openat(proc, path.c_str(), O_RDONLY | O_CLOEXEC));
  std::string text(bytes, '\0');
  const ssize_t n = fd.valid() ? ::read(fd.get(), text.data(), bytes) : -1;
  text.resize(n > 0 ? static_cast<std::size_t>(n) : 0);
  return text;
}

// This process's children that run as `uid`, from /proc: each process's parent from its short
// `stat` (after the name in parentheses, which may hold anything), then the real user id of this
// process's children alone from their `status`, which costs the kernel more to write.
std::vector<pid_t> childrenRunningAs(std::uint32_t uid) {
  std::vector<pid_t> found;
  DIR* dir = ::opendir("/proc");
  if (dir == nullptr) return found;
  const std::string self = std::to_string(::getpid()), user = std::to_string(uid);
  while (const dirent* e = ::readdir(dir)) {
    const std::string_view name = e->d_name;
    if (name.empty() || name.find_first_not_of("0123456789") != std::string_view::npos) continue;
    const std::string stat = procText(::dirfd(dir), e->d_name, "stat", 512);
    const std::size_t named = stat.rfind(')');  // then " <state> <ppid> "
    if (named == std::string::npos || stat.compare(named + 3, self.size() + 2, " " + self + " ") != 0) continue;
    std::istringstream status(procText(::dirfd(dir), e->d_name, "status", 4096));
    std::string line, real;
    while (std::getline(status, line)) {
      if (line.starts_with("Uid:")) real = line.substr(5, line.find_first_of(" \t", line.find_first_not_of(" \t", 5)) - 5);
    }
    real.erase(0, real.find_first_not_of(" \t"));
    if (real == user) found.push_back(static_cast<pid_t>(std::stol(std::string(name))));
  }
  ::closedir(dir);
  return found;
}

// Kills and reaps every process still running as `uid` that this frob started: frob is their
// subreaper, so one that left its process group and session (orphaned) became its child. Killed
// and reaped a generation at a time: an orphan's own children become frob's as it dies. Only
// frob's own children are touched, never a process of another frob (in a container, say) that uses
// the same number.
void killEveryProcessOf(std::uint32_t uid) {
  for (std::vector<pid_t> left = childrenRunningAs(uid); !left.empty(); left = childrenRunningAs(uid)) {
    for (pid_t pid : left) ::kill(pid, SIGKILL);
    for (pid_t pid : left) {
      while (::waitpid(pid, nullptr, 0) < 0 && errno == EINTR) {
      }
    }
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
  // The sandboxed programs' orphans become frob's children, to be ended with their user (killEveryProcessOf).
  ::prctl(PR_SET_CHILD_SUBREAPER, 1);
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
