#pragma once
// Starting a program under frob-sandbox, which applies the sandbox to itself and then runs it; shared by the
// sandboxed compile and the controller host.

#include "frob/base/result.hpp"
#include "frob/sandbox/fd.hpp"
#include "frob/sandbox/layers.hpp"
#include "sandbox_user.hpp"

#include <sys/types.h>

#include <cstdint>
#include <string>
#include <vector>

#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define FROB_SANITIZED_BUILD 1
#endif
#endif

namespace frob::course {

/// Whether this build runs under AddressSanitizer, which reserves terabytes of address space: then
/// no address-space limit can be set on frob-sandbox or what it runs, and memory is watched instead.
#ifdef FROB_SANITIZED_BUILD
inline constexpr bool kSanitizedBuild = true;
#else
inline constexpr bool kSanitizedBuild = false;
#endif

/// A program to run in the sandbox.
struct SandboxedDef {
  std::vector<std::string> command;  ///< the program (absolute path) and its arguments
  sandbox::Limits limits;            ///< memoryBytes is dropped in a sanitizer build (kSanitizedBuild)
  sandbox::Namespaces namespaces;
  sandbox::FileAccess files;
  std::string cwd;                ///< its working folder
  std::vector<std::string> env;   ///< its whole environment, NAME=VALUE
  std::vector<std::string> own;   ///< as root, folders given to the user of its own it runs as (sandbox_user.hpp)
  bool rootIfUnreadable = false;  ///< as root, stay root where its own user could not read its files (reported as a layer not applied)
  bool noNetwork = false;         ///< seccomp: no sockets (the controller host filters itself)
  std::vector<int> fds;           ///< fds[k] becomes descriptor k of the program; -1: /dev/null
};

/// A sandboxed program, running. Kills its process group when destroyed, unless reaped.
class Sandboxed {
 public:
  /// Starts `def` under frob-sandbox and reads which layers it applied; every failure is frob's (graderFailure()).
  [[nodiscard]] static Result<Sandboxed> start(const SandboxedDef& def);
  Sandboxed() = default;
  ~Sandboxed();
  Sandboxed(Sandboxed&& o) noexcept;
  Sandboxed& operator=(Sandboxed&& o) noexcept;

  /// Its process id; 0 once reaped, when the id may already be another process's.
  [[nodiscard]] pid_t pid() const { return status_ == -1 ? pid_ : 0; }
  /// A pidfd, readable once the program has ended.
  [[nodiscard]] int pidfd() const { return pidfd_.get(); }
  /// The layers frob-sandbox applied.
  [[nodiscard]] const std::vector<sandbox::Layer>& layers() const { return layers_; }
  /// Kills the program's whole process group.
  void kill();
  /// Its wait status once it has ended (blocks until then); the first call reaps it.
  int wait();
  /// Once reaped: the largest resident memory of it, or of any child it waited for, in bytes.
  [[nodiscard]] std::uint64_t peakMemoryBytes() const { return peakMemoryBytes_; }

 private:
  pid_t pid_ = 0;
  sandbox::Fd pidfd_;
  int status_ = -1;
  std::uint64_t peakMemoryBytes_ = 0;
  std::vector<sandbox::Layer> layers_;
  SandboxUser user_;  // held until it is reaped
};

/// How a sandboxed program that ran to its end (or its deadline) did.
struct SandboxedRun {
  int status = -1;                    ///< its wait status
  bool timedOut = false;              ///< killed at the deadline
  std::uint64_t peakMemoryBytes = 0;  ///< the largest resident memory of it or of a child it waited for
  std::string output;                 ///< its stdout and stderr together, cut at the limit
  std::vector<sandbox::Layer> layers;
};

/// Runs `def` to its end with its stdout and stderr captured (def.fds[1], [2] are set here), killed
/// after `seconds` of wall-clock time; keeps the first and the last `outputBytes` / 2 of what it
/// printed (the first error, and the end, where a crash says what it is).
[[nodiscard]] Result<SandboxedRun> runSandboxed(SandboxedDef def, double seconds, std::size_t outputBytes);

}  // namespace frob::course
