#include "frob/sandbox/channel.hpp"

#include <fcntl.h>
#include <linux/futex.h>
#include <sched.h>
#include <signal.h>
#include <sys/mman.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <mutex>
#include <new>
#include <optional>
#include <utility>

namespace frob::sandbox {

namespace {

Status errorText(const char* what) { return Status::failure(std::string(what) + ": " + std::strerror(errno)); }

void cpuRelax() { __builtin_ia32_pause(); }

// Spins up to `nanoseconds` until `bell`'s sequence is `sequence`, looking `looks` times between
// offers of the core to another process that wants it (on an idle core the offer returns at once).
bool spin(const Doorbell& bell, std::uint32_t sequence, std::uint64_t nanoseconds, int looks) {
  if (bell.sequence.load(std::memory_order_acquire) == sequence) return true;
  if (nanoseconds == 0) return false;
  std::optional<std::chrono::steady_clock::time_point> end;  // read after the first looks: most waits end within them
  for (;;) {
    for (int i = 0; i < looks; ++i) {
      if (bell.sequence.load(std::memory_order_acquire) == sequence) return true;
      cpuRelax();
    }
    const auto now = std::chrono::steady_clock::now();
    if (!end) end = now + std::chrono::nanoseconds(nanoseconds);
    if (now >= *end) return false;
    ::sched_yield();
  }
}

// The trusted side's mappings of channels, for the SIGBUS handler: a slot is in use while its end is set.
struct GuardSlot {
  std::atomic<std::uintptr_t> begin{0}, end{0};
  std::atomic<bool> cut{false};
};
constexpr int kGuardSlots = 256;
GuardSlot guardSlots[kGuardSlots];
struct sigaction previousBusAction {};

// A read of a guarded mapping faulted: zeros take its place, so the read and every later one succeed.
// Any other SIGBUS goes to the handler there was before.
void onBus(int sig, siginfo_t* info, void* context) {
  const auto at = reinterpret_cast<std::uintptr_t>(info->si_addr);
  for (GuardSlot& g : guardSlots) {
    const std::uintptr_t end = g.end.load(std::memory_order_acquire), begin = g.begin.load(std::memory_order_acquire);
    if (at < begin || at >= end) continue;
    if (::mmap(reinterpret_cast<void*>(begin), end - begin, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS | MAP_FIXED, -1, 0) != MAP_FAILED) {
      g.cut.store(true, std::memory_order_release);
      return;
    }
  }
  if ((previousBusAction.sa_flags & SA_SIGINFO) != 0) return previousBusAction.sa_sigaction(sig, info, context);
  if (previousBusAction.sa_handler != SIG_DFL && previousBusAction.sa_handler != SIG_IGN) return previousBusAction.sa_handler(sig);
  ::signal(SIGBUS, SIG_DFL);  // the faulting instruction runs again and the default action ends the process
}

// Guards [begin, begin + bytes) against SIGBUS; the slot's index, or -1 when every slot is taken.
int guard(const std::byte* begin, std::size_t bytes) {
  static std::once_flag installed;
  std::call_once(installed, [] {
    struct sigaction sa {};
    sa.sa_sigaction = onBus;
    sa.sa_flags = SA_SIGINFO | SA_NODEFER;
    ::sigaction(SIGBUS, &sa, &previousBusAction);
  });
  for (int i = 0; i < kGuardSlots; ++i) {
    std::uintptr_t free = 0;
    if (!guardSlots[i].begin.compare_exchange_strong(free, reinterpret_cast<std::uintptr_t>(begin))) continue;
    guardSlots[i].cut.store(false);
    guardSlots[i].end.store(reinterpret_cast<std::uintptr_t>(begin) + bytes, std::memory_order_release);
    return i;
  }
  return -1;
}

void unguard(int slot) {
  if (slot < 0) return;
  guardSlots[slot].end.store(0, std::memory_order_release);
  guardSlots[slot].begin.store(0, std::memory_order_release);
}

}  // namespace

Channel::~Channel() {
  unguard(guard_);
  if (base_ != nullptr) ::munmap(base_, mapped_);
}

Channel::Channel(Channel&& o) noexcept { *this = std::move(o); }

Channel& Channel::operator=(Channel&& o) noexcept {
  std::swap(base_, o.base_);
  std::swap(mapped_, o.mapped_);
  std::swap(guard_, o.guard_);
  std::swap(fd_, o.fd_);
  std::swap(setupBytes_, o.setupBytes_);
  std::swap(inBytes_, o.inBytes_);
  std::swap(outBytes_, o.outBytes_);
  std::swap(robots_, o.robots_);
  return *this;
}

Status Channel::map(std::size_t bytes) {
  void* at = ::mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_SHARED, fd_.get(), 0);
  if (at == MAP_FAILED) return errorText("mapping the controller channel");
  if (base_ != nullptr) ::munmap(base_, mapped_);
  base_ = static_cast<std::byte*>(at);
  mapped_ = bytes;
  return {};
}

Status Channel::create(std::size_t setupBytes, std::uint32_t robots, std::size_t inBytes, std::size_t outBytes) {
  fd_.reset(::memfd_create("frob-channel", MFD_CLOEXEC | MFD_ALLOW_SEALING));
  if (!fd_.valid()) return errorText("memfd_create");
  setupBytes_ = setupBytes, robots_ = robots, inBytes_ = inBytes, outBytes_ = outBytes;
  const std::size_t bytes = kHeaderBytes + setupBytes + robots * (inBytes + outBytes);
  if (::ftruncate(fd_.get(), static_cast<off_t>(bytes)) != 0) return errorText("sizing the controller channel");
  if (::fcntl(fd_.get(), F_ADD_SEALS, F_SEAL_SHRINK | F_SEAL_GROW | F_SEAL_SEAL) != 0) return errorText("sealing the controller channel");
  if (Status s = map(bytes); !s) return s;
  guard_ = guard(base_, mapped_);
  Header& h = *new (base_) Header{};
  h.setupBytes = setupBytes, h.robots = robots, h.inBytes = inBytes, h.outBytes = outBytes;
  return {};
}

Status Channel::attach(int fd) {
  fd_.reset(fd);
  if (Status s = map(kHeaderBytes); !s) return s;
  const Header& h = header();
  if (h.magic != kMagic || h.version != kVersion) return Status::failure("the controller channel has another version");
  setupBytes_ = h.setupBytes, robots_ = h.robots, inBytes_ = h.inBytes, outBytes_ = h.outBytes;
  return map(kHeaderBytes + setupBytes_ + robots_ * (inBytes_ + outBytes_));
}

bool Channel::cut() const { return guard_ >= 0 && guardSlots[guard_].cut.load(std::memory_order_acquire); }

std::span<std::byte> Channel::setup() const { return {base_ + kHeaderBytes, setupBytes_}; }

std::span<std::byte> Channel::frameArea(std::uint32_t robot) const {
  return {base_ + kHeaderBytes + setupBytes_ + robot * (inBytes_ + outBytes_), inBytes_};
}

std::span<std::byte> Channel::replyArea(std::uint32_t robot) const {
  return {base_ + kHeaderBytes + setupBytes_ + robot * (inBytes_ + outBytes_) + inBytes_, outBytes_};
}

// The trusted side looks often between offers: its answer is due within a few microseconds.
bool spinUntil(const Doorbell& bell, std::uint32_t sequence, std::uint64_t nanoseconds) { return spin(bell, sequence, nanoseconds, 64); }

void waitFutex(Doorbell& bell, std::uint32_t sequence, std::uint64_t spinNanoseconds) {
  // A host offers its core at every look: hosts that share a core hand it on to the one whose frame came.
  if (spin(bell, sequence, spinNanoseconds, 1)) return;
  // Announce the sleep, then look again: a ring in between is seen here or wakes the futex,
  // whose value check fails at once when the sequence has already moved on.
  bell.sleeping.store(1, std::memory_order_seq_cst);
  for (std::uint32_t seen; (seen = bell.sequence.load(std::memory_order_seq_cst)) != sequence;) {
    ::syscall(SYS_futex, &bell.sequence, FUTEX_WAIT, seen, nullptr, nullptr, 0);
  }
  bell.sleeping.store(0, std::memory_order_relaxed);
}

void ring(Doorbell& bell, std::uint32_t sequence, int wakeFd) {
  bell.sequence.store(sequence, std::memory_order_seq_cst);
  if (bell.sleeping.load(std::memory_order_seq_cst) == 0) return;
  if (wakeFd < 0) {
    ::syscall(SYS_futex, &bell.sequence, FUTEX_WAKE, 1, nullptr, nullptr, 0);
  } else {
    const std::uint64_t one = 1;
    [[maybe_unused]] const ssize_t n = ::write(wakeFd, &one, sizeof one);
  }
}

}  // namespace frob::sandbox
