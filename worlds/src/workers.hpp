#pragma once
// Private: a few persistent threads that share out one job over robot ranges. Chunks go to
// whichever thread claims them first, the caller's included, so a worker the OS has not yet
// scheduled (the machine is shared) never holds the caller up: the caller takes its chunks.
// Which thread runs which chunk varies; jobs must give the same results however they are split.

#include <atomic>
#include <cstddef>
#include <cstdint>
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
  // Calls job(begin, end) over chunks of at least `grain` items, and at most 16 per thread,
  // covering [0, n) (all of it in one call when there is one thread or one chunk); returns when
  // all are done.
  void run(std::size_t n, std::size_t grain, const std::function<void(std::size_t, std::size_t)>& job);

 private:
  void work(std::uint64_t generation);
  int count_;
  std::vector<std::thread> threads_;
  // generation << 32 | next chunk << 16 | chunks: one word, so that a claim is one compare-exchange
  // and a late worker can never claim a chunk of a job that has already finished.
  std::atomic<std::uint64_t> ticket_{0};
  std::atomic<std::uint32_t> done_{0};  // chunks of the current job finished
  std::atomic<bool> stop_{false};
  // The current job; read only by a thread holding a claimed chunk, so never while it changes.
  const std::function<void(std::size_t, std::size_t)>* job_ = nullptr;
  std::size_t n_ = 0, grain_ = 1;
};

}  // namespace frob::worlds::detail
