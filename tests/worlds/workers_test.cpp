// The worker threads (private to worlds/): every item of every job runs exactly once, whoever
// claims its chunk, job after job.
#include "workers.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <thread>
#include <vector>

namespace frob::worlds::detail {
namespace {

TEST(Workers, EveryItemRunsExactlyOnceJobAfterJob) {
  for (int threads : {1, 2, 3, 4}) {
    Workers workers(threads);
    for (int job = 0; job < 300; ++job) {
      const std::size_t n = static_cast<std::size_t>(job * 7 % 131), grain = 1 + static_cast<std::size_t>(job % 5);
      std::vector<std::atomic<int>> runs(n);
      workers.run(n, grain, [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i) runs[i].fetch_add(1, std::memory_order_relaxed);
      });
      for (std::size_t i = 0; i < n; ++i) ASSERT_EQ(runs[i].load(), 1) << threads << " threads, job " << job << ", item " << i;
    }
  }
}

TEST(Workers, AnotherThreadRunsChunksAlongsideTheCaller) {
  // Each chunk waits (yielding, however long the OS takes to run the worker) until both chunks
  // have started, which only another thread can bring about.
  Workers workers(2);
  std::atomic<int> started{0};
  std::thread::id ids[2];
  workers.run(2, 1, [&](std::size_t begin, std::size_t) {
    ids[begin] = std::this_thread::get_id();
    started.fetch_add(1);
    while (started.load() < 2) std::this_thread::yield();
  });
  EXPECT_NE(ids[0], ids[1]);
}

TEST(Workers, ManyItemsStillFitTheChunkCount) {
  Workers workers(2);
  const std::size_t n = 200000;
  std::vector<std::atomic<int>> runs(n);
  workers.run(n, 1, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) runs[i].fetch_add(1, std::memory_order_relaxed);
  });
  for (std::size_t i = 0; i < n; ++i) ASSERT_EQ(runs[i].load(), 1) << i;
}

}  // namespace
}  // namespace frob::worlds::detail
