#pragma once
// The machinery behind parallel.hpp: strands (tasks run beside the current one in runs of their
// own) and the coroutines behind each composition. parallel.hpp includes it once it has defined
// Outcome.

#include "frob/run_task.hpp"
#include "frob/task_transformers.hpp"

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace frob {
namespace detail {

// Why reading withTask's first task's output after it ended fails.
[[nodiscard]] std::string endedOutputMessage(const std::string& task, double endedAt, double readAt);

// A task run beside the current one in a run of its own: a fresh copy of the task state, none of
// the parent's scopes or filters (as the paper's cloneState). Destroying it aborts the task.
template <class A, class B>
struct Strand {
  NodeRef<RunnerNode<A, B>> runner;
  Behavior<A> output;

  [[nodiscard]] bool done() const { return runner->done(); }
  [[nodiscard]] Outcome<B> outcome() const {
    const auto& slot = runner->result();
    if (slot.value) return {slot.value, std::nullopt};
    if (slot.error) return {std::nullopt, roboErrIn(slot.error)};  // the runner holds only RoboErrs
    return {};
  }
};

template <class A, class B>
Strand<A, B> startStrand(const TaskState& state, std::int64_t parentRecord, Task<A, B> t) {
  NodeRef<BehaviorNode<A>> output = makeNode<RunnerNode<A, B>>(state, std::move(t), Behavior<A>(zeroOf<A>()), parentRecord, true);
  return {NodeRef<RunnerNode<A, B>>(output.owner(), static_cast<RunnerNode<A, B>*>(output.get())), Behavior<A>(output)};
}

// Occurs once, at the instant the strand's task ended, carrying how: the same occurrence for every
// observer, whenever it first looked. A task started after that instant does not see it.
template <class A, class B>
class StrandEndNode final : public EventNode<Outcome<B>> {
 public:
  explicit StrandEndNode(Strand<A, B> s) : strand_(std::move(s)) {}

 protected:
  std::optional<Outcome<B>> compute(const Instant& now) override {
    strand_.output.at(now);  // run it up to now
    const std::optional<Instant>& end = strand_.runner->endedAt();
    if (!end || end->id != now.id) return std::nullopt;
    return strand_.outcome();
  }

 private:
  Strand<A, B> strand_;
};

// A strand's output as withTask's second task reads it: at the instant the strand's task ended, its
// last output (what it drove until then); after that instant, a read is a run-time error naming the
// task and both instants (the paper: "reference to the value of t1 after this event will result in
// a runtime error"), never a silent default.
template <class A, class B>
class StrandOutputNode final : public BehaviorNode<A> {
 public:
  explicit StrandOutputNode(Strand<A, B> s) : strand_(std::move(s)) {}

 protected:
  A compute(const Instant& now) override {
    A v = strand_.output.at(now);
    if (const std::optional<Instant>& end = strand_.runner->endedAt()) {
      if (std::optional<A> last = strand_.runner->lastOutput(now)) return *last;
      throw FrobError(endedOutputMessage(strand_.runner->taskName(), end->time, now.time));
    }
    return v;
  }

 private:
  Strand<A, B> strand_;
};

template <class A, class B>
Event<Outcome<B>> endOf(const Strand<A, B>& s) {
  return Event<Outcome<B>>(makeNode<StrandEndNode<A, B>>(s));
}

using Watcher = std::function<void(const Instant&)>;

// Samples `out` every instant, so a strand runs whether or not anyone reads its output.
template <class A>
Watcher keepSampling(Behavior<A> out) {
  return [out](const Instant& now) { out.at(now); };
}

// A behavior merged with the outputs of a changing set of strands.
template <class A, class B, class M>
class MergeStrandsNode final : public BehaviorNode<A> {
 public:
  MergeStrandsNode(Behavior<A> own, std::shared_ptr<std::vector<Strand<A, B>>> strands, M merge)
      : own_(std::move(own)), strands_(std::move(strands)), merge_(std::move(merge)) {}

 protected:
  A compute(const Instant& now) override {
    A v = own_.at(now);
    for (const Strand<A, B>& s : *strands_) v = merge_(v, s.output.at(now));
    return v;
  }

 private:
  Behavior<A> own_;
  std::shared_ptr<std::vector<Strand<A, B>>> strands_;
  M merge_;
};

// `t` with its output merged (merge(other, own)) with another behavior.
template <class A, class B, class M>
Task<A, B> mergedWith(Behavior<A> other, M merge, Task<A, B> t) {
  return withFilter([other, merge](Behavior<A> own) { return Behavior<A>(lift(merge, other, own)); }, std::move(t));
}

// withTask: `second(first's output, first's end)` beside `first(second's output, one step late)`.
template <class A2, class A1, class B1, class B2>
Task<A2, B2> feeding(Erased<Task<A1, B1>, Behavior<A2>> first, Erased<Task<A2, B2>, Behavior<A1>, Event<Outcome<B1>>> second) {
  RunContext<A2>* ctx = co_await GetContext{};
  std::int64_t record = co_await GetRecord{};
  Behavior<A2> secondOut = ctx->delayedOutput();
  Strand<A1, B1> strand = startStrand(ctx->state, record, first(secondOut));
  strand.runner->recordOutput();
  ScopeEntry<Watcher> keep(ctx->watchers, keepSampling(strand.output));
  if constexpr (std::is_void_v<B2>) {
    co_await second(Behavior<A1>(makeNode<StrandOutputNode<A1, B1>>(strand)), endOf(strand));
  } else {
    co_return co_await second(Behavior<A1>(makeNode<StrandOutputNode<A1, B1>>(strand)), endOf(strand));
  }
}

// parallel: `first` in a strand, `second` here with the outputs merged; both results.
template <class A, class BP, class BQ, class M>
Task<A, std::pair<ResultOf<BP>, ResultOf<BQ>>> bothOf(Task<A, BP> first, Task<A, BQ> second, M m) {
  RunContext<A>* ctx = co_await GetContext{};
  std::int64_t record = co_await GetRecord{};
  Strand<A, BP> strand = startStrand(ctx->state, record, std::move(first));
  ScopeEntry<Watcher> keep(ctx->watchers, keepSampling(strand.output));
  Event<RoboErr> firstFailed = endOf(strand).filter([](const Outcome<BP>& o) { return !o.ok(); }).map([](const Outcome<BP>& o) { return *o.error; });
  ResultOf<BQ> secondResult = co_await resultOf(addError(firstFailed, mergedWith(strand.output, m, std::move(second)))).quiet();
  if (!strand.done()) {  // the first goes on alone
    Behavior<A> out = strand.output;
    Event<Outcome<BP>> end = endOf(strand);
    co_await mkTask([out, end](const TaskState&) { return std::pair{out, end}; }).named("waiting for the other branch");
  }
  Outcome<BP> o = strand.outcome();
  if (!o.ok()) throw *o.error;
  co_return std::pair<ResultOf<BP>, ResultOf<BQ>>(std::move(*o.value), std::move(secondResult));
}

// disable: `first` in a strand, `second` here with the outputs merged; the first to end wins.
template <class A, class BP, class BQ, class M>
Task<A, std::variant<ResultOf<BP>, ResultOf<BQ>>> firstOf(Task<A, BP> first, Task<A, BQ> second, M m) {
  using Result = std::variant<ResultOf<BP>, ResultOf<BQ>>;
  RunContext<A>* ctx = co_await GetContext{};
  std::int64_t record = co_await GetRecord{};
  std::int64_t id = ctx->nextScope++;
  Strand<A, BP> strand = startStrand(ctx->state, record, std::move(first));
  ScopeEntry<Watcher> keep(ctx->watchers, keepSampling(strand.output));
  auto firstEnded = endOf(strand).map([id](const Outcome<BP>& o) {
    return std::make_exception_ptr(ScopeExit<Outcome<BP>>{{id, "the other branch ended first"}, o});
  });
  std::optional<ResultOf<BQ>> secondResult;
  std::optional<Outcome<BP>> o;
  try {
    ScopeEntry<Event<std::exception_ptr>> scope(ctx->interrupts, firstEnded);
    secondResult = co_await resultOf(mergedWith(strand.output, m, std::move(second))).quiet();
  } catch (const ScopeExit<Outcome<BP>>& s) {
    if (s.scope != id) throw;
    o = s.value;
  }
  if (secondResult) co_return Result(std::in_place_index<1>, std::move(*secondResult));
  if (!o->ok()) throw *o->error;
  co_return Result(std::in_place_index<0>, std::move(*o->value));
}

// syncLoop: p, q, p, q, ... forever.
template <class A, class P, class Q>
Task<A> loop(Erased<P> p, Erased<Q> q) {
  for (;;) {
    co_await p();
    co_await q();
  }
}

// asyncLoop: p, then q in a strand beside the next round; the output merged with every q running.
template <class A, class BQ, class P, class M>
Task<A> spawningLoop(Erased<P> p, Erased<Task<A, BQ>> q, M m) {
  RunContext<A>* ctx = co_await GetContext{};
  std::int64_t record = co_await GetRecord{};
  auto strands = std::make_shared<std::vector<Strand<A, BQ>>>();
  ScopeEntry<std::function<Behavior<A>(Behavior<A>)>> merged(
      ctx->filters, [strands, m](Behavior<A> own) { return Behavior<A>(makeNode<MergeStrandsNode<A, BQ, M>>(std::move(own), strands, m)); });
  ScopeEntry<Watcher> keep(ctx->watchers, [strands](const Instant& now) {
    for (const auto& s : *strands) s.output.at(now);
    for (const auto& s : *strands) {
      if (s.done() && !s.outcome().ok()) throw *s.outcome().error;
    }
    std::erase_if(*strands, [](const auto& s) { return s.done(); });
  });
  for (;;) {
    co_await p();
    strands->push_back(startStrand(ctx->state, record, q()));
  }
}

}  // namespace detail
}  // namespace frob
