// The host defines the C library's ways of opening a file and of starting a process; a controller
// module's calls (and those of the C++ library it uses) bind to these, which call the real ones and
// note what happened. Landlock and seccomp do the refusing; this only names what was refused in the
// grader's message. A raw system call passes unnoticed, and is refused all the same.
#include "refusals.hpp"

#include <dlfcn.h>
#include <fcntl.h>
#include <spawn.h>
#include <sys/syscall.h>

#include <algorithm>
#include <cerrno>
#include <cstdarg>
#include <cstdio>
#include <cstring>

namespace {

frob::sandbox::Header* guarded = nullptr;

void noteRefusal(const char* path, bool writing) {
  if (guarded == nullptr || path == nullptr || (errno != EACCES && errno != EPERM) || guarded->deniedPath[0] != 0) return;
  const int saved = errno;
  const std::size_t n = std::min(std::strlen(path), sizeof guarded->deniedPath - 1);
  for (std::size_t i = 0; i < n; ++i) guarded->deniedPath[i] = path[i];
  guarded->deniedWrite = writing ? 1 : 0;
  errno = saved;
}

bool writes(int flags) { return (flags & (O_WRONLY | O_RDWR | O_CREAT | O_TRUNC)) != 0; }
bool writes(const char* mode) { return mode != nullptr && std::strpbrk(mode, "wa+") != nullptr; }

// The next definition of `name` after ours: the C library's.
template <class F>
F real(const char* name) {
  return reinterpret_cast<F>(::dlsym(RTLD_NEXT, name));
}

mode_t modeOf(int flags, va_list args) { return (flags & (O_CREAT | O_TMPFILE)) != 0 ? va_arg(args, mode_t) : 0; }

}  // namespace

void noteRefusedCalls(frob::sandbox::Header* header) { guarded = header; }

namespace {
// Notes a process start, which seccomp is about to refuse.
void noteProcess() {
  if (guarded != nullptr && guarded->trappedSyscall < 0) guarded->trappedSyscall = SYS_clone;
}
}  // namespace

#define FROB_NOTE_REFUSED_OPEN(name)                                      \
  extern "C" int name(const char* path, int flags, ...) {                 \
    static const auto next = real<int (*)(const char*, int, ...)>(#name); \
    va_list args;                                                         \
    va_start(args, flags);                                                \
    const mode_t mode = modeOf(flags, args);                              \
    va_end(args);                                                         \
    const int fd = next(path, flags, mode);                               \
    if (fd < 0) noteRefusal(path, writes(flags));                         \
    return fd;                                                            \
  }
#define FROB_NOTE_REFUSED_OPENAT(name)                                         \
  extern "C" int name(int dir, const char* path, int flags, ...) {             \
    static const auto next = real<int (*)(int, const char*, int, ...)>(#name); \
    va_list args;                                                              \
    va_start(args, flags);                                                     \
    const mode_t mode = modeOf(flags, args);                                   \
    va_end(args);                                                              \
    const int fd = next(dir, path, flags, mode);                               \
    if (fd < 0) noteRefusal(path, writes(flags));                              \
    return fd;                                                                 \
  }
#define FROB_NOTE_REFUSED_FOPEN(name)                                          \
  extern "C" FILE* name(const char* path, const char* mode) {                  \
    static const auto next = real<FILE* (*)(const char*, const char*)>(#name); \
    FILE* f = next(path, mode);                                                \
    if (f == nullptr) noteRefusal(path, writes(mode));                         \
    return f;                                                                  \
  }

FROB_NOTE_REFUSED_OPEN(open)
FROB_NOTE_REFUSED_OPEN(open64)
FROB_NOTE_REFUSED_OPENAT(openat)
FROB_NOTE_REFUSED_OPENAT(openat64)
FROB_NOTE_REFUSED_FOPEN(fopen)
FROB_NOTE_REFUSED_FOPEN(fopen64)

extern "C" int system(const char* command) {
  static const auto next = real<int (*)(const char*)>("system");
  noteProcess();
  return next(command);
}

extern "C" FILE* popen(const char* command, const char* mode) {
  static const auto next = real<FILE* (*)(const char*, const char*)>("popen");
  noteProcess();
  return next(command, mode);
}

#define FROB_NOTE_REFUSED_SPAWN(name)                                                                                                       \
  extern "C" int name(pid_t* pid, const char* path, const posix_spawn_file_actions_t* actions, const posix_spawnattr_t* attributes,         \
                      char* const argv[], char* const envp[]) {                                                                             \
    static const auto next =                                                                                                                \
        real<int (*)(pid_t*, const char*, const posix_spawn_file_actions_t*, const posix_spawnattr_t*, char* const*, char* const*)>(#name); \
    noteProcess();                                                                                                                          \
    return next(pid, path, actions, attributes, argv, envp);                                                                                \
  }
FROB_NOTE_REFUSED_SPAWN(posix_spawn)
FROB_NOTE_REFUSED_SPAWN(posix_spawnp)
