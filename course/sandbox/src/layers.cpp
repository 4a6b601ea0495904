#include "frob/sandbox/layers.hpp"

#include "frob/sandbox/fd.hpp"

#include <fcntl.h>
#include <grp.h>
#include <linux/landlock.h>
#include <sched.h>
#include <seccomp.h>
#include <signal.h>
#include <sys/mman.h>
#include <sys/mount.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <sys/sysinfo.h>
#include <ucontext.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>

namespace frob::sandbox {

namespace {

std::string errorText(const char* what) { return std::string(what) + ": " + std::strerror(errno); }

// Landlock's rights, by the ABI that added them (Debian 12's headers know only ABI 1).
constexpr std::uint64_t kFsAbi1 = (1ULL << 13) - 1;                                // EXECUTE .. MAKE_SYM
constexpr std::uint64_t kFsRefer = 1ULL << 13;                                     // ABI 2
constexpr std::uint64_t kFsTruncate = 1ULL << 14;                                  // ABI 3
constexpr std::uint64_t kFsIoctlDev = 1ULL << 15;                                  // ABI 5
constexpr std::uint64_t kNetBindTcp = 1ULL << 0, kNetConnectTcp = 1ULL << 1;       // ABI 4
constexpr std::uint64_t kScopeAbstractUnix = 1ULL << 0, kScopeSignal = 1ULL << 1;  // ABI 6
constexpr std::uint64_t kFileRights =
    LANDLOCK_ACCESS_FS_EXECUTE | LANDLOCK_ACCESS_FS_WRITE_FILE | LANDLOCK_ACCESS_FS_READ_FILE | kFsTruncate | kFsIoctlDev;

// landlock_ruleset_attr as the newest ABI lays it out; older kernels are given a prefix of it.
struct RulesetAttr {
  std::uint64_t handledFs = 0, handledNet = 0, scoped = 0;
};

// Adds a rule granting `rights` (those a file can hold, when `path` is a file) below `path`.
bool addRule(int ruleset, const std::string& path, std::uint64_t rights, std::string& problem) {
  const Fd fd(::open(path.c_str(), O_PATH | O_CLOEXEC));
  if (!fd.valid()) return errno == ENOENT;  // nothing there to grant
  struct stat st {};
  if (::fstat(fd.get(), &st) == 0 && !S_ISDIR(st.st_mode)) rights &= kFileRights;
  landlock_path_beneath_attr rule{.allowed_access = rights, .parent_fd = fd.get()};
  const long rc = ::syscall(SYS_landlock_add_rule, ruleset, LANDLOCK_RULE_PATH_BENEATH, &rule, 0);
  if (rc != 0) problem = errorText(("adding " + path).c_str());
  return rc == 0;
}

// Writes `text` to /proc/self/`file`; false with the reason in `problem` if it cannot.
bool writeProc(const char* file, const std::string& text, std::string& problem) {
  const Fd fd(::open((std::string("/proc/self/") + file).c_str(), O_WRONLY | O_CLOEXEC));
  if (fd.valid() && ::write(fd.get(), text.data(), text.size()) == static_cast<ssize_t>(text.size())) return true;
  problem = errorText(file);
  return false;
}

}  // namespace

Layer limitResources(const Limits& limits) {
  Layer layer{.name = "resource limits"};
  const auto set = [&](int resource, std::uint64_t value, const char* what) {
    if (value == 0 && resource != RLIMIT_CORE) return true;
    const rlimit r{value, value};
    if (::setrlimit(resource, &r) == 0) return true;
    layer.note = errorText(what);
    return false;
  };
  // CPU: SIGXCPU at the limit, SIGKILL one second later.
  rlimit cpu{limits.cpuSeconds, limits.cpuSeconds + 1};
  const bool ok = set(RLIMIT_CORE, 0, "no core files") && set(RLIMIT_AS, limits.memoryBytes, "memory") &&
                  set(RLIMIT_FSIZE, limits.fileBytes, "file size") && set(RLIMIT_NOFILE, limits.openFiles, "open files") &&
                  (limits.cpuSeconds == 0 || ::setrlimit(RLIMIT_CPU, &cpu) == 0 || (layer.note = errorText("cpu"), false));
  // The stack as asked, or as large as the hard limit allows: a larger one only spares a deep recursion.
  rlimit stack{};
  if (limits.stackBytes != 0 && ::getrlimit(RLIMIT_STACK, &stack) == 0) {
    stack.rlim_cur = std::min<rlim_t>(limits.stackBytes, stack.rlim_max);
    ::setrlimit(RLIMIT_STACK, &stack);
  }
  // When the machine runs short of memory (a grader's container may hold less than the limit), the
  // kernel kills the controller first, never frob; raising one's own score needs no privilege.
  std::string oomProblem;
  const bool killedFirst = writeProc("oom_score_adj", "1000", oomProblem);
  layer.applied = ok;
  if (ok) {
    layer.note = "cpu " + std::to_string(limits.cpuSeconds) + " s, " +
                 (limits.memoryBytes != 0 ? "memory " + std::to_string(limits.memoryBytes >> 20) + " MiB" : std::string("no memory limit")) +
                 ", files " + std::to_string(limits.fileBytes >> 20) + " MiB, no core files" +
                 (killedFirst ? ", killed first when memory runs short" : ", " + oomProblem);
  }
  return layer;
}

Layer dropPrivileges(std::uint32_t uid, std::uint32_t gid) {
  Layer layer{.name = "unprivileged user"};
  if (::geteuid() != 0) {
    layer.note = "not needed: not running as root";
    layer.required = false;
    return layer;
  }
  if (::setgroups(0, nullptr) != 0 || ::setresgid(gid, gid, gid) != 0 || ::setresuid(uid, uid, uid) != 0) {
    layer.note = errno == EINVAL ? "uid " + std::to_string(uid) + " has no mapping in this user namespace" : errorText("setuid");
    return layer;
  }
  layer.applied = true;
  layer.note = "uid " + std::to_string(uid);
  return layer;
}

std::string unreachableAs(std::uint32_t uid, std::uint32_t gid, const FileAccess& access, const std::string& cwd) {
  // Asked as that user (no groups, the effective ids only), with root kept to return to.
  // One it cannot become (no mapping in this user namespace) is for dropPrivileges to report.
  if (::setgroups(0, nullptr) != 0 || ::setegid(gid) != 0 || ::seteuid(uid) != 0) {
    [[maybe_unused]] const int back = ::setegid(0);
    return "";
  }
  std::string why;
  const auto ask = [&](const std::string& path, int mode) {
    if (why.empty() && ::faccessat(AT_FDCWD, path.c_str(), mode, AT_EACCESS) != 0 && errno != ENOENT) why = errorText(path.c_str());
  };
  for (const std::string& p : access.read) ask(p, R_OK);
  for (const std::string& p : access.write) ask(p, R_OK | W_OK | X_OK);
  for (const std::string& p : access.execute) ask(p, X_OK);
  ask(cwd, X_OK);
  if (::seteuid(0) != 0 || ::setegid(0) != 0) return errorText("becoming root again");
  return why;
}

Layer enterNamespaces(const Namespaces& ns) {
  Layer layer{.name = "namespaces"};
  const uid_t uid = ::geteuid();
  const gid_t gid = ::getegid();
  // Its /proc/self files belong to root once a root process changed user, unless it is dumpable again.
  ::prctl(PR_SET_DUMPABLE, 1, 0, 0, 0);
  if (::unshare(CLONE_NEWUSER | CLONE_NEWIPC | CLONE_NEWNS) != 0) {
    layer.note = "not available: " + errorText("unshare") + " (user namespaces are disabled here)";
    ::prctl(PR_SET_DUMPABLE, 0, 0, 0, 0);
    return layer;
  }
  // The same ids inside as outside, so that files it makes have an owner.
  bool ok = writeProc("setgroups", "deny", layer.note) && writeProc("uid_map", std::to_string(uid) + " " + std::to_string(uid) + " 1", layer.note) &&
            writeProc("gid_map", std::to_string(gid) + " " + std::to_string(gid) + " 1", layer.note);
  ::prctl(PR_SET_DUMPABLE, 0, 0, 0, 0);
  // Its mounts stay its own; the scratch folder is a tmpfs of bounded size, whose files never run.
  if (ok && ::mount(nullptr, "/", nullptr, MS_REC | MS_PRIVATE, nullptr) != 0) ok = false, layer.note = errorText("making mounts private");
  if (ok && !ns.scratch.empty()) {
    const std::string options = "size=" + std::to_string(ns.scratchBytes) + ",nr_inodes=4096,mode=0700";
    if (::mount("frob-scratch", ns.scratch.c_str(), "tmpfs", MS_NOSUID | MS_NODEV | MS_NOEXEC, options.c_str()) != 0) {
      ok = false, layer.note = errorText(("mounting a tmpfs on " + ns.scratch).c_str());
    }
  }
  if (ok && ns.tasks != 0) {
    const rlimit r{ns.tasks, ns.tasks};
    if (::setrlimit(RLIMIT_NPROC, &r) != 0) ok = false, layer.note = errorText("limiting processes");
  }
  layer.applied = ok;
  if (ok) {
    const std::string tasks = uid == 0 ? "; root's processes are not counted" : "; " + std::to_string(ns.tasks) + " processes and threads";
    layer.note = "user, IPC and mount" + (ns.tasks != 0 ? tasks : std::string()) +
                 (ns.scratch.empty() ? std::string() : "; scratch a " + std::to_string(ns.scratchBytes >> 20) + " MiB tmpfs");
  }
  return layer;
}

Layer noNewPrivileges() {
  Layer layer{.name = "no new privileges"};
  layer.applied = ::prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0) == 0;
  if (!layer.applied) layer.note = errorText("prctl");
  return layer;
}

Layer restrictFiles(const FileAccess& access) {
  Layer layer{.name = "landlock"};
  const long abi = ::syscall(SYS_landlock_create_ruleset, nullptr, 0, LANDLOCK_CREATE_RULESET_VERSION);
  if (abi < 1) {
    layer.note = errno == EOPNOTSUPP ? "not available: Landlock is disabled in this kernel"
                                     : "not available: this kernel has no Landlock (" + std::string(std::strerror(errno)) + ")";
    return layer;
  }
  RulesetAttr attr{.handledFs = kFsAbi1};
  std::size_t size = sizeof(std::uint64_t);
  if (abi >= 2) attr.handledFs |= kFsRefer;
  if (abi >= 3) attr.handledFs |= kFsTruncate;
  if (abi >= 4) attr.handledNet = kNetBindTcp | kNetConnectTcp, size = 2 * sizeof(std::uint64_t);
  if (abi >= 5) attr.handledFs |= kFsIoctlDev;
  if (abi >= 6) attr.scoped = kScopeAbstractUnix | kScopeSignal, size = sizeof attr;
  const Fd ruleset(static_cast<int>(::syscall(SYS_landlock_create_ruleset, &attr, size, 0)));
  if (!ruleset.valid()) {
    layer.note = errorText("landlock_create_ruleset");
    return layer;
  }
  constexpr std::uint64_t kRead = LANDLOCK_ACCESS_FS_READ_FILE | LANDLOCK_ACCESS_FS_READ_DIR;
  const std::uint64_t all = attr.handledFs & ~(LANDLOCK_ACCESS_FS_MAKE_CHAR | LANDLOCK_ACCESS_FS_MAKE_BLOCK);
  bool ok = true;
  for (const std::string& p : access.read) ok = ok && addRule(ruleset.get(), p, kRead, layer.note);
  for (const std::string& p : access.execute) ok = ok && addRule(ruleset.get(), p, kRead | LANDLOCK_ACCESS_FS_EXECUTE, layer.note);
  for (const std::string& p : access.write) ok = ok && addRule(ruleset.get(), p, all & ~LANDLOCK_ACCESS_FS_EXECUTE, layer.note);
  if (ok && ::syscall(SYS_landlock_restrict_self, ruleset.get(), 0) != 0) ok = false, layer.note = errorText("landlock_restrict_self");
  layer.applied = ok;
  if (ok) layer.note = "ABI " + std::to_string(abi);
  return layer;
}

Layer restrictSyscalls(SyscallPolicy policy) {
  Layer layer{.name = "seccomp"};
  const bool controller = policy == SyscallPolicy::Controller;
  scmp_filter_ctx ctx = ::seccomp_init(SCMP_ACT_ALLOW);
  if (ctx == nullptr) {
    layer.note = "not available: seccomp_init failed";
    return layer;
  }
  const std::uint32_t refuse = controller ? SCMP_ACT_TRAP : SCMP_ACT_ERRNO(EPERM);
  int rc = 0;
  const auto deny = [&](int call) {
    if (rc == 0) rc = ::seccomp_rule_add(ctx, refuse, call, 0);
  };
  for (int call : {SCMP_SYS(socket),
                   SCMP_SYS(socketpair),
                   SCMP_SYS(connect),
                   SCMP_SYS(bind),
                   SCMP_SYS(listen),
                   SCMP_SYS(accept),
                   SCMP_SYS(accept4),
                   SCMP_SYS(ptrace),
                   SCMP_SYS(process_vm_readv),
                   SCMP_SYS(process_vm_writev),
                   SCMP_SYS(io_uring_setup),
                   SCMP_SYS(bpf),
                   SCMP_SYS(perf_event_open),
                   SCMP_SYS(userfaultfd),
                   SCMP_SYS(mount),
                   SCMP_SYS(umount2),
                   SCMP_SYS(unshare),
                   SCMP_SYS(setns),
                   SCMP_SYS(chroot),
                   SCMP_SYS(pivot_root),
                   SCMP_SYS(keyctl),
                   SCMP_SYS(add_key),
                   SCMP_SYS(request_key),
                   SCMP_SYS(init_module),
                   SCMP_SYS(finit_module),
                   SCMP_SYS(kexec_load),
                   SCMP_SYS(personality)}) {
    deny(call);
  }
  // No changing another process's scheduling, priority or limits (a classmate's host, or frob when
  // it runs as the same user): pid 0, the caller, only; no whole group or user at once.
  const auto onlySelf = [&](std::uint32_t action, int call, unsigned arg) {
    const scmp_arg_cmp other{.arg = arg, .op = SCMP_CMP_NE, .datum_a = 0, .datum_b = 0};
    if (rc == 0) rc = ::seccomp_rule_add_array(ctx, action, call, 1, &other);
  };
  for (int call : {SCMP_SYS(sched_setscheduler), SCMP_SYS(sched_setparam), SCMP_SYS(sched_setattr), SCMP_SYS(prlimit64), SCMP_SYS(migrate_pages),
                   SCMP_SYS(move_pages)}) {
    onlySelf(refuse, call, 0);
  }
  // A controller keeps to the cores its run was given (a class's runs share the cores a run each):
  // its threads, spinning on another run's core, would slow that run until it fell behind.
  if (controller) {
    deny(SCMP_SYS(sched_setaffinity));
  } else {
    onlySelf(refuse, SCMP_SYS(sched_setaffinity), 0);
  }
  for (int call : {SCMP_SYS(setpriority), SCMP_SYS(ioprio_set)}) {
    onlySelf(refuse, call, 1);  // who
    const scmp_arg_cmp group{.arg = 0, .op = SCMP_CMP_NE, .datum_a = call == SCMP_SYS(setpriority) ? 0U /* PRIO_PROCESS */ : 1U, .datum_b = 0};
    if (rc == 0) rc = ::seccomp_rule_add_array(ctx, refuse, call, 1, &group);
  }
  if (controller) {
    // Nor reading it: what the kernel shows of another process's scheduling carries notes between
    // hosts. Refused as not implemented, which the C library takes in its stride.
    for (int call : {SCMP_SYS(sched_getaffinity), SCMP_SYS(sched_getscheduler), SCMP_SYS(sched_getparam), SCMP_SYS(sched_getattr),
                     SCMP_SYS(sched_rr_get_interval), SCMP_SYS(getpgid), SCMP_SYS(getsid), SCMP_SYS(get_robust_list)}) {
      onlySelf(SCMP_ACT_ERRNO(ENOSYS), call, 0);
    }
    onlySelf(SCMP_ACT_ERRNO(ENOSYS), SCMP_SYS(getpriority), 1);
    onlySelf(SCMP_ACT_ERRNO(ENOSYS), SCMP_SYS(ioprio_get), 1);
    if (rc == 0) rc = ::seccomp_rule_add(ctx, SCMP_ACT_ERRNO(ENOSYS), SCMP_SYS(kcmp), 0);
    // No file locks: a lock on a file every host may read (a library) is a note another host sees.
    if (rc == 0) rc = ::seccomp_rule_add(ctx, SCMP_ACT_ERRNO(ENOLCK), SCMP_SYS(flock), 0);
    for (const std::uint64_t command : {F_SETLK, F_SETLKW, F_GETLK, F_OFD_SETLK, F_OFD_SETLKW, F_OFD_GETLK}) {
      const scmp_arg_cmp locks{.arg = 1, .op = SCMP_CMP_EQ, .datum_a = command, .datum_b = 0};
      if (rc == 0) rc = ::seccomp_rule_add_array(ctx, SCMP_ACT_ERRNO(ENOLCK), SCMP_SYS(fcntl), 1, &locks);
    }
    for (int call : {SCMP_SYS(execve), SCMP_SYS(execveat), SCMP_SYS(fork), SCMP_SYS(vfork), SCMP_SYS(tkill), SCMP_SYS(pidfd_open),
                     SCMP_SYS(pidfd_send_signal), SCMP_SYS(pidfd_getfd), SCMP_SYS(setsid), SCMP_SYS(setpgid)}) {
      deny(call);
    }
    // No kernel objects shared between processes, which outlive the run and would carry notes from
    // one run, or one student, to the next: System V IPC and POSIX message queues.
    for (int call : {SCMP_SYS(shmget), SCMP_SYS(shmat), SCMP_SYS(shmctl), SCMP_SYS(msgget), SCMP_SYS(msgsnd), SCMP_SYS(msgrcv), SCMP_SYS(msgctl),
                     SCMP_SYS(semget), SCMP_SYS(semop), SCMP_SYS(semtimedop), SCMP_SYS(semctl), SCMP_SYS(mq_open), SCMP_SYS(mq_unlink),
                     SCMP_SYS(mq_timedsend), SCMP_SYS(mq_timedreceive), SCMP_SYS(mq_notify), SCMP_SYS(mq_getsetattr)}) {
      deny(call);
    }
    // Nothing that reads or changes which pages of a file the kernel caches, nor watches files: a
    // library every host may read would carry notes between hosts, and from one run to the next.
    // Refused as not implemented. cachestat is 451 on every architecture (Linux 6.5), also where this
    // libseccomp has no name for it.
    int cachestat = ::seccomp_syscall_resolve_name("cachestat");
    if (cachestat == __NR_SCMP_ERROR) cachestat = 451;
    for (int call : {SCMP_SYS(mincore), SCMP_SYS(fadvise64), SCMP_SYS(readahead), cachestat, SCMP_SYS(preadv2), SCMP_SYS(pwritev2),
                     SCMP_SYS(io_setup), SCMP_SYS(io_submit), SCMP_SYS(inotify_init), SCMP_SYS(inotify_init1), SCMP_SYS(inotify_add_watch),
                     SCMP_SYS(fanotify_init), SCMP_SYS(fanotify_mark)}) {
      if (rc == 0) rc = ::seccomp_rule_add(ctx, SCMP_ACT_ERRNO(ENOSYS), call, 0);
    }
    for (const std::uint64_t advice : {MADV_COLD, MADV_PAGEOUT}) {  // evicting a file's clean pages from the cache
      const scmp_arg_cmp evicts{.arg = 2, .op = SCMP_CMP_EQ, .datum_a = advice, .datum_b = 0};
      if (rc == 0) rc = ::seccomp_rule_add_array(ctx, SCMP_ACT_ERRNO(ENOSYS), SCMP_SYS(madvise), 1, &evicts);
    }
    // No signals asked for on a file: they could be sent to another process (before Landlock scopes signals).
    for (const std::uint64_t command : {F_SETOWN, F_SETOWN_EX, F_SETSIG, F_SETLEASE}) {
      const scmp_arg_cmp asks{.arg = 1, .op = SCMP_CMP_EQ, .datum_a = command, .datum_b = 0};
      if (rc == 0) rc = ::seccomp_rule_add_array(ctx, refuse, SCMP_SYS(fcntl), 1, &asks);
    }
    // sysinfo counts every thread of the machine (one host starts threads, another sees the count
    // move) and shows its memory, uptime and load: it traps, and the handler answers it with fixed
    // figures (refused, glibc's qsort would take garbage for memory's size and sort differently).
    if (rc == 0) rc = ::seccomp_rule_add(ctx, SCMP_ACT_TRAP, SCMP_SYS(sysinfo), 0);
    // Threads may start; processes may not. clone3 hides its flags from the filter, so it reports
    // "not implemented" and the C library falls back to clone.
    const scmp_arg_cmp noThread{.arg = 0, .op = SCMP_CMP_MASKED_EQ, .datum_a = CLONE_THREAD, .datum_b = 0};
    if (rc == 0) rc = ::seccomp_rule_add_array(ctx, refuse, SCMP_SYS(clone), 1, &noThread);
    if (rc == 0) rc = ::seccomp_rule_add(ctx, SCMP_ACT_ERRNO(ENOSYS), SCMP_SYS(clone3), 0);
    // Signals only to itself: the target (a pid, or a thread group's) must be its own pid.
    const auto self = static_cast<scmp_datum_t>(::getpid());
    for (int call : {SCMP_SYS(kill), SCMP_SYS(tgkill), SCMP_SYS(rt_sigqueueinfo), SCMP_SYS(rt_tgsigqueueinfo)}) {
      for (scmp_compare op : {SCMP_CMP_GT, SCMP_CMP_LT}) {
        const scmp_arg_cmp other{.arg = 0, .op = op, .datum_a = self, .datum_b = 0};
        if (rc == 0) rc = ::seccomp_rule_add_array(ctx, refuse, call, 1, &other);
      }
    }
  }
  if (rc == 0) rc = ::seccomp_load(ctx);
  ::seccomp_release(ctx);
  layer.applied = rc == 0;
  layer.note = rc == 0 ? (controller ? "no sockets, exec, processes, tracing, IPC objects, file locks, or signals to or scheduling of others; "
                                       "sysinfo the same for all"
                                     : "no sockets, tracing or scheduling of others")
                       : std::string("not applied: ") + std::strerror(-rc);
  return layer;
}

namespace {
volatile std::int32_t* trappedSyscall = nullptr;

// The same answer to sysinfo in every host: 4 GiB of memory, half of it free, one process, just started.
bool answerSysinfo(void* context) {
  auto* uc = static_cast<ucontext_t*>(context);
#if defined(__x86_64__)
  greg_t& arg = uc->uc_mcontext.gregs[REG_RDI];
  greg_t& result = uc->uc_mcontext.gregs[REG_RAX];
#elif defined(__aarch64__)
  auto& arg = uc->uc_mcontext.regs[0];
  auto& result = uc->uc_mcontext.regs[0];
#else
  return false;
#endif
  auto* out = reinterpret_cast<struct sysinfo*>(arg);
  __builtin_memset(out, 0, sizeof *out);
  out->totalram = 4UL << 30, out->freeram = 2UL << 30, out->procs = 1, out->mem_unit = 1;
  result = 0;
  return true;
}

void onSigsys(int, siginfo_t* info, void* context) {
  constexpr int kSentBySeccomp = 1;  // SYS_SECCOMP, the si_code of a trap (not a SIGSYS a controller raised itself)
  if (info->si_code == kSentBySeccomp && info->si_syscall == SYS_sysinfo && answerSysinfo(context)) return;
  if (trappedSyscall != nullptr) *trappedSyscall = info->si_syscall;
  ::signal(SIGSYS, SIG_DFL);  // the signal is blocked in this handler; it kills once the handler returns
  ::raise(SIGSYS);
}
}  // namespace

void installTrapReporter(volatile std::int32_t* syscallOut) {
  trappedSyscall = syscallOut;
  *trappedSyscall = -1;
  struct sigaction sa {};
  sa.sa_sigaction = onSigsys;
  sa.sa_flags = SA_SIGINFO;
  ::sigaction(SIGSYS, &sa, nullptr);
}

std::string describeSyscall(std::int32_t number) {
  const auto is = [number](std::initializer_list<int> calls) {
    for (int c : calls)
      if (c == number) return true;
    return false;
  };
  if (is({SCMP_SYS(socket), SCMP_SYS(socketpair), SCMP_SYS(connect), SCMP_SYS(bind), SCMP_SYS(listen), SCMP_SYS(accept), SCMP_SYS(accept4)}))
    return "open a network socket";
  if (is({SCMP_SYS(execve), SCMP_SYS(execveat)})) return "run another program";
  if (is({SCMP_SYS(fork), SCMP_SYS(vfork), SCMP_SYS(clone), SCMP_SYS(setsid), SCMP_SYS(setpgid)})) return "start another process";
  if (is({SCMP_SYS(kill), SCMP_SYS(tgkill), SCMP_SYS(tkill), SCMP_SYS(rt_sigqueueinfo), SCMP_SYS(rt_tgsigqueueinfo), SCMP_SYS(pidfd_open),
          SCMP_SYS(pidfd_send_signal), SCMP_SYS(pidfd_getfd)}))
    return "signal another process";
  if (is({SCMP_SYS(ptrace), SCMP_SYS(process_vm_readv), SCMP_SYS(process_vm_writev)})) return "inspect another process";
  if (is({SCMP_SYS(shmget), SCMP_SYS(shmat), SCMP_SYS(shmctl), SCMP_SYS(msgget), SCMP_SYS(msgsnd), SCMP_SYS(msgrcv), SCMP_SYS(msgctl),
          SCMP_SYS(semget), SCMP_SYS(semop), SCMP_SYS(semtimedop), SCMP_SYS(semctl), SCMP_SYS(mq_open), SCMP_SYS(mq_unlink), SCMP_SYS(mq_timedsend),
          SCMP_SYS(mq_timedreceive), SCMP_SYS(mq_notify), SCMP_SYS(mq_getsetattr)}))
    return "make a kernel object shared between processes (System V IPC or a POSIX message queue)";
  if (is({SCMP_SYS(fcntl)})) return "ask for signals on a file (fcntl F_SETOWN, F_SETSIG or F_SETLEASE)";
  if (is({SCMP_SYS(sched_setaffinity)})) return "choose the cores it runs on";
  if (is({SCMP_SYS(sched_setscheduler), SCMP_SYS(sched_setparam), SCMP_SYS(sched_setattr), SCMP_SYS(prlimit64), SCMP_SYS(migrate_pages),
          SCMP_SYS(move_pages), SCMP_SYS(setpriority), SCMP_SYS(ioprio_set)}))
    return "change the scheduling, priority or limits of another process";
  char* name = ::seccomp_syscall_resolve_num_arch(SCMP_ARCH_NATIVE, number);
  std::string what = std::string("make the system call ") + (name != nullptr ? name : std::to_string(number).c_str());
  std::free(name);
  return what;
}

}  // namespace frob::sandbox
