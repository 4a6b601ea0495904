#pragma once
/// Tasks in parallel (the paper's section 3.3) and Lyons' process compositions (section 4.2).

#include "frob/run_task.hpp"
#include "frob/task_transformers.hpp"

#include <variant>

namespace frob {

/// How a task running beside another ended: its result, or the RoboErr that ended it. Any other
/// exception in either branch is a bug, not a robot error: it ends the whole run with its message.
template <class B>
struct Outcome {
  std::optional<ResultOf<B>> value;  ///< set when it returned
  std::optional<RoboErr> error;      ///< set when it failed
  /// True when it returned normally.
  [[nodiscard]] bool ok() const { return value.has_value(); }
};

namespace detail {

// A task run beside the current one in a run of its own: a fresh copy of the task state, none of
// the parent's scopes or filters (as the paper's cloneState). Destroying it aborts the task.
template <class A, class B>
struct Strand {
  std::shared_ptr<RunnerNode<A, B>> runner;
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
  auto runner = std::make_shared<RunnerNode<A, B>>(state, std::move(t), Behavior<A>(zeroOf<A>()), parentRecord, true);
  return {runner, Behavior<A>(runner)};
}

// Occurs once, at the instant the strand's task has ended, carrying how.
template <class A, class B>
class StrandEndNode final : public EventNode<Outcome<B>> {
 public:
  explicit StrandEndNode(Strand<A, B> s) : strand_(std::move(s)) {}

 protected:
  std::optional<Outcome<B>> compute(const Instant& now) override {
    if (fired_) return std::nullopt;
    strand_.output.at(now);  // run it up to now
    if (!strand_.done()) return std::nullopt;
    fired_ = true;
    return strand_.outcome();
  }

 private:
  Strand<A, B> strand_;
  bool fired_ = false;
};

template <class A, class B>
Event<Outcome<B>> endOf(const Strand<A, B>& s) {
  return Event<Outcome<B>>(std::make_shared<StrandEndNode<A, B>>(s));
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
    for (const Strand<A, B>& s : *strands_) v = std::invoke(merge_, v, s.output.at(now));
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

}  // namespace detail

/// The paper's withTask: runs `t1f(out2)` beside `t2f(out1, end1)` and returns the second's
/// result. The second sees the first's output at once and its end (result or error) as an event;
/// the first sees the second's output one step late (no algebraic loop). When the second ends,
/// the first is aborted. The first runs with a fresh copy of the task state. Either function may
/// be a generic lambda; the first's argument is then a Behavior<Wheels>.
template <class F1, class F2>
[[nodiscard]] auto withTask(F1 t1f, F2 t2f, std::source_location loc = std::source_location::current()) {
  using A2 = detail::FedOutput<F1>;
  using T1 = std::invoke_result_t<F1&, Behavior<A2>>;
  using A1 = typename T1::output_type;
  using B1 = typename T1::result_type;
  using B2 = typename std::invoke_result_t<F2&, Behavior<A1>, Event<Outcome<B1>>>::result_type;
  return [](F1 first, F2 second) -> Task<A2, B2> {
    detail::RunContext<A2>* ctx = co_await detail::GetContext{};
    std::int64_t record = co_await detail::GetRecord{};
    Behavior<A2> secondOut = ctx->delayedOutput();
    detail::Strand<A1, B1> strand = detail::startStrand(ctx->state, record, std::invoke(first, secondOut));
    detail::ScopeEntry<detail::Watcher> keep(ctx->watchers, detail::keepSampling(strand.output));
    if constexpr (std::is_void_v<B2>) {
      co_await std::invoke(second, strand.output, detail::endOf(strand));
    } else {
      co_return co_await std::invoke(second, strand.output, detail::endOf(strand));
    }
  }(std::move(t1f), std::move(t2f))
                                        .at(loc)
                                        .named("withTask");
}

/// Lyons' P | Q: `p` and `q` run in parallel, the output is merge(p's output, q's output) while
/// both run; it ends when both have ended, with both results. An error in either fails it.
template <class A, class BP, class BQ, class M>
  requires std::invocable<M&, const A&, const A&>
[[nodiscard]] Task<A, std::pair<ResultOf<BP>, ResultOf<BQ>>> parallel(Task<A, BP> p, Task<A, BQ> q, M merge,
                                                                      std::source_location loc = std::source_location::current()) {
  return [](Task<A, BP> first, Task<A, BQ> second, M m) -> Task<A, std::pair<ResultOf<BP>, ResultOf<BQ>>> {
    detail::RunContext<A>* ctx = co_await detail::GetContext{};
    std::int64_t record = co_await detail::GetRecord{};
    detail::Strand<A, BP> strand = detail::startStrand(ctx->state, record, std::move(first));
    detail::ScopeEntry<detail::Watcher> keep(ctx->watchers, detail::keepSampling(strand.output));
    Event<RoboErr> firstFailed =
        detail::endOf(strand).filter([](const Outcome<BP>& o) { return !o.ok(); }).map([](const Outcome<BP>& o) { return *o.error; });
    ResultOf<BQ> secondResult = co_await detail::resultOf(addError(firstFailed, detail::mergedWith(strand.output, m, std::move(second)))).quiet();
    if (!strand.done()) {  // the first goes on alone
      Behavior<A> out = strand.output;
      Event<Outcome<BP>> end = detail::endOf(strand);
      co_await mkTask([out, end](const TaskState&) { return std::pair{out, end}; }).named("waiting for the other branch");
    }
    Outcome<BP> o = strand.outcome();
    if (!o.ok()) throw *o.error;
    co_return std::pair<ResultOf<BP>, ResultOf<BQ>>(std::move(*o.value), std::move(secondResult));
  }(std::move(p), std::move(q), std::move(merge))
                                                               .at(loc)
                                                               .named("parallel");
}

/// Lyons' P # Q (disabling composition): `p` and `q` run in parallel with merged outputs; the
/// first to end wins and the other is aborted. The result says which ended (index 0 for p).
template <class A, class BP, class BQ, class M>
  requires std::invocable<M&, const A&, const A&>
[[nodiscard]] Task<A, std::variant<ResultOf<BP>, ResultOf<BQ>>> disable(Task<A, BP> p, Task<A, BQ> q, M merge,
                                                                        std::source_location loc = std::source_location::current()) {
  using Result = std::variant<ResultOf<BP>, ResultOf<BQ>>;
  return [](Task<A, BP> first, Task<A, BQ> second, M m) -> Task<A, Result> {
    detail::RunContext<A>* ctx = co_await detail::GetContext{};
    std::int64_t record = co_await detail::GetRecord{};
    std::int64_t id = ctx->nextScope++;
    detail::Strand<A, BP> strand = detail::startStrand(ctx->state, record, std::move(first));
    detail::ScopeEntry<detail::Watcher> keep(ctx->watchers, detail::keepSampling(strand.output));
    auto firstEnded = detail::endOf(strand).map([id](const Outcome<BP>& o) {
      return std::make_exception_ptr(detail::ScopeExit<Outcome<BP>>{{id, "the other branch ended first"}, o});
    });
    std::optional<ResultOf<BQ>> secondResult;
    std::optional<Outcome<BP>> o;
    try {
      detail::ScopeEntry<Event<std::exception_ptr>> scope(ctx->interrupts, firstEnded);
      secondResult = co_await detail::resultOf(detail::mergedWith(strand.output, m, std::move(second))).quiet();
    } catch (const detail::ScopeExit<Outcome<BP>>& s) {
      if (s.scope != id) throw;
      o = s.value;
    }
    if (secondResult) co_return Result(std::in_place_index<1>, std::move(*secondResult));
    if (!o->ok()) throw *o->error;
    co_return Result(std::in_place_index<0>, std::move(*o->value));
  }(std::move(p), std::move(q), std::move(merge))
                                                               .at(loc)
                                                               .named("disable");
}

/// Lyons' P <> Q (synchronous loop): p, then q, then again, forever. `pf` and `qf` make the tasks.
template <class PF, class QF>
[[nodiscard]] auto syncLoop(PF pf, QF qf, std::source_location loc = std::source_location::current()) {
  using A = typename std::invoke_result_t<PF&>::output_type;
  return [](PF p, QF q) -> Task<A> {
    for (;;) {
      co_await std::invoke(p);
      co_await std::invoke(q);
    }
  }(std::move(pf), std::move(qf))
                               .at(loc)
                               .named("syncLoop");
}

/// Lyons' P <>< Q (asynchronous loop): p; then q starts beside the rest of the loop, which runs
/// p again, and so on. The output is the loop's merged with every q still running; finished q's
/// are dropped, and an error in any q fails the loop.
template <class PF, class QF, class M>
[[nodiscard]] auto asyncLoop(PF pf, QF qf, M merge, std::source_location loc = std::source_location::current()) {
  using A = typename std::invoke_result_t<PF&>::output_type;
  using BQ = typename std::invoke_result_t<QF&>::result_type;
  return [](PF p, QF q, M m) -> Task<A> {
    detail::RunContext<A>* ctx = co_await detail::GetContext{};
    std::int64_t record = co_await detail::GetRecord{};
    auto strands = std::make_shared<std::vector<detail::Strand<A, BQ>>>();
    detail::ScopeEntry<std::function<Behavior<A>(Behavior<A>)>> merged(ctx->filters, [strands, m](Behavior<A> own) {
      return Behavior<A>(std::make_shared<detail::MergeStrandsNode<A, BQ, M>>(std::move(own), strands, m));
    });
    detail::ScopeEntry<detail::Watcher> keep(ctx->watchers, [strands](const Instant& now) {
      for (const auto& s : *strands) s.output.at(now);
      for (const auto& s : *strands) {
        if (s.done() && !s.outcome().ok()) throw *s.outcome().error;
      }
      std::erase_if(*strands, [](const auto& s) { return s.done(); });
    });
    for (;;) {
      co_await std::invoke(p);
      strands->push_back(detail::startStrand(ctx->state, record, std::invoke(q)));
    }
  }(std::move(pf), std::move(qf), std::move(merge))
                                    .at(loc)
                                    .named("asyncLoop");
}

}  // namespace frob
