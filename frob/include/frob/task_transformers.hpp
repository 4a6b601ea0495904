#pragma once
/// Task transformers (the paper's section 3.2): new tasks made from old ones, each scoped to the
/// task it wraps and all of that task's subtasks.

#include "frob/task.hpp"

#include <memory>
#include <optional>
#include <type_traits>
#include <utility>

namespace frob {

/// What timeLimit(t, s) gives: `t`'s result or std::nullopt when time ran out; for a task without
/// a result, true when it ended in time (the paper's `Maybe ()`).
template <class B>
using TimeLimitResult = std::conditional_t<std::is_void_v<B>, bool, std::optional<B>>;

/// What withB(f, t) gives: `t`'s result paired with the behavior's value `C` as `t` ended; for a
/// task without a result, the behavior's value alone.
template <class B, class C>
using WithBResult = std::conditional_t<std::is_void_v<B>, C, std::pair<B, C>>;

}  // namespace frob

#include "frob/detail/task_transformers.hpp"  // the coroutines behind the declarations below

namespace frob {

/// The paper's taskCatch: runs `t`; if it fails with a RoboErr, becomes `handler(error)`.
/// The handler takes this task's place (a tail call), so a task that restarts itself from its
/// handler, as the paper's `bug` does, runs in constant memory. A taskCatch whose task becomes a
/// taskCatch with the same handler (the same lambda capturing equal values: `bug` restarting after
/// a round) folds into it instead of nesting, with the meaning of nesting: one more error handled
/// before one escapes. So the restart runs in bounded depth. The RoboErrs it sees: taskError,
/// a mkTaskE error event, an enclosing addError's event, and withExit's "ended before its withExit
/// event" (a mistake in the task's logic). A timeLimit's timeout is not one: it ends the timeLimit
/// with std::nullopt, whatever handlers lie between. The occurrence that failed `t` is not seen
/// again by the handler's task (event.hpp: one occurrence is delivered once).
template <class A, class B, class H>
  requires std::invocable<H&, const RoboErr&>
[[nodiscard]] Task<A, B> taskCatch(Task<A, B> t, H handler, std::source_location loc = detail::callSite()) {
  if constexpr (!std::is_convertible_v<std::invoke_result_t<H&, const RoboErr&>, Task<A, B>>) {
    static_assert(detail::kNever<H>,
                  "taskCatch: the handler must return a task like the one it guards, the same Task<A, B> (for a "
                  "Task<Wheels, bool>, one that also ends with a bool), e.g. [g](const RoboErr&) { return bug(g); }");
    return t;
  } else {
    std::string inner = t.name();
    auto c = std::make_unique<detail::Catcher<A, B>>(detail::Erased<Task<A, B>, const RoboErr&>(std::move(handler)), sizeof(H), std::move(t));
    return detail::catching(std::move(c)).at(loc).named("taskCatch(" + inner + ")");
  }
}

/// The paper's addError: `error` fails every subtask of `t` while `t` runs (scoped), with a
/// RoboErr that a taskCatch inside `t` can catch. Each occurrence fails the subtask running at its
/// instant, once: a handler's task started in that instant runs on.
template <class A, class B>
[[nodiscard]] Task<A, B> addError(Event<RoboErr> error, Task<A, B> t, std::source_location loc = detail::callSite()) {
  std::string name = "addError(" + t.name() + ")";
  auto asException = error.map([](const RoboErr& e) { return std::make_exception_ptr(e); });
  return detail::interrupted(std::move(t), std::move(asException)).at(loc).named(std::move(name));
}

/// The paper's timeLimit: `t`'s result, or std::nullopt if `t` has not ended within `seconds`
/// (then `t` and its subtasks are aborted; the timeout is no RoboErr, so no taskCatch inside `t`
/// can hold it up: the limit holds). For a task without a result (Task<A>), a bool: true
/// when `t` ended in time, so `if (!co_await timeLimit(t, 5_s))` reads "if it ran out of time".
template <class A, class B>
[[nodiscard]] Task<A, TimeLimitResult<B>> timeLimit(Task<A, B> t, double seconds, std::source_location loc = detail::callSite()) {
  std::string name = "timeLimit(" + t.name() + ")";
  return detail::limited(std::move(t), seconds).at(loc).named(std::move(name));
}

/// The paper's withExit (an untilB around `t`): runs `t` until `exit` occurs, then aborts it and
/// returns the event's value, also when `t` ends at that very instant. If `t` ends first, that is
/// an error (RoboErr).
template <class X, class A, class B>
[[nodiscard]] Task<A, X> withExit(Event<X> exit, Task<A, B> t, std::source_location loc = detail::callSite()) {
  std::string name = "withExit(" + t.name() + ")";
  return detail::exiting(std::move(exit), std::move(t)).at(loc).named(std::move(name));
}

/// The paper's withB: runs `t` with the behavior `f(state)` started beside it, and returns
/// `t`'s result paired with that behavior's value at the instant `t` ended; for a task without a
/// result (Task<A>), that value alone. `f` gets the task state of withB's start by value, as
/// mkTask's function does: it stays put while `t`'s subtasks run.
template <class F, class A, class B>
  requires std::invocable<F&, const TaskState&>
[[nodiscard]] auto withB(F f, Task<A, B> t, std::source_location loc = detail::callSite()) {
  using C = ValueOf<std::invoke_result_t<F&, const TaskState&>>;
  std::string name = "withB(" + t.name() + ")";
  return detail::beside<C>(detail::Erased<Behavior<C>, const TaskState&>(std::move(f)), std::move(t)).at(loc).named(std::move(name));
}

/// withB given the behavior itself, not the function of the task state that makes it: a compile
/// error that shows the fix.
template <class Bh, class A, class B>
  requires(BehaviorType<Bh> && !std::invocable<Bh&, const TaskState&>)
Task<A, WithBResult<B, ValueOf<Bh>>> withB(const Bh&, Task<A, B>, std::source_location = detail::callSite()) {
  static_assert(detail::kNever<Task<A, B>>,
                "withB: the first argument is a function of the task state that makes the behavior, as in the paper "
                "(TaskState -> Behavior): write withB([b](const TaskState&) { return b; }, task), not withB(b, task)");
  __builtin_unreachable();
}

/// The paper's withMyResult: the task `f(mine)` where `mine` is that task's own output, one
/// step late (so that a controller can feed back on its output without an algebraic loop).
/// `f` may be a generic lambda ([](auto mine) { ... }): `mine` is then a Behavior<Wheels>.
template <class F>
[[nodiscard]] auto withMyResult(F f, std::source_location loc = detail::callSite()) {
  using A = detail::FedOutput<F>;
  using B = typename std::invoke_result_t<F&, Behavior<A>>::result_type;
  return detail::fedBack<A, B>(detail::Erased<Task<A, B>, Behavior<A>>(std::move(f))).at(loc).named("withMyResult");
}

/// The paper's withFilter: every output of `t` and its subtasks passes through `f`, either a
/// function of values (A -> A) or of behaviors (Behavior<A> -> Behavior<A>).
template <class F, class A, class B>
[[nodiscard]] Task<A, B> withFilter(F f, Task<A, B> t, std::source_location loc = detail::callSite()) {
  std::string name = "withFilter(" + t.name() + ")";
  return detail::filtered(std::move(t), detail::asFilter<A>(std::move(f))).at(loc).named(std::move(name));
}

/// The paper's withPicture: `p` is drawn (in world coordinates) while `t` runs.
template <class A, class B>
[[nodiscard]] Task<A, B> withPicture(Behavior<Picture> p, Task<A, B> t, std::source_location loc = detail::callSite()) {
  std::string name = "withPicture(" + t.name() + ")";
  return detail::publishing(std::move(t), std::move(p)).at(loc).named(std::move(name));
}

/// Plots `b` under `name` while `t` runs: `frob run --plot` charts it beside the front sonar and
/// the wheels (e.g. withPlot("left", sonar(r, 4), followWall())). The task stack names it
/// withPlot(left, followWall).
template <class A, class B>
[[nodiscard]] Task<A, B> withPlot(std::string name, Behavior<double> b, Task<A, B> t, std::source_location loc = detail::callSite()) {
  std::string label = "withPlot(" + name + ", " + t.name() + ")";
  return withPicture(lift([name = std::move(name)](double v) { return plotValue(name, v); }, std::move(b)), std::move(t), loc)
      .named(std::move(label));
}

}  // namespace frob
