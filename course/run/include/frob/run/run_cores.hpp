#pragma once
/// The cores a class's runs share: each run takes a core of its own for its grader and its
/// controller hosts, which take turns on it (the hosts sleep while the grader simulates). Runs that
/// spin while they wait for each other only suit a machine with cores to spare: sharing the cores,
/// they take them from each other at every step's handover.

#include <sched.h>
#include <sys/types.h>

#include <condition_variable>
#include <cstddef>
#include <mutex>
#include <vector>

namespace frob::course {

class RunCores {
 public:
  /// The cores this process may run on (if none can be read, core 0 alone, which pins nothing).
  RunCores();
  /// The cores numbered `cores` (not empty).
  explicit RunCores(std::vector<int> cores);
  RunCores(const RunCores&) = delete;
  RunCores& operator=(const RunCores&) = delete;

  /// A core held by a run. The thread that took it runs on that core alone, and so does every program
  /// it starts meanwhile (its hosts), until the hold ends (on any thread) and that thread's cores
  /// are what they were.
  class Held {
   public:
    Held() = default;
    ~Held();
    Held(Held&& o) noexcept;
    Held& operator=(Held&& o) noexcept;
    /// The core held; -1 for none.
    [[nodiscard]] int core() const { return core_; }

   private:
    friend class RunCores;
    void release();
    RunCores* from_ = nullptr;
    int core_ = -1;
    pid_t thread_ = 0;     // the thread that took it, whose cores are put back
    bool pinned_ = false;  // the thread's cores were changed (best effort: a refusal leaves it where it was)
    cpu_set_t before_{};
  };

  /// Waits for a core no run holds, and takes it for the calling thread.
  [[nodiscard]] Held take();
  /// How many runs may hold a core at once.
  [[nodiscard]] std::size_t size() const { return count_; }

 private:
  std::mutex mutex_;
  std::condition_variable freed_;
  std::vector<int> free_;
  std::size_t count_;
};

}  // namespace frob::course
