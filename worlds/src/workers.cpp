#include "workers.hpp"

namespace frob::worlds::detail {

Workers::Workers(int count) : count_(count < 1 ? 1 : count), start_(count_), done_(count_) {
  for (int w = 1; w < count_; ++w)
    threads_.emplace_back([this, w] {
      for (;;) {
        start_.arrive_and_wait();  // the barrier publishes job_, n_ and stop_ to this thread
        if (stop_) return;
        chunk(w);
        done_.arrive_and_wait();
      }
    });
}

Workers::~Workers() {
  stop_ = true;
  if (count_ > 1) start_.arrive_and_wait();
  for (auto& t : threads_) t.join();
}

void Workers::chunk(int worker) {
  const std::size_t begin = n_ * static_cast<std::size_t>(worker) / static_cast<std::size_t>(count_);
  const std::size_t end = n_ * static_cast<std::size_t>(worker + 1) / static_cast<std::size_t>(count_);
  if (begin < end) (*job_)(begin, end);
}

void Workers::run(std::size_t n, const std::function<void(std::size_t, std::size_t)>& job) {
  if (count_ == 1) {
    job(0, n);
    return;
  }
  job_ = &job;
  n_ = n;
  start_.arrive_and_wait();
  chunk(0);
  done_.arrive_and_wait();
}

}  // namespace frob::worlds::detail
