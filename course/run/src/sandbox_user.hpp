#pragma once
// The unprivileged user a sandboxed program runs as while frob runs as root: one of its own, so that
// no two sandboxed programs on the machine (two robots' hosts, two runs, a compiler) can signal,
// renice, re-pin or trace each other, or read each other's /proc files.

#include "frob/base/result.hpp"
#include "frob/sandbox/fd.hpp"

#include <cstdint>

namespace frob::course {

/// The first and one past the last user id handed out: between isolate's boxes (60000-60999) and
/// systemd's dynamic users (61184-65519), under 65536 so that a container's usual mapping has them.
inline constexpr std::uint32_t kFirstSandboxUid = 61000;
inline constexpr std::uint32_t kEndSandboxUid = 61184;

/// A user id held until destroyed: no account's, and held by no other SandboxUser on this machine,
/// in this process or another (a lock per id in a folder only root may change, released by the
/// kernel if frob dies). Every process frob started that still runs as it is killed before it is
/// released (one that left its process group and session, say: frob is its subreaper), so that the
/// next holder's programs meet none.
class SandboxUser {
 public:
  /// The first free id, as root; otherwise none (`held()` false: the program runs as the caller).
  /// Fails (frob's failure) when root cannot keep its locks or every id is held.
  [[nodiscard]] static Result<SandboxUser> take();
  SandboxUser() = default;
  ~SandboxUser();
  SandboxUser(SandboxUser&& o) noexcept;
  SandboxUser& operator=(SandboxUser&& o) noexcept;

  [[nodiscard]] bool held() const { return lock_.valid(); }
  [[nodiscard]] std::uint32_t uid() const { return uid_; }

 private:
  std::uint32_t uid_ = 0;
  sandbox::Fd lock_;  // its lock file, flock()ed
};

}  // namespace frob::course
