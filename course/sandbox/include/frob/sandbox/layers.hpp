#pragma once
/// The layers of the sandbox around an untrusted process, each applied to the calling process and each
/// reporting whether it took effect: resource limits, an unprivileged user, namespaces of its own,
/// no new privileges, Landlock for files, seccomp for system calls. frob-sandbox applies them before it runs a compiler or
/// a controller host; the host adds its own system-call filter before it loads student code.

#include <cstdint>
#include <string>
#include <vector>

namespace frob::sandbox {

/// One layer and whether it was applied; `note` says why not, or what it holds.
struct Layer {
  std::string name;      ///< e.g. "landlock"
  bool applied = false;  ///< false when the kernel lacks it or it was not asked for
  bool required = true;  ///< false when this process has no need of it (no uid to drop when not root)
  std::string note;      ///< e.g. "ABI 7" or "not available: the kernel was built without Landlock"
};

/// Resource limits; 0 leaves a limit as it is.
struct Limits {
  std::uint64_t cpuSeconds = 0;   ///< CPU time of the whole process (SIGXCPU, then SIGKILL a second later)
  std::uint64_t memoryBytes = 0;  ///< address space (malloc and new fail past it)
  std::uint64_t fileBytes = 0;    ///< largest file it may write (SIGXFSZ past it)
  std::uint64_t openFiles = 0;    ///< open file descriptors
  std::uint64_t stackBytes = 0;   ///< the main thread's stack, at most its hard limit (0: as inherited)
};

/// Namespaces of its own: a user namespace (in which `tasks` counts only its own processes and
/// threads), an IPC namespace (no System V object or POSIX message queue shared with anyone), and
/// a mount namespace in which `scratch`, when given, is a tmpfs of `scratchBytes`: bounded in total,
/// and gone with the process.
struct Namespaces {
  std::uint64_t tasks = 0;  ///< processes and threads at once (RLIMIT_NPROC); 0: no limit
  std::string scratch;      ///< a folder to cover with the tmpfs; "": none
  std::uint64_t scratchBytes = 0;
};

/// What the files allow: everything else is neither read, written nor run.
struct FileAccess {
  std::vector<std::string> read;     ///< folders or files it may read (and list)
  std::vector<std::string> write;    ///< folders it may read, create, change and delete in
  std::vector<std::string> execute;  ///< files or folders whose programs it may run (and read)
};

/// Which system calls a filter refuses.
enum class SyscallPolicy {
  NoNetwork,   ///< no sockets and no tracing (a compiler, which runs its linker)
  Controller,  ///< also no exec, no new processes, no signals to other processes (a controller host)
};

/// Applies `limits` as rlimits, and no core files.
[[nodiscard]] Layer limitResources(const Limits& limits);
/// When running as root: drops every group and becomes `uid`/`gid`; otherwise changes nothing.
[[nodiscard]] Layer dropPrivileges(std::uint32_t uid, std::uint32_t gid);
/// As root, before dropPrivileges: the first of `access`'s paths and `cwd` (those that exist) that
/// `uid`/`gid` could not use as `access` says, and why; "" when it could use them all.
[[nodiscard]] std::string unreachableAs(std::uint32_t uid, std::uint32_t gid, const FileAccess& access, const std::string& cwd);
/// Enters `ns` (after dropPrivileges: the namespaces belong to the user it became). Not applied
/// where the kernel or a container forbids user namespaces; then nothing changes.
[[nodiscard]] Layer enterNamespaces(const Namespaces& ns);
/// PR_SET_NO_NEW_PRIVS: nothing run from now on gains privileges (set-user-ID programs included).
[[nodiscard]] Layer noNewPrivileges();
/// Landlock: only `access` on files, no TCP and (where the kernel has it) no signals or abstract
/// sockets out of the sandbox. Paths that do not exist are skipped.
[[nodiscard]] Layer restrictFiles(const FileAccess& access);
/// seccomp through libseccomp. A refused call kills the process with SIGSYS after the handler of
/// installTrapReporter() (if any) has noted which call it was; for NoNetwork it fails with EPERM.
[[nodiscard]] Layer restrictSyscalls(SyscallPolicy policy);

/// Where the SIGSYS handler writes the number of the refused system call (-1 until one is).
void installTrapReporter(volatile std::int32_t* syscallOut);

/// What a refused system call (by number) was trying to do, in words: "open a network socket".
[[nodiscard]] std::string describeSyscall(std::int32_t number);

}  // namespace frob::sandbox
