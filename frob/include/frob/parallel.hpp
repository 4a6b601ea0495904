#pragma once
/// Tasks in parallel (the paper's section 3.3) and Lyons' process compositions (section 4.2).

#include "frob/run_task.hpp"
#include "frob/task_transformers.hpp"

#include <optional>
#include <utility>
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

}  // namespace frob

#include "frob/detail/parallel.hpp"  // the coroutines behind the declarations below, which need Outcome

namespace frob {

/// The paper's withTask: runs `t1f(out2)` beside `t2f(out1, end1)` and returns the second's
/// result. The second sees the first's output at once and its end (result or error) as an event;
/// the first sees the second's output one step late (no algebraic loop). When the second ends,
/// the first is aborted. The first runs with a fresh copy of the task state. Either function may
/// be a generic lambda; the first's argument is then a Behavior<Wheels>.
/// `end1` occurs once, at the instant the first ended, the same for every subtask of the second;
/// a subtask started after that instant does not see it (as any event's past occurrence). At that
/// instant `out1` still reads the first's last output, so snapshot(end1, out1) gives it; reading
/// `out1` after it is a run-time error naming the task and the instants, as the paper says ("after
/// this event"): the first's output exists only while it runs.
template <class F1, class F2>
[[nodiscard]] auto withTask(F1 t1f, F2 t2f, std::source_location loc = detail::callSite()) {
  using A2 = detail::FedOutput<F1>;
  using T1 = std::invoke_result_t<F1&, Behavior<A2>>;
  using A1 = typename T1::output_type;
  using B1 = typename T1::result_type;
  using B2 = typename std::invoke_result_t<F2&, Behavior<A1>, Event<Outcome<B1>>>::result_type;
  return detail::feeding<A2, A1, B1, B2>(detail::Erased<Task<A1, B1>, Behavior<A2>>(std::move(t1f)),
                                         detail::Erased<Task<A2, B2>, Behavior<A1>, Event<Outcome<B1>>>(std::move(t2f)))
      .at(loc)
      .named("withTask");
}

/// Lyons' P | Q: `p` and `q` run in parallel, the output is merge(p's output, q's output) while
/// both run; it ends when both have ended, with both results. An error in either fails it.
template <class A, class BP, class BQ, class M>
  requires std::invocable<M&, const A&, const A&>
[[nodiscard]] Task<A, std::pair<ResultOf<BP>, ResultOf<BQ>>> parallel(Task<A, BP> p, Task<A, BQ> q, M merge,
                                                                      std::source_location loc = detail::callSite()) {
  return detail::bothOf(std::move(p), std::move(q), std::move(merge)).at(loc).named("parallel");
}

/// Lyons' P # Q (disabling composition): `p` and `q` run in parallel with merged outputs; the
/// first to end wins and the other is aborted. The result says which ended (index 0 for p).
template <class A, class BP, class BQ, class M>
  requires std::invocable<M&, const A&, const A&>
[[nodiscard]] Task<A, std::variant<ResultOf<BP>, ResultOf<BQ>>> disable(Task<A, BP> p, Task<A, BQ> q, M merge,
                                                                        std::source_location loc = detail::callSite()) {
  return detail::firstOf(std::move(p), std::move(q), std::move(merge)).at(loc).named("disable");
}

/// Lyons' P <> Q (synchronous loop): p, then q, then again, forever. `pf` and `qf` make the tasks.
template <class PF, class QF>
[[nodiscard]] auto syncLoop(PF pf, QF qf, std::source_location loc = detail::callSite()) {
  using A = typename std::invoke_result_t<PF&>::output_type;
  using P = std::invoke_result_t<PF&>;
  using Q = std::invoke_result_t<QF&>;
  return detail::loop<A>(detail::Erased<P>(std::move(pf)), detail::Erased<Q>(std::move(qf))).at(loc).named("syncLoop");
}

/// Lyons' P <>< Q (asynchronous loop): p; then q starts beside the rest of the loop, which runs
/// p again, and so on. The output is the loop's merged with every q still running; finished q's
/// are dropped, and an error in any q fails the loop.
template <class PF, class QF, class M>
[[nodiscard]] auto asyncLoop(PF pf, QF qf, M merge, std::source_location loc = detail::callSite()) {
  using A = typename std::invoke_result_t<PF&>::output_type;
  using BQ = typename std::invoke_result_t<QF&>::result_type;
  using P = std::invoke_result_t<PF&>;
  return detail::spawningLoop<A, BQ>(detail::Erased<P>(std::move(pf)), detail::Erased<Task<A, BQ>>(std::move(qf)), std::move(merge))
      .at(loc)
      .named("asyncLoop");
}

}  // namespace frob
