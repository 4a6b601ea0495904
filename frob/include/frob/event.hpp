#pragma once
/// Events: discrete occurrences in time, each carrying a value; at most one per instant.
///
/// One occurrence is delivered once. A task sees an occurrence of its exit event, its error event
/// or an enclosing scope's (addError, timeLimit, withExit) at the instant it happens, once: when a
/// task ends or fails on it, the task started in that same instant (the next task of a sequence,
/// a taskCatch handler's task) does not see that occurrence again, though it sees its own events'
/// occurrences at that instant (a predicate whose condition already holds). An occurrence that
/// lost a tie (a scope's, while the task's own exit won) still ends the task started next.

#include "frob/behavior.hpp"

#include <cstdint>
#include <optional>
#include <utility>

namespace frob {

/// The value of an occurrence that carries no information.
struct Unit {
  friend bool operator==(Unit, Unit) = default;
};

}  // namespace frob

#include "frob/detail/event.hpp"  // the nodes behind the declarations below, which need Unit

namespace frob {

/// True for `Event<T>`.
template <class T>
concept EventType = detail::IsEvent<std::remove_cvref_t<T>>::value;

/// Discrete occurrences carrying a `T`. Cheap to copy: copies share one node of the graph.
template <class T>
class Event {
 public:
  using value_type = T;

  /// An event computed by `node` (for library and host code).
  explicit Event(detail::NodeRef<detail::EventNode<T>> node) : node_(std::move(node)) {}

  /// The occurrence at instant `now`, if any; checked at most once per instant.
  const std::optional<T>& at(const Instant& now) const { return node_->at(now); }
  /// The node behind this event.
  [[nodiscard]] const detail::NodeRef<detail::EventNode<T>>& node() const { return node_; }

  /// The paper's `e ==> f`: each occurrence's value transformed by `f` (which may also take no argument).
  template <class F>
    requires std::invocable<F&, const T&> || std::invocable<F&>
  [[nodiscard]] auto map(F f) const {
    using R = Stored<typename detail::MapResult<F, T>::type>;
    detail::Closure closure(new F(std::move(f)), &detail::deleteClosure<F>);
    return Event<R>(detail::makeNode<detail::MapNode<R, T>>(node_, &detail::callMap<R, T, F>, std::move(closure)));
  }
  /// Each occurrence carrying `v` instead of its own value (the paper's `e -=> v`).
  template <class U>
  [[nodiscard]] auto as(U v) const {
    return map([v = std::move(v)] { return v; });
  }
  /// Only the occurrences whose value satisfies `p`.
  template <class P>
    requires std::predicate<P&, const T&>
  [[nodiscard]] Event filter(P p) const {
    return Event(detail::makeNode<detail::FilterNode<T, P>>(node_, std::move(p)));
  }

 private:
  detail::NodeRef<detail::EventNode<T>> node_;
};

/// The paper's `e .|. e'`: occurrences of either; when both occur at the same instant, `a`'s wins
/// and `b`'s is not in it: `(a | b).filter(p)` drops that instant if `a`'s value fails `p`, where
/// `a.filter(p) | b.filter(p)` keeps `b`'s (filter each side to keep both).
template <class T>
[[nodiscard]] Event<T> operator|(const Event<T>& a, const Event<T>& b) {
  return Event<T>(detail::makeNode<detail::OrNode<T>>(a.node(), b.node()));
}

/// The paper's `neverE`: an event that never occurs.
template <class T = Unit>
[[nodiscard]] Event<T> never() {
  return Event<T>(detail::makeNode<detail::NeverNode<T>>());
}

/// Occurs when `condition` becomes true, including at its first sample if it already holds; it
/// occurs again only after the condition has been false. The condition is sampled once per step
/// of the run (its dt: 0.01 s in the simulator unless the world says otherwise): a condition true
/// only between two samples never fires.
[[nodiscard]] inline Event<Unit> predicate(const Behavior<bool>& condition) {
  return Event<Unit>(detail::makeNode<detail::PredicateNode>(condition.node()));
}

/// Only the first occurrence of `e`.
template <class T>
[[nodiscard]] Event<T> once(const Event<T>& e) {
  return Event<T>(detail::makeNode<detail::OnceNode<T>>(e.node()));
}

/// At each occurrence of `e`, its value paired with `b`'s value at that instant.
template <class T, class B>
  requires BehaviorType<B>
[[nodiscard]] Event<std::pair<T, ValueOf<B>>> snapshot(const Event<T>& e, const B& b) {
  using U = ValueOf<B>;
  return Event<std::pair<T, U>>(detail::makeNode<detail::SnapshotNode<T, U>>(e.node(), toBehavior(b).node()));
}

/// Occurs once, `seconds` (>= 0) after it starts: at the first sample where time() >= seconds holds
/// for a behavior started with it, at the instant `seconds` after its start (it may be in between).
[[nodiscard]] Event<Unit> after(double seconds);

/// Occurs every `seconds` (> 0) after it starts, carrying how many periods have elapsed: 1, 2, 3, ...
/// at any step; when `seconds` is shorter than the step, one occurrence per step carries the count
/// of every period elapsed so far (e.g. every(0.03) at 10 Hz: 3, 6, 10, 13, ...).
[[nodiscard]] Event<std::int64_t> every(double seconds);

}  // namespace frob
