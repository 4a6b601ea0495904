#pragma once
// The machinery behind run_task.hpp: the node a running task becomes.

#include "frob/task.hpp"

#include <cstdio>
#include <exception>
#include <optional>
#include <string>

namespace frob {
namespace detail {

// The behavior of a running task: each instant it checks the current atomic task's events,
// moves on through as many tasks as end at this instant, then samples the current behavior. A task
// starts at the instant of the event that ended the one before: when a timer's due time fell
// between samples, that is its lag before this sample (the lag of the instant it is sampled at).
template <class A, class B>
class RunnerNode final : public BehaviorNode<A> {
 public:
  // A run of `task` then `final`. A run inside another (parallel tasks) hangs its timeline under
  // `parentRecord` and, with `holdRoboErrs`, keeps an uncaught RoboErr in result() for the other
  // branch to catch; any other exception ends the whole run, as it would at the top.
  // `stops`: `final` is zero for ever, so that once the task has returned the run has stopped for good.
  RunnerNode(TaskState ts, Task<A, B> task, Behavior<A> final, std::int64_t parentRecord = -1, bool holdRoboErrs = false, bool stops = false)
      : ctx_(std::move(ts)),
        name_(task.name()),
        task_(std::move(task)),
        final_(std::move(final)),
        parentRecord_(parentRecord),
        holdRoboErrs_(holdRoboErrs),
        stops_(stops) {}
  RunnerNode(const RunnerNode&) = delete;
  RunnerNode& operator=(const RunnerNode&) = delete;
  ~RunnerNode() override {
    if (slot_.frame) slot_.frame.destroy();  // stops every task still running, innermost last
    ctx_.destroyReplaced();
  }

  /// The task's result or error once it has ended (done() is true).
  [[nodiscard]] bool done() const { return slot_.value.has_value() || slot_.error != nullptr; }
  [[nodiscard]] const ResultSlot<ResultOf<B>>& result() const { return slot_; }
  /// The instant the task ended, once it has (as first sampled then: the runner is sampled each instant).
  [[nodiscard]] const std::optional<Instant>& endedAt() const { return endedAt_; }
  /// The name of the task it runs.
  [[nodiscard]] const std::string& taskName() const { return name_; }
  [[nodiscard]] bool stoppedForGood() const override { return stops_ && slot_.value.has_value(); }
  /// Records the run's output from its first sample on, for lastOutput.
  void recordOutput() { (void)ctx_.delayedOutput(); }
  /// At the instant the task ended, its output at the sample before (none if it ended as it began).
  [[nodiscard]] std::optional<A> lastOutput(const Instant& now) const {
    if (!endedAt_ || endedAt_->id != now.id || startedAt_ == now.id || !ctx_.output) return std::nullopt;
    return ctx_.output->delayed(now);
  }

 protected:
  A compute(const Instant& now) override {
    ctx_.now = &now;
    ctx_.time = now.time;
    // The common step: the current task goes on. Everything else is in advance().
    if (AtomicBase<A>* atom = ctx_.current; atom != nullptr && ctx_.watchers.empty() && !ctx_.output && now.lag == 0.0) {
      try {
        if (const A* out = atom->step(now)) {
          if constexpr (requires { isFinite(*out); }) {
            if (!isFinite(*out)) fail(nonFiniteMessage(*atom->name, printable(*out), now));
          }
          return *out;
        }
      } catch (const FrobError&) {
        throw;
      } catch (...) {
        atom->fail(std::current_exception());  // an event or behavior that throws fails its task
      }
      return advance(now, true);
    }
    return advance(now, false);
  }

 private:
  // Starts the task, moves through every task that ends at `now` (`ended`: the current one has),
  // then samples the current one; or the final behavior once the task is over.
  [[gnu::noinline]] A advance(const Instant& now, bool ended) {
    if (failure_) std::rethrow_exception(failure_);
    // Only what starts at this instant starts before it: the run itself (at the lag it is sampled
    // at), or a task after the event that ended the one before.
    here_ = now;
    if (started_) here_.lag = ended ? ctx_.current->endLag : 0.0;
    ctx_.now = &here_;
    if (!started_) {
      started_ = true;
      startedAt_ = now.id;
      ctx_.snapshot(here_);
      task_.startIn(slot_, &ctx_, std::noop_coroutine(), parentRecord_, nullptr).resume();
      ctx_.destroyReplaced();
    }
    for (int transitions = 0;; ++transitions) {
      AtomicBase<A>* atom = ctx_.current;
      if (atom == nullptr) return finished(now);
      if (transitions > kMaxTransitionsPerInstant) fail(runawayMessage(*atom->name, now));
      if (!ended) {
        try {
          if (const A* out = atom->step(here_)) {
            for (const auto& watch : ctx_.watchers) watch(here_);
            if constexpr (requires { isFinite(*out); }) {
              if (!isFinite(*out)) fail(nonFiniteMessage(*atom->name, printable(*out), now));
            }
            if (ctx_.output) ctx_.output->write(now, *out);
            return *out;
          }
        } catch (const FrobError&) {
          throw;
        } catch (...) {
          atom->fail(std::current_exception());  // an event or behavior that throws fails its task
        }
        here_.lag = atom->endLag;
      }
      ended = false;
      ctx_.current = nullptr;
      ctx_.snapshot(here_);
      atom->waiter.resume();
      ctx_.destroyReplaced();
    }
  }

  static constexpr int kMaxTransitionsPerInstant = 1000;

  A finished(const Instant& now) {
    if (!endedAt_) endedAt_ = now;
    if (slot_.error && !reported_ && !(holdRoboErrs_ && roboErrIn(slot_.error))) {
      reported_ = true;
      TaskEnd how = TaskEnd::Failed;
      std::string what = describe(slot_.error, &how);
      std::string who = slot_.error == ctx_.origin ? ctx_.originTask : "the controller";
      fail("task '" + who + "' failed at t = " + seconds(now) + ": " + what);
    }
    A out = final_.at(here_);
    if (ctx_.output) ctx_.output->write(now, out);
    return out;
  }
  [[noreturn]] void fail(const std::string& message) {
    ctx_.current = nullptr;  // every later sample takes the slow path, which rethrows
    failure_ = std::make_exception_ptr(FrobError(message));
    std::rethrow_exception(failure_);
  }
  static std::string seconds(const Instant& now) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3f s", now.time);
    return buf;
  }
  static std::string runawayMessage(const std::string& task, const Instant& now) {
    return "task '" + task + "' ended at its start more than " + std::to_string(kMaxTransitionsPerInstant) + " times at t = " + seconds(now) +
           ": each task in the loop ends in the same step it begins (an event that has already occurred, "
           "e.g. one shared by consecutive tasks, or a condition that already holds)";
  }
  static std::string nonFiniteMessage(const std::string& task, const std::string& value, const Instant& now) {
    return "task '" + task + "' produced a non-finite output " + value + " at t = " + seconds(now) +
           " (a division by zero or a NaN in its behavior?)";
  }

  RunContext<A> ctx_;
  std::string name_;
  Task<A, B> task_;
  Behavior<A> final_;
  ResultSlot<ResultOf<B>> slot_;
  std::exception_ptr failure_;
  std::int64_t parentRecord_;
  bool holdRoboErrs_;
  bool stops_;
  std::optional<Instant> endedAt_;
  Instant here_;  // the instant sampled, with the lag of what starts in it
  std::uint64_t startedAt_ = 0;
  bool started_ = false;
  bool reported_ = false;
};

}  // namespace detail
}  // namespace frob
