#pragma once
// The machinery behind task_transformers.hpp: scopes kept in a run's context while a wrapped task
// runs, and the coroutines behind each transformer. task_transformers.hpp includes it once it has
// defined TimeLimitResult and WithBResult.

#include "frob/picture.hpp"
#include "frob/task.hpp"

#include <cstdio>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

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

// addError: `body` with `error` interrupting it and its subtasks.
template <class A, class B>
Task<A, B> interrupted(Task<A, B> body, Event<std::exception_ptr> error) {
  return scoped(std::move(body),
                [error](RunContext<A>& ctx) { return std::make_unique<ScopeEntry<Event<std::exception_ptr>>>(ctx.interrupts, error); });
}

// withFilter's `f` as a function of behaviors: one of behaviors is tried first, since a function
// of values would also accept a Behavior argument's implicit lifting the other way round.
template <class A, class F>
std::function<Behavior<A>(Behavior<A>)> asFilter(F f) {
  if constexpr (requires(F& g, Behavior<A> b) {
                  { g(b) } -> BehaviorType;
                }) {
    return [f](Behavior<A> b) { return toBehavior(f(std::move(b))); };
  } else {
    return [f](Behavior<A> b) { return Behavior<A>(lift(f, b)); };
  }
}

// withFilter: `body` with `filter` applied to its outputs and its subtasks'.
template <class A, class B>
Task<A, B> filtered(Task<A, B> body, std::function<Behavior<A>(Behavior<A>)> filter) {
  using Filter = std::function<Behavior<A>(Behavior<A>)>;
  return scoped(std::move(body), [filter](RunContext<A>& ctx) { return std::make_unique<ScopeEntry<Filter>>(ctx.filters, filter); });
}

// withPicture: `body` with `p` published on the robot's debug channel while it runs.
template <class A, class B>
Task<A, B> publishing(Task<A, B> body, Behavior<Picture> p) {
  return scoped(std::move(body), [p](RunContext<A>& ctx) { return std::make_unique<PublishedPicture>(ctx.debug, p); });
}

// taskCatch: `c`'s task, or on a RoboErr its handler's task in its place, inside the layers left.
template <class A, class B>
Task<A, B> catching(std::unique_ptr<Catcher<A, B>> c) {
  for (;;) {
    std::optional<RoboErr> caught;
    try {
      Task<A, B> body = std::move(*c->body);
      c->body.reset();
      if constexpr (std::is_void_v<B>) {
        co_await std::move(body);
        co_return;
      } else {
        co_return co_await std::move(body);
      }
    } catch (const RoboErr& e) {
      caught = e;
    }
    Task<A, B> next = c->handler(*caught);
    if (--c->layers == 0) {
      co_await become(std::move(next));
      if constexpr (!std::is_void_v<B>) __builtin_unreachable();  // become() destroys this frame: it never resumes
    }
    c->body = c->absorb(std::move(next));
  }
}

// timeLimit: `body` with a scope that aborts it `limit` seconds after it starts.
template <class A, class B>
Task<A, TimeLimitResult<B>> limited(Task<A, B> body, double limit) {
  RunContext<A>* ctx = co_await GetContext{};
  std::int64_t id = ctx->nextScope++;
  char reason[64];
  std::snprintf(reason, sizeof reason, "time limit of %.3g s reached", limit);
  auto expiry = after(limit).map([id, why = std::string(reason)] { return std::make_exception_ptr(ScopeSignal{id, why}); });
  std::optional<ResultOf<B>> result;
  try {
    ScopeEntry<Event<std::exception_ptr>> scope(ctx->interrupts, expiry);
    result = co_await resultOf(std::move(body)).quiet();
  } catch (const ScopeSignal& s) {
    if (s.scope != id) throw;
  }
  if constexpr (std::is_void_v<B>) {
    co_return result.has_value();
  } else {
    co_return result;
  }
}

// withExit: `body` with a scope that aborts it when `e` occurs, giving the event's value.
template <class X, class A, class B>
Task<A, X> exiting(Event<X> e, Task<A, B> body) {
  RunContext<A>* ctx = co_await GetContext{};
  std::int64_t id = ctx->nextScope++;
  auto signal = e.map([id](const X& x) { return std::make_exception_ptr(ScopeExit<X>{{id, "its withExit event occurred"}, x}); });
  std::string bodyName = body.name();
  std::optional<X> value;
  try {
    ScopeEntry<Event<std::exception_ptr>> scope(ctx->interrupts, signal);
    co_await resultOf(std::move(body)).quiet();
  } catch (const ScopeExit<X>& s) {
    if (s.scope != id) throw;
    value = s.value;
  }
  // A tie goes to the event, as in the paper's untilB: the body's last step was sampled with it.
  if (!value) value = e.at(*ctx->now);
  if (!value) throw RoboErr("task '" + bodyName + "' ended before its withExit event occurred");
  co_return std::move(*value);
}

// withB: `body` with the behavior `make(state)` sampled beside it from its start.
template <class C, class A, class B>
Task<A, WithBResult<B, C>> beside(Erased<Behavior<C>, const TaskState&> make, Task<A, B> body) {
  RunContext<A>* ctx = co_await GetContext{};
  const TaskState start = ctx->state;  // a copy: the context's state moves on with each subtask
  Behavior<C> c = make(start);
  c.at(*ctx->now);  // it starts with the task
  ScopeEntry<std::function<void(const Instant&)>> watch(ctx->watchers, [c](const Instant& now) { c.at(now); });
  if constexpr (std::is_void_v<B>) {
    co_await std::move(body);
    co_return c.at(*ctx->now);
  } else {
    B r = co_await std::move(body);
    co_return std::pair<B, C>(std::move(r), c.at(*ctx->now));
  }
}

// withMyResult: the task `make(mine)`, with `mine` its run's output one instant late.
template <class A, class B>
Task<A, B> fedBack(Erased<Task<A, B>, Behavior<A>> make) {
  RunContext<A>* ctx = co_await GetContext{};
  Behavior<A> mine = ctx->delayedOutput();
  if constexpr (std::is_void_v<B>) {
    co_await make(mine);
  } else {
    co_return co_await make(mine);
  }
}

}  // namespace detail
}  // namespace frob
