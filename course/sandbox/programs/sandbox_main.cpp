// frob-sandbox: applies the sandbox to itself, then runs a program in its place. The grader runs the compiler and
// the controller host through it, so that every layer is in force before their first instruction.
//
//   frob-sandbox --cpu 60 --memory 2147483648 --tasks 64 --read /usr --write /tmp/build.x --cwd /tmp/build.x \
//             --report-fd 5 --keep-fds 3 -- /usr/bin/clang++ ...
#include "frob/sandbox/fd.hpp"
#include "frob/sandbox/layers.hpp"

#include <CLI/CLI.hpp>

#include <elf.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace {

// The dynamic loader an ELF program names (PT_INTERP), which the kernel runs along with it; "" if none.
std::string interpreterOf(int fd) {
  Elf64_Ehdr eh{};
  std::string interp;
  if (fd >= 0 && ::pread(fd, &eh, sizeof eh, 0) == sizeof eh && std::memcmp(eh.e_ident, ELFMAG, SELFMAG) == 0 && eh.e_ident[EI_CLASS] == ELFCLASS64) {
    for (int i = 0; i < eh.e_phnum; ++i) {
      Elf64_Phdr ph{};
      if (::pread(fd, &ph, sizeof ph, static_cast<off_t>(eh.e_phoff + i * sizeof ph)) != sizeof ph) break;
      if (ph.p_type != PT_INTERP || ph.p_filesz > 4096) continue;
      interp.resize(ph.p_filesz);
      if (::pread(fd, interp.data(), ph.p_filesz, static_cast<off_t>(ph.p_offset)) != static_cast<ssize_t>(ph.p_filesz)) interp.clear();
      interp = interp.c_str();  // without its terminating zero
    }
  }
  return interp;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace frob::sandbox;
  CLI::App cli{"Runs a program in the sandbox: resource limits, an unprivileged user, Landlock, seccomp", "frob-sandbox"};
  Limits limits;
  Namespaces namespaces;
  FileAccess files;
  std::uint32_t uid = 65534, gid = 65534;
  std::string cwd = ".", seccomp = "none";
  int keepFds = 3, reportFd = -1;
  bool rootIfUnreadable = false;
  pid_t parent = 0;
  std::vector<std::string> env, command;
  cli.add_option("--cpu", limits.cpuSeconds, "CPU seconds");
  cli.add_option("--memory", limits.memoryBytes, "address space, bytes");
  cli.add_option("--file-size", limits.fileBytes, "largest file written, bytes");
  cli.add_option("--open-files", limits.openFiles, "open file descriptors");
  cli.add_option("--stack", limits.stackBytes, "the main thread's stack, bytes");
  cli.add_option("--tasks", namespaces.tasks, "processes and threads at once, in a user namespace of its own");
  cli.add_option("--scratch", namespaces.scratch, "a folder to cover with a tmpfs of its own");
  cli.add_option("--scratch-bytes", namespaces.scratchBytes, "the size of that tmpfs");
  cli.add_option("--read", files.read, "a folder or file it may read");
  cli.add_option("--write", files.write, "a folder it may change");
  cli.add_option("--execute", files.execute, "a folder or file it may run");
  cli.add_option("--uid", uid, "user to become when run as root");
  cli.add_option("--gid", gid, "group to become when run as root");
  cli.add_flag("--root-if-unreadable", rootIfUnreadable,
               "as root, stay root if the user to become could not use the files it is given (frob's headers in a folder only root may enter)");
  cli.add_option("--cwd", cwd, "working folder");
  cli.add_option("--keep-fds", keepFds, "file descriptors 0 .. N-1 stay open; all others close");
  cli.add_option("--report-fd", reportFd, "where to write which layers were applied");
  cli.add_option("--parent", parent, "die with this process");
  cli.add_option("--env", env, "NAME=VALUE for the program's otherwise empty environment");
  cli.add_option("--seccomp", seccomp, "system-call filter")->check(CLI::IsMember({"none", "no-network"}));
  cli.add_option("command", command, "the program and its arguments")->required();
  CLI11_PARSE(cli, argc, argv);

  ::setsid();  // its own session and process group
  // A program that cannot be run is said on the report, which its caller reads as frob's failure,
  // never the program's: the report closes when the program starts (it is close-on-exec).
  const auto cannotRun = [&](const std::string& why) {
    const std::string line = "!cannot run " + command[0] + ": " + why + "\n";
    if (reportFd >= 0) {
      [[maybe_unused]] const ssize_t n = ::write(reportFd, line.data(), line.size());
    }
    std::fprintf(stderr, "frob-sandbox: %s", line.c_str() + 1);
    return 127;
  };
  // Opened before the user changes: the program may sit in a folder only the caller can enter.
  const int program = ::open(command[0].c_str(), O_RDONLY | O_CLOEXEC);
  if (program < 0 || ::chdir(cwd.c_str()) != 0) return cannotRun(std::string(std::strerror(errno)) + " (in " + cwd + ")");
  // Every descriptor closes but 0 .. keepFds-1, the report and the program.
  if (reportFd >= 0 && reportFd < keepFds) reportFd = -1;
  int from = keepFds;
  for (int keep : {std::min(reportFd, program), std::max(reportFd, program)}) {
    if (keep < from) continue;
    if (keep > from) ::syscall(SYS_close_range, from, keep - 1, 0);
    from = keep + 1;
  }
  ::syscall(SYS_close_range, from, ~0U, 0);
  files.execute.push_back(command[0]);
  if (std::string loader = interpreterOf(program); !loader.empty()) files.execute.push_back(loader);
  const Layer resources = limitResources(limits);  // while /proc/self is still its own to write
  const std::string unreachable = rootIfUnreadable && ::geteuid() == 0 ? unreachableAs(uid, gid, files, cwd) : "";
  const Layer user = unreachable.empty() ? dropPrivileges(uid, gid)
                                         : Layer{"unprivileged user", false, false, "uid " + std::to_string(uid) + " cannot use " + unreachable};
  std::vector<Layer> layers{resources, user, enterNamespaces(namespaces)};
  if (::chdir(cwd.c_str()) != 0) return cannotRun(std::string("entering ") + cwd + ": " + std::strerror(errno));  // into the tmpfs, if one covers it
  layers.push_back(noNewPrivileges());
  layers.push_back(restrictFiles(files));
  if (seccomp == "no-network") layers.push_back(restrictSyscalls(SyscallPolicy::NoNetwork));
  // Killed with the process that started it; set after the user changed, which clears it.
  ::prctl(PR_SET_PDEATHSIG, SIGKILL);
  if (parent != 0 && ::getppid() != parent) return 127;
  if (reportFd >= 0) {  // close-on-exec: the report ends as the program starts
    std::string report;
    for (const Layer& l : layers) report += l.name + "\t" + (l.applied ? "1" : "0") + (l.required ? "1" : "0") + "\t" + l.note + "\n";
    [[maybe_unused]] const ssize_t n = ::write(reportFd, report.data(), report.size());
    ::fcntl(reportFd, F_SETFD, FD_CLOEXEC);
  }

  std::vector<char*> args, envp;
  for (std::string& a : command) args.push_back(a.data());
  for (std::string& e : env) envp.push_back(e.data());
  args.push_back(nullptr), envp.push_back(nullptr);
  ::syscall(SYS_execveat, program, "", args.data(), envp.data(), AT_EMPTY_PATH);
  return cannotRun(std::strerror(errno));
}
