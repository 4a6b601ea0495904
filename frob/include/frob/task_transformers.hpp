#pragma once
/// Task transformers (the paper's section 3.2): new tasks made from old ones, each scoped to the
/// task it wraps and all of that task's subtasks.

#include "frob/task.hpp"

#include <cstdio>
#include <memory>

namespace frob {
namespace detail {

// Keeps a scope entry in a run's context while the wrapping frame lives (also when it is aborted).
template <class T>
class ScopeEntry {
 public:
  ScopeEntry(std::vector<T>& stack, T entry) : stack_(stack) { stack_.push_back(std::move(entry)); }
  ScopeEntry(const ScopeEntry&) = delete;
  ScopeEntry& operator=(const ScopeEntry&) = delete;
  ~ScopeEntry() { stack_.pop_back(); }

 private:
  std::vector<T>& stack_;
};

class PublishedPicture {
 public:
  PublishedPicture(std::shared_ptr<DebugChannel> debug, Behavior<Picture> p) : debug_(std::move(debug)), handle_(debug_->publish(std::move(p))) {}
  PublishedPicture(const PublishedPicture&) = delete;
  PublishedPicture& operator=(const PublishedPicture&) = delete;
  ~PublishedPicture() { debug_->withdraw(handle_); }

 private:
  std::shared_ptr<DebugChannel> debug_;
  std::int64_t handle_;
};

// Runs `body` with the scope `open(ctx)` makes alive around it.
template <class A, class B, class Open>
Task<A, B> scoped(Task<A, B> body, Open open) {
  RunContext<A>* ctx = co_await GetContext{};
  auto scope = open(*ctx);
  if constexpr (std::is_void_v<B>) {
    co_await std::move(body);
  } else {
    co_return co_await std::move(body);
  }
}

// The parameter type of a lambda's call operator.
template <class M>
struct FirstArg;
template <class R, class C, class Arg>
struct FirstArg<R (C::*)(Arg) const> {
  using type = std::remove_cvref_t<Arg>;
};
template <class R, class C, class Arg>
struct FirstArg<R (C::*)(Arg)> {
  using type = std::remove_cvref_t<Arg>;
};

// The output type A of the task `f(Behavior<A>)` makes: from f's parameter, or Wheels (what a
// robot drives) for a generic lambda such as [](auto mine) { ... }.
template <class F>
auto fedOutput() {
  if constexpr (requires { &F::operator(); }) {
    return std::type_identity<frob::ValueOf<typename FirstArg<decltype(&F::operator())>::type>>{};
  } else {
    return std::type_identity<Wheels>{};
  }
}
template <class F>
using FedOutput = typename decltype(fedOutput<F>())::type;

// Awaits `body` and gives its result, with Unit for a void task.
template <class A, class B>
Task<A, ResultOf<B>> resultOf(Task<A, B> body) {
  if constexpr (std::is_void_v<B>) {
    co_await std::move(body);
    co_return Unit{};
  } else {
    co_return co_await std::move(body);
  }
}

}  // namespace detail

/// The paper's taskCatch: runs `t`; if it fails with a RoboErr, becomes `handler(error)`.
/// The handler takes this task's place (a tail call), so a task that restarts itself from its
/// handler, as the paper's `bug` does, runs in constant memory.
template <class A, class B, class H>
  requires std::invocable<H&, const RoboErr&>
[[nodiscard]] Task<A, B> taskCatch(Task<A, B> t, H handler, std::source_location loc = std::source_location::current()) {
  std::string inner = t.name();
  return [](Task<A, B> body, H h) -> Task<A, B> {
    std::optional<RoboErr> caught;
    try {
      if constexpr (std::is_void_v<B>) {
        co_await std::move(body);
        co_return;
      } else {
        co_return co_await std::move(body);
      }
    } catch (const RoboErr& e) {
      caught = e;
    }
    co_await become(Task<A, B>(std::invoke(h, *caught)));
  }(std::move(t), std::move(handler))
                                         .at(loc)
                                         .named("taskCatch(" + inner + ")");
}

/// The paper's addError: `error` fails every subtask of `t` while `t` runs (scoped).
template <class A, class B>
[[nodiscard]] Task<A, B> addError(Event<RoboErr> error, Task<A, B> t, std::source_location loc = std::source_location::current()) {
  std::string name = "addError(" + t.name() + ")";
  auto asException = error.map([](const RoboErr& e) { return std::make_exception_ptr(e); });
  return detail::scoped(std::move(t),
                        [asException](detail::RunContext<A>& ctx) {
                          return std::make_unique<detail::ScopeEntry<Event<std::exception_ptr>>>(ctx.interrupts, asException);
                        })
      .at(loc)
      .named(std::move(name));
}

/// The paper's timeLimit: `t`'s result, or no value if `t` has not ended within `seconds`
/// (then `t` and its subtasks are aborted).
template <class A, class B>
[[nodiscard]] Task<A, std::optional<ResultOf<B>>> timeLimit(Task<A, B> t, double seconds,
                                                            std::source_location loc = std::source_location::current()) {
  std::string name = "timeLimit(" + t.name() + ")";
  return [](Task<A, B> body, double limit) -> Task<A, std::optional<ResultOf<B>>> {
    detail::RunContext<A>* ctx = co_await detail::GetContext{};
    std::int64_t id = ctx->nextScope++;
    char reason[64];
    std::snprintf(reason, sizeof reason, "time limit of %.3g s reached", limit);
    auto expiry = after(limit).map([id, why = std::string(reason)] { return std::make_exception_ptr(detail::ScopeSignal{id, why}); });
    std::optional<ResultOf<B>> result;
    try {
      detail::ScopeEntry<Event<std::exception_ptr>> scope(ctx->interrupts, expiry);
      result = co_await detail::resultOf(std::move(body)).quiet();
    } catch (const detail::ScopeSignal& s) {
      if (s.scope != id) throw;
    }
    co_return result;
  }(std::move(t), seconds)
                                                  .at(loc)
                                                  .named(std::move(name));
}

/// The paper's withExit (an untilB around `t`): runs `t` until `exit` occurs, then aborts it and
/// returns the event's value, also when `t` ends at that very instant. If `t` ends first, that is
/// an error (RoboErr).
template <class X, class A, class B>
[[nodiscard]] Task<A, X> withExit(Event<X> exit, Task<A, B> t, std::source_location loc = std::source_location::current()) {
  std::string name = "withExit(" + t.name() + ")";
  return [](Event<X> e, Task<A, B> body) -> Task<A, X> {
    detail::RunContext<A>* ctx = co_await detail::GetContext{};
    std::int64_t id = ctx->nextScope++;
    auto signal = e.map([id](const X& x) { return std::make_exception_ptr(detail::ScopeExit<X>{{id, "its withExit event occurred"}, x}); });
    std::string bodyName = body.name();
    std::optional<X> value;
    try {
      detail::ScopeEntry<Event<std::exception_ptr>> scope(ctx->interrupts, signal);
      co_await detail::resultOf(std::move(body)).quiet();
    } catch (const detail::ScopeExit<X>& s) {
      if (s.scope != id) throw;
      value = s.value;
    }
    // A tie goes to the event, as in the paper's untilB: the body's last step was sampled with it.
    if (!value) value = e.at(*ctx->now);
    if (!value) throw RoboErr("task '" + bodyName + "' ended before its withExit event occurred");
    co_return std::move(*value);
  }(std::move(exit), std::move(t))
                                                .at(loc)
                                                .named(std::move(name));
}

/// The paper's withB: runs `t` with the behavior `f(state)` started beside it, and returns
/// `t`'s result paired with that behavior's value at the instant `t` ended. `f` gets the task state
/// of withB's start by value, as mkTask's function does: it stays put while `t`'s subtasks run.
template <class F, class A, class B>
  requires std::invocable<F&, const TaskState&>
[[nodiscard]] auto withB(F f, Task<A, B> t, std::source_location loc = std::source_location::current()) {
  using C = ValueOf<std::invoke_result_t<F&, const TaskState&>>;
  std::string name = "withB(" + t.name() + ")";
  return [](F make, Task<A, B> body) -> Task<A, std::pair<ResultOf<B>, C>> {
    detail::RunContext<A>* ctx = co_await detail::GetContext{};
    const TaskState start = ctx->state;  // a copy: the context's state moves on with each subtask
    Behavior<C> c = toBehavior(std::invoke(make, start));
    c.at(*ctx->now);  // it starts with the task
    detail::ScopeEntry<std::function<void(const Instant&)>> watch(ctx->watchers, [c](const Instant& now) { c.at(now); });
    ResultOf<B> r = co_await detail::resultOf(std::move(body)).quiet();
    co_return std::pair<ResultOf<B>, C>(std::move(r), c.at(*ctx->now));
  }(std::move(f), std::move(t))
                                            .at(loc)
                                            .named(std::move(name));
}

/// The paper's withMyResult: the task `f(mine)` where `mine` is that task's own output, one
/// step late (so that a controller can feed back on its output without an algebraic loop).
/// `f` may be a generic lambda ([](auto mine) { ... }): `mine` is then a Behavior<Wheels>.
template <class F>
[[nodiscard]] auto withMyResult(F f, std::source_location loc = std::source_location::current()) {
  using A = detail::FedOutput<F>;
  using B = typename std::invoke_result_t<F&, Behavior<A>>::result_type;
  return [](F make) -> Task<A, B> {
    detail::RunContext<A>* ctx = co_await detail::GetContext{};
    Behavior<A> mine = ctx->delayedOutput();
    if constexpr (std::is_void_v<B>) {
      co_await std::invoke(make, mine);
    } else {
      co_return co_await std::invoke(make, mine);
    }
  }(std::move(f))
                           .at(loc)
                           .named("withMyResult");
}

/// The paper's withFilter: every output of `t` and its subtasks passes through `f`, either a
/// function of values (A -> A) or of behaviors (Behavior<A> -> Behavior<A>).
template <class F, class A, class B>
[[nodiscard]] Task<A, B> withFilter(F f, Task<A, B> t, std::source_location loc = std::source_location::current()) {
  std::string name = "withFilter(" + t.name() + ")";
  std::function<Behavior<A>(Behavior<A>)> filter;
  // A function of behaviors is tried first: a function of values would also accept a Behavior
  // argument's implicit lifting the other way round.
  if constexpr (requires(F& g, Behavior<A> b) {
                  { std::invoke(g, b) } -> BehaviorType;
                }) {
    filter = [f](Behavior<A> b) { return toBehavior(std::invoke(f, std::move(b))); };
  } else {
    filter = [f](Behavior<A> b) { return Behavior<A>(lift(f, b)); };
  }
  return detail::scoped(std::move(t),
                        [filter](detail::RunContext<A>& ctx) {
                          return std::make_unique<detail::ScopeEntry<std::function<Behavior<A>(Behavior<A>)>>>(ctx.filters, filter);
                        })
      .at(loc)
      .named(std::move(name));
}

/// The paper's withPicture: `p` is drawn (in world coordinates) while `t` runs.
template <class A, class B>
[[nodiscard]] Task<A, B> withPicture(Behavior<Picture> p, Task<A, B> t, std::source_location loc = std::source_location::current()) {
  std::string name = "withPicture(" + t.name() + ")";
  return detail::scoped(std::move(t), [p](detail::RunContext<A>& ctx) { return std::make_unique<detail::PublishedPicture>(ctx.debug, p); })
      .at(loc)
      .named(std::move(name));
}

/// Plots `b` under `name` while `t` runs: `frob run --plot` charts it beside the front sonar and
/// the wheels (e.g. withPlot("left", sonar(r, 4), followWall())).
template <class A, class B>
[[nodiscard]] Task<A, B> withPlot(std::string name, Behavior<double> b, Task<A, B> t, std::source_location loc = std::source_location::current()) {
  return withPicture(lift([name = std::move(name)](double v) { return plotValue(name, v); }, std::move(b)), std::move(t), loc);
}

}  // namespace frob
