#pragma once
/// Events: discrete occurrences in time, each carrying a value; at most one per instant.

#include "frob/behavior.hpp"

#include <cstdint>
#include <optional>
#include <utility>

namespace frob {

/// The value of an occurrence that carries no information.
struct Unit {
  friend bool operator==(Unit, Unit) = default;
};

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

template <class F, class T>
decltype(auto) callWith(F& f, const T& v) {
  if constexpr (std::invocable<F&, const T&>) {
    return std::invoke(f, v);
  } else {
    return std::invoke(f);
  }
}

}  // namespace detail

/// True for `Event<T>`.
template <class T>
concept EventType = detail::IsEvent<std::remove_cvref_t<T>>::value;

/// Discrete occurrences carrying a `T`. Cheap to copy: copies share one node of the graph.
template <class T>
class Event {
 public:
  using value_type = T;

  /// An event computed by `node` (for library and host code).
  explicit Event(std::shared_ptr<detail::EventNode<T>> node) : node_(std::move(node)) {}

  /// The occurrence at instant `now`, if any; checked at most once per instant.
  const std::optional<T>& at(const Instant& now) const { return node_->at(now); }
  /// The node behind this event.
  [[nodiscard]] const std::shared_ptr<detail::EventNode<T>>& node() const { return node_; }

  /// The paper's `e ==> f`: each occurrence's value transformed by `f` (which may also take no argument).
  template <class F>
    requires std::invocable<F&, const T&> || std::invocable<F&>
  [[nodiscard]] auto map(F f) const;
  /// Each occurrence carrying `v` instead of its own value (the paper's `e -=> v`).
  template <class U>
  [[nodiscard]] auto as(U v) const {
    return map([v = std::move(v)] { return v; });
  }
  /// Only the occurrences whose value satisfies `p`.
  template <class P>
    requires std::predicate<P&, const T&>
  [[nodiscard]] Event filter(P p) const;

 private:
  std::shared_ptr<detail::EventNode<T>> node_;
};

namespace detail {

template <class T>
class NeverNode final : public EventNode<T> {
 protected:
  std::optional<T> compute(const Instant&) override { return std::nullopt; }
};

template <class R, class T, class F>
class MapNode final : public EventNode<R> {
 public:
  MapNode(std::shared_ptr<EventNode<T>> e, F f) : e_(std::move(e)), f_(std::move(f)) {}

 protected:
  std::optional<R> compute(const Instant& now) override {
    const std::optional<T>& o = e_->at(now);
    if (!o) return std::nullopt;
    return R(plain(callWith(f_, *o)));
  }

 private:
  std::shared_ptr<EventNode<T>> e_;
  F f_;
};

template <class T, class P>
class FilterNode final : public EventNode<T> {
 public:
  FilterNode(std::shared_ptr<EventNode<T>> e, P p) : e_(std::move(e)), p_(std::move(p)) {}

 protected:
  std::optional<T> compute(const Instant& now) override {
    const std::optional<T>& o = e_->at(now);
    if (o && std::invoke(p_, *o)) return o;
    return std::nullopt;
  }

 private:
  std::shared_ptr<EventNode<T>> e_;
  P p_;
};

// Both sides are checked every instant (so stateful events on the right keep their state current);
// on a tie the left occurrence wins.
template <class T>
class OrNode final : public EventNode<T> {
 public:
  OrNode(std::shared_ptr<EventNode<T>> a, std::shared_ptr<EventNode<T>> b) : a_(std::move(a)), b_(std::move(b)) {}

 protected:
  std::optional<T> compute(const Instant& now) override {
    const std::optional<T>& a = a_->at(now);
    const std::optional<T>& b = b_->at(now);
    return a ? a : b;
  }

 private:
  std::shared_ptr<EventNode<T>> a_, b_;
};

// Fires when the condition becomes true, including at its first sample if it already holds.
class PredicateNode final : public EventNode<Unit> {
 public:
  explicit PredicateNode(std::shared_ptr<BehaviorNode<bool>> b) : b_(std::move(b)) {}

 protected:
  std::optional<Unit> compute(const Instant& now) override {
    bool v = b_->at(now);
    bool rising = v && !previous_;
    previous_ = v;
    return rising ? std::optional<Unit>(Unit{}) : std::nullopt;
  }

 private:
  std::shared_ptr<BehaviorNode<bool>> b_;
  bool previous_ = false;
};

// The first occurrence only; the source is released after it so that it can be freed.
template <class T>
class OnceNode final : public EventNode<T> {
 public:
  explicit OnceNode(std::shared_ptr<EventNode<T>> e) : e_(std::move(e)) {}

 protected:
  std::optional<T> compute(const Instant& now) override {
    if (!e_) return std::nullopt;
    std::optional<T> o = e_->at(now);
    if (o) e_.reset();
    return o;
  }

 private:
  std::shared_ptr<EventNode<T>> e_;
};

// The behavior is sampled every instant, not only at occurrences, so stateful behaviors stay current.
template <class T, class U>
class SnapshotNode final : public EventNode<std::pair<T, U>> {
 public:
  SnapshotNode(std::shared_ptr<EventNode<T>> e, std::shared_ptr<BehaviorNode<U>> b) : e_(std::move(e)), b_(std::move(b)) {}

 protected:
  std::optional<std::pair<T, U>> compute(const Instant& now) override {
    const U& u = b_->at(now);
    const std::optional<T>& o = e_->at(now);
    if (!o) return std::nullopt;
    return std::pair<T, U>(*o, u);
  }

 private:
  std::shared_ptr<EventNode<T>> e_;
  std::shared_ptr<BehaviorNode<U>> b_;
};

// Occurs at local times k × period for k = 1, 2, ... (or once at `period` when not repeating),
// on the first instant at or after each; carries the number of periods elapsed, which may step by
// more than one when the period is shorter than the clock's step.
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

template <class T>
template <class F>
  requires std::invocable<F&, const T&> || std::invocable<F&>
auto Event<T>::map(F f) const {
  using R = Stored<typename detail::MapResult<F, T>::type>;
  return Event<R>(std::make_shared<detail::MapNode<R, T, F>>(node_, std::move(f)));
}

template <class T>
template <class P>
  requires std::predicate<P&, const T&>
Event<T> Event<T>::filter(P p) const {
  return Event<T>(std::make_shared<detail::FilterNode<T, P>>(node_, std::move(p)));
}

/// The paper's `e .|. e'`: occurrences of either; when both occur at the same instant, `a`'s wins.
template <class T>
[[nodiscard]] Event<T> operator|(const Event<T>& a, const Event<T>& b) {
  return Event<T>(std::make_shared<detail::OrNode<T>>(a.node(), b.node()));
}

/// The paper's `neverE`: an event that never occurs.
template <class T = Unit>
[[nodiscard]] Event<T> never() {
  return Event<T>(std::make_shared<detail::NeverNode<T>>());
}

/// Occurs when `condition` becomes true, including at its first sample if it already holds; it
/// occurs again only after the condition has been false.
[[nodiscard]] inline Event<Unit> predicate(const Behavior<bool>& condition) {
  return Event<Unit>(std::make_shared<detail::PredicateNode>(condition.node()));
}

/// Only the first occurrence of `e`.
template <class T>
[[nodiscard]] Event<T> once(const Event<T>& e) {
  return Event<T>(std::make_shared<detail::OnceNode<T>>(e.node()));
}

/// At each occurrence of `e`, its value paired with `b`'s value at that instant.
template <class T, class B>
  requires BehaviorType<B>
[[nodiscard]] Event<std::pair<T, ValueOf<B>>> snapshot(const Event<T>& e, const B& b) {
  using U = ValueOf<B>;
  return Event<std::pair<T, U>>(std::make_shared<detail::SnapshotNode<T, U>>(e.node(), toBehavior(b).node()));
}

/// Occurs once, `seconds` (>= 0) after it starts (its first sample).
[[nodiscard]] Event<Unit> after(double seconds);

/// Occurs every `seconds` (> 0) after it starts, carrying how many periods have elapsed: 1, 2, 3, ...
/// at any step; when `seconds` is shorter than the step, one occurrence per step carries the count
/// of every period elapsed so far (e.g. every(0.03) at 10 Hz: 3, 6, 10, 13, ...).
[[nodiscard]] Event<std::int64_t> every(double seconds);

}  // namespace frob
