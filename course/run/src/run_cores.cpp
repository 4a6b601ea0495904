#include "frob/run/run_cores.hpp"

#include <unistd.h>

#include <utility>

namespace frob::course {

namespace {

std::vector<int> allowedCores() {
  cpu_set_t allowed;
  CPU_ZERO(&allowed);
  std::vector<int> cores;
  if (::sched_getaffinity(0, sizeof allowed, &allowed) == 0) {
    for (int c = 0; c < CPU_SETSIZE; ++c) {
      if (CPU_ISSET(c, &allowed)) cores.push_back(c);
    }
  }
  return cores.empty() ? std::vector<int>{0} : cores;
}

}  // namespace

RunCores::RunCores() : RunCores(allowedCores()) {}

RunCores::RunCores(std::vector<int> cores) : free_(std::move(cores)), count_(free_.size()) {}

RunCores::Held RunCores::take() {
  Held h;
  {
    std::unique_lock<std::mutex> lock(mutex_);
    freed_.wait(lock, [&] { return !free_.empty(); });
    h.from_ = this;
    h.core_ = free_.back();
    free_.pop_back();
  }
  cpu_set_t one;
  CPU_ZERO(&one);
  CPU_SET(h.core_, &one);
  h.thread_ = ::gettid();
  h.pinned_ = ::sched_getaffinity(h.thread_, sizeof h.before_, &h.before_) == 0 && ::sched_setaffinity(h.thread_, sizeof one, &one) == 0;
  return h;
}

RunCores::Held::~Held() { release(); }

RunCores::Held::Held(Held&& o) noexcept { *this = std::move(o); }

RunCores::Held& RunCores::Held::operator=(Held&& o) noexcept {
  if (this != &o) {
    release();
    from_ = std::exchange(o.from_, nullptr);
    core_ = std::exchange(o.core_, -1);
    thread_ = std::exchange(o.thread_, 0);
    pinned_ = std::exchange(o.pinned_, false);
    before_ = o.before_;
  }
  return *this;
}

void RunCores::Held::release() {
  if (from_ == nullptr) return;
  if (pinned_) ::sched_setaffinity(thread_, sizeof before_, &before_);
  {
    const std::lock_guard<std::mutex> lock(from_->mutex_);
    from_->free_.push_back(core_);
  }
  from_->freed_.notify_one();
  from_ = nullptr, core_ = -1, pinned_ = false;
}

}  // namespace frob::course
