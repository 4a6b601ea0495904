#pragma once
// Private: a few persistent threads that run one job over robot ranges, then wait at a barrier.

#include <barrier>
#include <cstddef>
#include <functional>
#include <thread>
#include <vector>

namespace frob::worlds::detail {

class Workers {
 public:
  // `count` threads in all, the caller's included.
  explicit Workers(int count);
  ~Workers();
  Workers(const Workers&) = delete;
  Workers& operator=(const Workers&) = delete;
  [[nodiscard]] int count() const { return count_; }
  // Calls job(begin, end) over contiguous chunks of [0, n), one chunk per thread; returns when all are done.
  void run(std::size_t n, const std::function<void(std::size_t, std::size_t)>& job);

 private:
  void chunk(int worker);
  int count_;
  std::barrier<> start_;
  std::barrier<> done_;
  std::vector<std::thread> threads_;
  const std::function<void(std::size_t, std::size_t)>* job_ = nullptr;
  std::size_t n_ = 0;
  bool stop_ = false;
};

}  // namespace frob::worlds::detail
