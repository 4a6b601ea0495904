#pragma once
/// The shared memory between the grader (trusted) and a controller host (untrusted): a header with
/// a doorbell each way, then a setup area, then an area per robot (its frame in, its reply out).
/// A doorbell is a sequence number in shared memory: the waiter spins on it briefly, then sleeps
/// (the host on a futex, the trusted side in poll, with a deadline, on the read end of a pipe that
/// only it holds); the ringer wakes it only if it sleeps, so a step in which both sides spin makes no
/// system call at all.
/// The trusted side sizes the channel once and seals it against shrinking and growing before the
/// host starts, so the host cannot pull memory from under it; should a read of it fault anyway
/// (SIGBUS), the mapping is replaced by zeros and the channel reports that it was cut.

#include "frob/base/result.hpp"
#include "frob/sandbox/fd.hpp"

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>

namespace frob::sandbox {

inline constexpr std::uint32_t kMagic = 0x424f5246;  // "FROB"
inline constexpr std::uint32_t kVersion = 5;         // 5: the trusted side sets the host's spin
/// The file descriptors a host finds its channel on.
inline constexpr int kChannelFd = 3, kWakeFd = 4;

/// What the trusted side asks of the host.
enum class Command : std::uint32_t { Load, Build, Step };
/// What the host is doing, so that a crash can be described.
enum class Activity : std::uint32_t { Starting, Loading, Building, Stepping, Waiting };

/// One direction's doorbell.
struct alignas(64) Doorbell {
  std::atomic<std::uint32_t> sequence{0};  ///< the last command rung (request) or answered (reply)
  std::atomic<std::uint32_t> sleeping{0};  ///< 1 while the waiter sleeps and must be woken
};

/// The start of the shared memory. The host may write anything anywhere, so the trusted side
/// reads back only the host's fields below, and treats them as claims, never as facts.
struct Header {
  std::uint32_t magic = kMagic;
  std::uint32_t version = kVersion;
  // Written by the trusted side before it rings the request.
  Command command = Command::Load;
  std::uint32_t robots = 0;               ///< robot areas in the channel
  std::uint64_t setupBytes = 0;           ///< size of the setup area
  std::uint64_t inBytes = 0;              ///< size of each robot's frame area
  std::uint64_t outBytes = 0;             ///< size of each robot's reply area
  std::int64_t step = 0;                  ///< the step to sample (Step)
  double dt = 0.0;                        ///< the run's step, seconds (Build)
  std::uint64_t hostSpinNanoseconds = 0;  ///< how long the host spins on the request before it sleeps (it yields the core meanwhile)
  Doorbell request;
  Doorbell reply;
  // Written by the host: what it was doing, and what it tried that was refused.
  std::atomic<Activity> activity{Activity::Starting};
  std::atomic<std::uint32_t> robot{0};  ///< the robot being built or sampled
  volatile std::int32_t trappedSyscall = -1;
  volatile std::int32_t faultSignal = 0;     ///< SIGSEGV, SIGBUS, ... as the host's handler saw it
  volatile std::uint32_t stackOverflow = 0;  ///< 1 when the fault was just past the stack
  volatile std::uint32_t deniedWrite = 0;    ///< 1 when the refused file was opened for writing
  volatile char deniedPath[512] = {};        ///< the first file a controller was refused
};

/// The shared memory as one side maps it. Move-only; unmaps on destruction.
class Channel {
 public:
  /// Size of the header's page.
  static constexpr std::size_t kHeaderBytes = 4096;

  Channel() = default;
  ~Channel();
  Channel(Channel&& other) noexcept;
  Channel& operator=(Channel&& other) noexcept;

  /// Trusted side: a new sealed memfd holding a header, a setup area of `setupBytes`, and `robots`
  /// robot areas of `inBytes` + `outBytes` each. Pages cost memory only once they are written.
  [[nodiscard]] Status create(std::size_t setupBytes, std::uint32_t robots, std::size_t inBytes, std::size_t outBytes);
  /// Host: maps the channel on `fd`, which it then owns, with the sizes its header gives.
  [[nodiscard]] Status attach(int fd);
  /// Trusted side: whether a read faulted (the memory was cut from under it); it reads zeros since.
  [[nodiscard]] bool cut() const;

  [[nodiscard]] int fd() const { return fd_.get(); }
  [[nodiscard]] Header& header() const { return *reinterpret_cast<Header*>(base_); }
  [[nodiscard]] std::span<std::byte> setup() const;
  [[nodiscard]] std::span<std::byte> frameArea(std::uint32_t robot) const;
  [[nodiscard]] std::span<std::byte> replyArea(std::uint32_t robot) const;

 private:
  Status map(std::size_t bytes);
  std::byte* base_ = nullptr;
  std::size_t mapped_ = 0;
  int guard_ = -1;  // this mapping's slot in the SIGBUS handler's list (trusted side)
  Fd fd_;
  // The layout as this side knows it (the trusted side never reads it back from the header).
  std::size_t setupBytes_ = 0, inBytes_ = 0, outBytes_ = 0;
  std::uint32_t robots_ = 0;
};

/// Spins up to `nanoseconds` until `bell`'s sequence is `sequence` (offering the core now and then to
/// another process that wants it); true if it got there.
[[nodiscard]] bool spinUntil(const Doorbell& bell, std::uint32_t sequence, std::uint64_t nanoseconds);
/// Sleeps on `bell` (a futex) until its sequence is `sequence`; spins first for `spinNanoseconds`,
/// offering the core at every look.
void waitFutex(Doorbell& bell, std::uint32_t sequence, std::uint64_t spinNanoseconds);
/// Sets `bell` to `sequence` and wakes its waiter if it sleeps: on the futex, or by writing to `wakeFd`.
void ring(Doorbell& bell, std::uint32_t sequence, int wakeFd = -1);

}  // namespace frob::sandbox
