#pragma once
/// File descriptors with one owner each, closed when the owner goes: no descriptor is leaked into a
/// program started later, and none is closed twice.

#include "frob/base/result.hpp"

#include <utility>

namespace frob::sandbox {

/// An owned file descriptor (-1: none). Move-only; closes it on destruction.
class Fd {
 public:
  Fd() = default;
  /// Owns `fd`.
  explicit Fd(int fd) : fd_(fd) {}
  ~Fd() { reset(); }
  Fd(Fd&& o) noexcept : fd_(o.release()) {}
  Fd& operator=(Fd&& o) noexcept {
    if (this != &o) reset(o.release());
    return *this;
  }
  Fd(const Fd&) = delete;
  Fd& operator=(const Fd&) = delete;

  /// The descriptor, still owned here; -1 when none.
  [[nodiscard]] int get() const { return fd_; }
  /// True when a descriptor is held.
  [[nodiscard]] bool valid() const { return fd_ >= 0; }
  /// Hands the descriptor over to the caller, who closes it.
  [[nodiscard]] int release() { return std::exchange(fd_, -1); }
  /// Closes the descriptor held, if any and not `fd`, and owns `fd` instead.
  void reset(int fd = -1);

 private:
  int fd_ = -1;
};

/// The two ends of a pipe.
struct Pipe {
  Fd read;
  Fd write;
};

/// A new pipe, both ends close-on-exec; fails with the system's reason, after `what`.
[[nodiscard]] Result<Pipe> openPipe(const char* what);

}  // namespace frob::sandbox
