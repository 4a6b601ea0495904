#include "sandboxed.hpp"

#include "frob/base/layout.hpp"
#include "frob/run/controller_file.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <sstream>

namespace frob::course {

Result<Sandboxed> Sandboxed::start(const SandboxedDef& def) {
  Result<sandbox::Pipe> report = sandbox::openPipe("cannot start the sandbox");
  if (!report) return graderFailure(report.error());
  const int keep = static_cast<int>(def.fds.size());
  std::vector<std::string> args{layout().sandbox.string(),
                                "--keep-fds",
                                std::to_string(keep),
                                "--report-fd",
                                std::to_string(keep),
                                "--parent",
                                std::to_string(::getpid()),
                                "--cwd",
                                def.cwd};
  const auto add = [&](const char* flag, auto value) {
    if (value != 0) args.insert(args.end(), {flag, std::to_string(value)});
  };
  add("--cpu", def.limits.cpuSeconds);
  if (!kSanitizedBuild) add("--memory", def.limits.memoryBytes);
  add("--file-size", def.limits.fileBytes);
  add("--open-files", def.limits.openFiles);
  add("--stack", def.limits.stackBytes);
  add("--tasks", def.namespaces.tasks);
  if (!def.namespaces.scratch.empty()) {
    args.insert(args.end(), {"--scratch", def.namespaces.scratch});
    add("--scratch-bytes", def.namespaces.scratchBytes);
  }
  for (const auto& [flag, paths] : {std::pair{"--read", &def.files.read}, {"--write", &def.files.write}, {"--execute", &def.files.execute}}) {
    for (const std::string& p : *paths) args.insert(args.end(), {flag, p});
  }
  for (const std::string& e : def.env) args.insert(args.end(), {"--env", e});
  Result<SandboxUser> user = SandboxUser::take();
  if (!user) return graderFailure(user.error());
  if (user.value().held()) {
    const std::string id = std::to_string(user.value().uid());
    args.insert(args.end(), {"--uid", id, "--gid", id});
    // EINVAL: root of a user namespace where the id has no mapping; the sandbox then says it stays root.
    for (const std::string& f : def.own) {
      if (::chown(f.c_str(), user.value().uid(), user.value().uid()) != 0 && errno != EINVAL)
        return graderFailure("cannot give " + f + " to user " + id + ": " + std::strerror(errno));
    }
  }
  if (def.rootIfUnreadable) args.push_back("--root-if-unreadable");
  if (def.noNetwork) args.insert(args.end(), {"--seccomp", "no-network"});
  args.push_back("--");
  args.insert(args.end(), def.command.begin(), def.command.end());

  // Each descriptor, the report's too, is copied here to a number above `keep` (the lowest free
  // ones, so within the open-files limit), and the program's copies made from those: no copy
  // overwrites a source, wherever the sources are (the report's pipe takes the lowest free numbers,
  // which another thread may just have freed below `keep`). Ours close-on-exec, and when we return.
  std::vector<int> sources = def.fds;
  sources.push_back(report.value().write.get());
  std::vector<sandbox::Fd> copies;
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  int added = 0;
  for (int k = 0; k <= keep && added == 0; ++k) {
    if (sources[k] < 0) {
      added = posix_spawn_file_actions_addopen(&actions, k, "/dev/null", O_RDWR, 0);
    } else {
      copies.emplace_back(::fcntl(sources[k], F_DUPFD_CLOEXEC, keep + 1));
      added = copies.back().valid() ? posix_spawn_file_actions_adddup2(&actions, copies.back().get(), k) : errno;
    }
  }
  if (added != 0) {
    posix_spawn_file_actions_destroy(&actions);
    return graderFailure("cannot give the sandbox its descriptors: " + std::string(std::strerror(added)));
  }
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  char* noEnv[] = {nullptr};
  Sandboxed j;
  j.user_ = std::move(user.value());
  const int err = ::posix_spawn(&j.pid_, argv[0], &actions, nullptr, argv.data(), noEnv);
  posix_spawn_file_actions_destroy(&actions);
  report.value().write.reset();  // ours, and the copies: the report ends when frob-sandbox closes its own
  copies.clear();
  if (err != 0) {
    j.pid_ = 0;
    return graderFailure("cannot start the sandbox " + layout().sandbox.string() + ": " + std::strerror(err));
  }
  j.pidfd_.reset(static_cast<int>(::syscall(SYS_pidfd_open, j.pid_, 0)));
  // The report ends as frob-sandbox runs the program (or dies); a line "!why" says it could not.
  std::string text;
  char buf[4096];
  for (ssize_t n; (n = ::read(report.value().read.get(), buf, sizeof buf)) != 0;) {
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) break;
    text.append(buf, static_cast<std::size_t>(n));
  }
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    if (line.starts_with('!')) return graderFailure(line.substr(1) + " (exit status " + std::to_string(WEXITSTATUS(j.wait())) + ")");
    const std::size_t a = line.find('\t'), b = line.find('\t', a + 1);
    if (b == std::string::npos) continue;
    const std::string flags = line.substr(a + 1, b - a - 1);  // applied, then required
    j.layers_.push_back({line.substr(0, a), flags.starts_with("1"), flags.ends_with("1"), line.substr(b + 1)});
  }
  if (j.layers_.empty()) {  // no report: whatever runs is unconfirmed, and is killed (one that had ended keeps its status)
    j.kill();
    return graderFailure("the sandbox " + layout().sandbox.string() + " did not start: status " + std::to_string(j.wait()));
  }
  return j;
}

Sandboxed::~Sandboxed() {
  if (pid_ > 0) {
    kill();
    wait();
  }
}

Sandboxed::Sandboxed(Sandboxed&& o) noexcept { *this = std::move(o); }

Sandboxed& Sandboxed::operator=(Sandboxed&& o) noexcept {
  std::swap(pid_, o.pid_);
  std::swap(pidfd_, o.pidfd_);
  std::swap(status_, o.status_);
  std::swap(peakMemoryBytes_, o.peakMemoryBytes_);
  std::swap(layers_, o.layers_);
  std::swap(user_, o.user_);
  return *this;
}

void Sandboxed::kill() {
  if (pid_ <= 0 || status_ != -1) return;
  ::kill(-pid_, SIGKILL);  // its process group: any thread or child it has
  ::kill(pid_, SIGKILL);   // in case it had not made its own group yet
}

int Sandboxed::wait() {
  if (pid_ > 0 && status_ == -1) {
    int status = 0;
    rusage usage{};
    while (::wait4(pid_, &status, 0, &usage) < 0 && errno == EINTR) {
    }
    status_ = status;
    peakMemoryBytes_ = static_cast<std::uint64_t>(usage.ru_maxrss) << 10;  // kernel's KiB
    user_ = SandboxUser();                                                 // its id is free once nothing runs as it
  }
  return status_;
}

Result<SandboxedRun> runSandboxed(SandboxedDef def, double seconds, std::size_t outputBytes) {
  Result<sandbox::Pipe> out = sandbox::openPipe("cannot start the sandbox");
  if (!out) return graderFailure(out.error());
  def.fds.resize(std::max<std::size_t>(def.fds.size(), 3), -1);
  def.fds[1] = def.fds[2] = out.value().write.get();
  Result<Sandboxed> started = Sandboxed::start(def);
  out.value().write.reset();  // so that the output ends when the program and its children are gone
  if (!started) return started.status();
  const int output = out.value().read.get();
  Sandboxed& j = started.value();
  SandboxedRun run{.layers = j.layers()};
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  std::string tail;  // the last half of the limit, where a crash says what it is
  std::size_t cut = 0;
  char buf[1 << 16];
  // Read until the pipe closes (the program and anything it started are gone) or time is up.
  for (bool open = true; open;) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now()).count();
    if (left <= 0) {
      run.timedOut = true;
      j.kill();
      break;
    }
    pollfd p{output, POLLIN, 0};
    if (::poll(&p, 1, static_cast<int>(std::min<long long>(left, 1000))) <= 0) continue;
    const ssize_t n = ::read(output, buf, sizeof buf);
    if (n < 0 && errno == EINTR) continue;
    open = n > 0;
    if (n <= 0) continue;
    const std::size_t taken = std::min(static_cast<std::size_t>(n), outputBytes / 2 - std::min(outputBytes / 2, run.output.size()));
    run.output.append(buf, taken);
    tail.append(buf + taken, static_cast<std::size_t>(n) - taken);
    if (tail.size() > outputBytes / 2) cut += tail.size() - outputBytes / 2, tail.erase(0, tail.size() - outputBytes / 2);
  }
  if (cut > 0) run.output += "\n[... " + std::to_string(cut) + " bytes cut ...]\n";
  run.output += tail;
  run.status = j.wait();
  run.peakMemoryBytes = j.peakMemoryBytes();
  return run;
}

}  // namespace frob::course
