#pragma once
// The machinery behind event.hpp: the nodes each event combinator makes. event.hpp includes it
// once it has defined Unit, which PredicateNode needs.

#include "frob/behavior.hpp"

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <type_traits>
#include <utility>

namespace frob {

template <class T>
class Event;

namespace detail {

template <class T>
struct IsEvent : std::false_type {};
template <class T>
struct IsEvent<Event<T>> : std::true_type {};

// The result of an event's map function, which may take the occurrence's value or nothing.
template <class F, class T>
struct MapResult {
  using type = std::invoke_result_t<F&>;
};
template <class F, class T>
  requires std::invocable<F&, const T&>
struct MapResult<F, T> {
  using type = std::invoke_result_t<F&, const T&>;
};

// Calls map function F, kept in `closure`, with an occurrence's value `v` (or with nothing, for
// a function that takes nothing); std::invoke only for member pointers, others directly.
template <class R, class T, class F>
R callMap(void* closure, const T& v) {
  F& f = *static_cast<F*>(closure);
  if constexpr (std::is_member_pointer_v<F>) {
    return R(plain(std::invoke(f, v)));
  } else if constexpr (std::invocable<F&, const T&>) {
    return R(plain(f(v)));
  } else {
    return R(plain(f()));
  }
}

template <class T>
class NeverNode final : public EventNode<T> {
 protected:
  std::optional<T> compute(const Instant&) override { return std::nullopt; }
};

// An event's map function's node, one type per R and T: the function is type-erased (callMap and
// its closure on the heap), as a lifted function's is (see LiftNode).
template <class R, class T>
class MapNode final : public EventNode<R> {
 public:
  using Call = R (*)(void* closure, const T& v);
  MapNode(NodeRef<EventNode<T>> e, Call call, Closure closure) : e_(std::move(e)), call_(call), closure_(std::move(closure)) {}

 protected:
  std::optional<R> compute(const Instant& now) override {
    const std::optional<T>& o = e_->at(now);
    if (!o) return std::nullopt;
    this->origin_ = e_->origin();
    return call_(closure_.get(), *o);
  }

 private:
  NodeRef<EventNode<T>> e_;
  Call call_;
  Closure closure_;
};

template <class T, class P>
class FilterNode final : public EventNode<T> {
 public:
  FilterNode(NodeRef<EventNode<T>> e, P p) : e_(std::move(e)), p_(std::move(p)) {}

 protected:
  std::optional<T> compute(const Instant& now) override {
    const std::optional<T>& o = e_->at(now);
    this->origin_ = e_->origin();
    if constexpr (std::is_member_pointer_v<P>) {
      if (o && std::invoke(p_, *o)) return o;
    } else {
      if (o && p_(*o)) return o;
    }
    return std::nullopt;
  }

 private:
  NodeRef<EventNode<T>> e_;
  P p_;
};

// Both sides are checked every instant (so stateful events on the right keep their state current);
// on a tie the left occurrence wins.
template <class T>
class OrNode final : public EventNode<T> {
 public:
  OrNode(NodeRef<EventNode<T>> a, NodeRef<EventNode<T>> b) : a_(std::move(a)), b_(std::move(b)) {}

 protected:
  std::optional<T> compute(const Instant& now) override {
    const std::optional<T>& a = a_->at(now);
    const std::optional<T>& b = b_->at(now);
    this->origin_ = a ? a_->origin() : b_->origin();
    return a ? a : b;
  }

 private:
  NodeRef<EventNode<T>> a_, b_;
};

// Fires when the condition becomes true, including at its first sample if it already holds: then
// at its start, which may lie between samples (that instant's lag).
class PredicateNode final : public EventNode<Unit> {
 public:
  explicit PredicateNode(NodeRef<BehaviorNode<bool>> b) : b_(std::move(b)) {}

 protected:
  std::optional<Unit> compute(const Instant& now) override {
    bool v = b_->at(now);
    bool rising = v && !previous_;
    this->origin_.lag = sampled_ ? 0.0 : now.lag;
    previous_ = v;
    sampled_ = true;
    return rising ? std::optional<Unit>(Unit{}) : std::nullopt;
  }

 private:
  NodeRef<BehaviorNode<bool>> b_;
  bool previous_ = false;
  bool sampled_ = false;
};

// The first occurrence only; the source is released at the next instant, so that it can be freed
// and the address of the occurrence's origin stays its own within the instant (see UsedOccurrences).
template <class T>
class OnceNode final : public EventNode<T> {
 public:
  explicit OnceNode(NodeRef<EventNode<T>> e) : e_(std::move(e)) {}

 protected:
  std::optional<T> compute(const Instant& now) override {
    if (occurred_) e_.reset();
    if (!e_) return std::nullopt;
    std::optional<T> o = e_->at(now);
    if (o) occurred_ = true, this->origin_ = e_->origin();
    return o;
  }

 private:
  NodeRef<EventNode<T>> e_;
  bool occurred_ = false;
};

// The behavior is sampled every instant, not only at occurrences, so stateful behaviors stay current.
template <class T, class U>
class SnapshotNode final : public EventNode<std::pair<T, U>> {
 public:
  SnapshotNode(NodeRef<EventNode<T>> e, NodeRef<BehaviorNode<U>> b) : e_(std::move(e)), b_(std::move(b)) {}

 protected:
  std::optional<std::pair<T, U>> compute(const Instant& now) override {
    const U& u = b_->at(now);
    const std::optional<T>& o = e_->at(now);
    if (!o) return std::nullopt;
    this->origin_ = e_->origin();
    return std::pair<T, U>(*o, u);
  }

 private:
  NodeRef<EventNode<T>> e_;
  NodeRef<BehaviorNode<U>> b_;
};

// Occurs at local times k × period for k = 1, 2, ... (or once at `period` when not repeating),
// on the first instant at or after each, with the time since it as its lag; carries the number of
// periods elapsed, which may step by more than one when the period is shorter than the clock's step.
class TimerNode final : public EventNode<std::int64_t> {
 public:
  TimerNode(double period, bool repeat) : period_(period), repeat_(repeat) {}

 protected:
  std::optional<std::int64_t> compute(const Instant& now) override;

 private:
  StartTime start_;
  double period_;
  bool repeat_;
  std::int64_t fired_ = 0;
};

}  // namespace detail
}  // namespace frob
