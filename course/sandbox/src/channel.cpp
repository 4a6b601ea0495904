#include "frob/sandbox/channel.hpp"

#include <linux/futex.h>
#include <sched.h>
#include <sys/mman.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <new>
#include <utility>

namespace frob::sandbox {

namespace {

Status errorText(const char* what) { return Status::failure(std::string(what) + ": " + std::strerror(errno)); }

void cpuRelax() { __builtin_ia32_pause(); }

}  // namespace

Channel::~Channel() {
  if (base_ != nullptr) ::munmap(base_, mapped_);
  if (head_ != nullptr) ::munmap(head_, kHeaderBytes);
}

Channel::Channel(Channel&& o) noexcept { *this = std::move(o); }

Channel& Channel::operator=(Channel&& o) noexcept {
  std::swap(head_, o.head_);
  std::swap(base_, o.base_);
  std::swap(mapped_, o.mapped_);
  std::swap(fd_, o.fd_);
  std::swap(setupBytes_, o.setupBytes_);
  std::swap(inBytes_, o.inBytes_);
  std::swap(outBytes_, o.outBytes_);
  std::swap(robots_, o.robots_);
  return *this;
}

Status Channel::map(std::size_t bytes) {
  if (head_ == nullptr) {
    void* head = ::mmap(nullptr, kHeaderBytes, PROT_READ | PROT_WRITE, MAP_SHARED, fd_.get(), 0);
    if (head == MAP_FAILED) return errorText("mapping the controller channel");
    head_ = static_cast<std::byte*>(head);
  }
  void* at = ::mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_SHARED, fd_.get(), 0);
  if (at == MAP_FAILED) return errorText("mapping the controller channel");
  if (base_ != nullptr) ::munmap(base_, mapped_);
  base_ = static_cast<std::byte*>(at);
  mapped_ = bytes;
  return {};
}

Status Channel::create(std::size_t setupBytes) {
  fd_.reset(::memfd_create("frob-channel", MFD_CLOEXEC));
  if (!fd_.valid()) return errorText("memfd_create");
  setupBytes_ = setupBytes;
  const std::size_t bytes = kHeaderBytes + setupBytes;
  if (::ftruncate(fd_.get(), static_cast<off_t>(bytes)) != 0) return errorText("sizing the controller channel");
  if (Status s = map(bytes); !s) return s;
  Header& h = *new (head_) Header{};
  h.setupBytes = setupBytes;
  return {};
}

Status Channel::resize(std::uint32_t robots, std::size_t inBytes, std::size_t outBytes) {
  robots_ = robots, inBytes_ = inBytes, outBytes_ = outBytes;
  const std::size_t bytes = kHeaderBytes + setupBytes_ + robots * (inBytes + outBytes);
  if (::ftruncate(fd_.get(), static_cast<off_t>(bytes)) != 0) return errorText("sizing the controller channel");
  if (Status s = map(bytes); !s) return s;
  Header& h = header();
  h.robots = robots, h.inBytes = inBytes, h.outBytes = outBytes;
  return {};
}

Status Channel::attach(int fd) {
  fd_.reset(fd);
  if (head_ == nullptr) {
    if (Status s = map(kHeaderBytes); !s) return s;
  }
  const Header& h = header();
  if (h.magic != kMagic || h.version != kVersion) return Status::failure("the controller channel has another version");
  setupBytes_ = h.setupBytes, robots_ = h.robots, inBytes_ = h.inBytes, outBytes_ = h.outBytes;
  return map(kHeaderBytes + setupBytes_ + robots_ * (inBytes_ + outBytes_));
}

std::span<std::byte> Channel::setup() const { return {base_ + kHeaderBytes, setupBytes_}; }

std::span<std::byte> Channel::frameArea(std::uint32_t robot) const {
  return {base_ + kHeaderBytes + setupBytes_ + robot * (inBytes_ + outBytes_), inBytes_};
}

std::span<std::byte> Channel::replyArea(std::uint32_t robot) const {
  return {base_ + kHeaderBytes + setupBytes_ + robot * (inBytes_ + outBytes_) + inBytes_, outBytes_};
}

bool spinUntil(const Doorbell& bell, std::uint32_t sequence, std::uint64_t nanoseconds) {
  if (bell.sequence.load(std::memory_order_acquire) == sequence) return true;
  if (nanoseconds == 0) return false;
  const auto end = std::chrono::steady_clock::now() + std::chrono::nanoseconds(nanoseconds);
  for (;;) {
    for (int i = 0; i < 64; ++i) {
      if (bell.sequence.load(std::memory_order_acquire) == sequence) return true;
      cpuRelax();
    }
    if (std::chrono::steady_clock::now() >= end) return false;
    // Give the core away if another process wants it (the other side, on a crowded machine);
    // on an idle one this returns at once.
    ::sched_yield();
  }
}

void waitFutex(Doorbell& bell, std::uint32_t sequence, std::uint64_t spinNanoseconds) {
  if (spinUntil(bell, sequence, spinNanoseconds)) return;
  // Announce the sleep, then look again: a ring in between is seen here or wakes the futex,
  // whose value check fails at once when the sequence has already moved on.
  bell.sleeping.store(1, std::memory_order_seq_cst);
  for (std::uint32_t seen; (seen = bell.sequence.load(std::memory_order_seq_cst)) != sequence;) {
    ::syscall(SYS_futex, &bell.sequence, FUTEX_WAIT, seen, nullptr, nullptr, 0);
  }
  bell.sleeping.store(0, std::memory_order_relaxed);
}

void ring(Doorbell& bell, std::uint32_t sequence, int eventFd) {
  bell.sequence.store(sequence, std::memory_order_seq_cst);
  if (bell.sleeping.load(std::memory_order_seq_cst) == 0) return;
  if (eventFd < 0) {
    ::syscall(SYS_futex, &bell.sequence, FUTEX_WAKE, 1, nullptr, nullptr, 0);
  } else {
    const std::uint64_t one = 1;
    [[maybe_unused]] const ssize_t n = ::write(eventFd, &one, sizeof one);
  }
}

}  // namespace frob::sandbox
