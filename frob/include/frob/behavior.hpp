#pragma once
/// Behaviors: values defined at every instant, built from constants, time, sensors and lifting.

#include "frob/detail/behavior.hpp"
#include "frob/geometry.hpp"

#include <algorithm>
#include <cmath>
#include <concepts>
#include <functional>
#include <memory>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

namespace frob {

/// True for behaviors: `Behavior<T>` and sensor readings (Pointwise).
template <class T>
concept BehaviorType = detail::IsBehavior<std::remove_cvref_t<T>>::value;

/// The value type of a behavior, or the type itself for a plain value.
template <class T>
using ValueOf = typename detail::ValueOf<std::remove_cvref_t<T>>::type;

/// The type a behavior stores for a result of type R (Eigen expressions become plain vectors).
template <class R>
using Stored = decltype(detail::plain(std::declval<R>()));

/// Operands of a pointwise operator: at least one of them is a behavior.
template <class A, class B>
concept BehaviorOperands = BehaviorType<A> || BehaviorType<B>;

/// The zero of a value type: 0 for numbers, the zero vector for Eigen vectors.
template <class T>
T zeroOf() {
  if constexpr (std::is_base_of_v<Eigen::EigenBase<T>, T>) {
    return T::Zero();
  } else {
    return T{};
  }
}

/// A plain value from which a constant Behavior<T> can be made (not a behavior, not a graph node).
template <class U, class T>
concept ValueFor = !BehaviorType<U> && !detail::IsNodeRef<std::remove_cvref_t<U>>::value && std::constructible_from<T, U&&>;

/// A value defined at every instant. Cheap to copy: copies share one node of the graph.
template <class T>
class Behavior {
 public:
  using value_type = T;

  /// The constant behavior zeroOf<T>().
  Behavior()
    requires std::default_initializable<T>
      : Behavior(zeroOf<T>()) {}
  /// The constant behavior `v` (so plain values mix freely with behaviors).
  template <class U>
    requires ValueFor<U, T>
  Behavior(U&& v);  // NOLINT(google-explicit-constructor): implicit lifting is the point
  /// A behavior computed by `node` (for library and host code).
  explicit Behavior(detail::NodeRef<detail::BehaviorNode<T>> node) : node_(std::move(node)) {}

  /// The value at instant `now`, computed at most once per instant.
  const T& at(const Instant& now) const { return node_->at(now); }
  /// The node behind this behavior.
  [[nodiscard]] const detail::NodeRef<detail::BehaviorNode<T>>& node() const { return node_; }
  /// Pointwise `f` of this behavior's value; `f` may be a member pointer: `wall.map(&Wall::distance)`.
  template <class F>
    requires std::invocable<F&, const T&>
  [[nodiscard]] auto map(F f) const;

 private:
  detail::NodeRef<detail::BehaviorNode<T>> node_;
};

/// A value computed in place from its arguments at each instant, not yet a node of the graph (a
/// sensor reading, which reads the robot's frame): it becomes one node when stored in a Behavior<R>.
template <class R, class F, class... Args>
class Pointwise {
 public:
  using value_type = R;

  Pointwise(F f, Args... args) : f_(std::move(f)), args_(std::move(args)...) {}
  /// The value at instant `now` (evaluated afresh each call; a Behavior memoises it).
  R eval(const Instant& now) const {
    return std::apply([&](const auto&... a) { return R(detail::plain(std::invoke(f_, a.get(now)...))); }, args_);
  }
  /// The value at `now` once the nodes it reads are up to date at `now` (for the library's plans).
  R evalFresh(const Instant& now) const {
    return std::apply([&](const auto&... a) { return R(detail::plain(std::invoke(f_, a.fresh(now)...))); }, args_);
  }
  /// Appends the nodes this expression reads, in the order it reads them (for the library's plans).
  void inputs(std::vector<detail::Input>& out) const {
    std::apply([&](const auto&... a) { (a.inputs(out), ...); }, args_);
  }
  /// This expression as one node of the graph.
  [[nodiscard]] Behavior<R> behavior() const { return Behavior<R>(detail::makeNode<detail::PointwiseNode<R, Pointwise>>(*this)); }
  /// Implicit conversion, so that `Behavior<double> d = sonar(r, 0);` reads naturally.
  operator Behavior<R>() const { return behavior(); }  // NOLINT(google-explicit-constructor)
  /// The value at instant `now`, as for a Behavior.
  R at(const Instant& now) const { return eval(now); }
  /// Pointwise `f` of this expression's value, as Behavior::map.
  template <class G>
    requires std::invocable<G&, const R&>
  [[nodiscard]] auto map(G g) const;

 private:
  F f_;
  std::tuple<Args...> args_;
};

/// The behavior a behavior-like value stands for: itself, or a reading as one node.
template <BehaviorType B>
[[nodiscard]] Behavior<ValueOf<B>> toBehavior(const B& b) {
  if constexpr (detail::IsPointwise<std::remove_cvref_t<B>>::value) {
    return b.behavior();
  } else {
    return b;
  }
}

template <class T>
template <class U>
  requires ValueFor<U, T>
Behavior<T>::Behavior(U&& v) : node_(detail::makeNode<detail::ConstantNode<T>>(T(std::forward<U>(v)))) {}

/// The constant behavior `v`.
template <class T>
[[nodiscard]] Behavior<std::remove_cvref_t<T>> constant(T&& v) {
  return Behavior<std::remove_cvref_t<T>>(std::forward<T>(v));
}

/// Seconds since this behavior started, counted in whole steps from the instant of the event that
/// started the task that first reads it (0 there; a timer's event may fall between samples).
[[nodiscard]] inline Behavior<double> time() { return Behavior<double>(detail::makeNode<detail::TimeNode>()); }

/// Pointwise application of `f` to behaviors and plain values: lift(f, b1, 2.0, b3).
template <class F, class... Args>
  requires std::invocable<F&, const ValueOf<Args>&...>
[[nodiscard]] Behavior<Stored<std::invoke_result_t<F&, const ValueOf<Args>&...>>> lift(F f, Args&&... args) {
  using R = Stored<std::invoke_result_t<F&, const ValueOf<Args>&...>>;
  detail::Closure closure(new F(std::move(f)), &detail::deleteClosure<F>);
  using Call = detail::LiftCall<R, F, detail::Inputs<ValueOf<Args>...>>;
  return Behavior<R>(detail::makeNode<detail::LiftNode<R, sizeof...(Args)>>(
      &Call::call, std::move(closure),
      std::array<std::shared_ptr<detail::NodeBase>, sizeof...(Args)>{detail::inputNode(std::forward<Args>(args))...}));
}

template <class T>
template <class F>
  requires std::invocable<F&, const T&>
auto Behavior<T>::map(F f) const {
  return lift(std::move(f), *this);
}

template <class R, class F, class... Args>
template <class G>
  requires std::invocable<G&, const R&>
auto Pointwise<R, F, Args...>::map(G g) const {
  return lift(std::move(g), *this);
}

}  // namespace frob

#include "frob/detail/numbers.hpp"  // what the operators below call, which needs toBehavior

namespace frob {

// Pointwise operators mixing Behavior<T> and plain values. Each is constrained on its value types,
// so `frontSonar(r) < "x"` fails to compile naming the invalid expression `a < b`.
#define FROB_BEHAVIOR_BINARY_OPERATOR(op, name)                                                               \
  template <class A, class B>                                                                                 \
    requires BehaviorOperands<A, B> && requires(const ValueOf<A>& a, const ValueOf<B>& b) { a op b; }         \
  [[nodiscard]] auto operator op(const A& a, const B& b) {                                                    \
    if constexpr (requires { detail::numbers::name(detail::number(a), detail::number(b)); }) {                \
      return detail::numbers::name(detail::number(a), detail::number(b));                                     \
    } else if constexpr (requires { detail::numbers::name(detail::behaviorOf(a), detail::behaviorOf(b)); }) { \
      return detail::numbers::name(detail::behaviorOf(a), detail::behaviorOf(b));                             \
    } else {                                                                                                  \
      return lift([](const auto& x, const auto& y) { return x op y; }, a, b);                                 \
    }                                                                                                         \
  }
FROB_BEHAVIOR_BINARY_OPERATOR(+, add)
FROB_BEHAVIOR_BINARY_OPERATOR(-, subtract)
FROB_BEHAVIOR_BINARY_OPERATOR(*, multiply)
FROB_BEHAVIOR_BINARY_OPERATOR(/, divide)
FROB_BEHAVIOR_BINARY_OPERATOR(<, less)
FROB_BEHAVIOR_BINARY_OPERATOR(<=, lessEqual)
FROB_BEHAVIOR_BINARY_OPERATOR(>, greater)
FROB_BEHAVIOR_BINARY_OPERATOR(>=, greaterEqual)
FROB_BEHAVIOR_BINARY_OPERATOR(==, equal)
FROB_BEHAVIOR_BINARY_OPERATOR(!=, notEqual)
FROB_BEHAVIOR_BINARY_OPERATOR(&&, logicalAnd)
FROB_BEHAVIOR_BINARY_OPERATOR(||, logicalOr)
#undef FROB_BEHAVIOR_BINARY_OPERATOR

/// Pointwise negation.
template <BehaviorType A>
  requires requires(const ValueOf<A>& a) { -a; }
[[nodiscard]] auto operator-(const A& a) {
  if constexpr (detail::NumberOperand<A>) {
    return detail::numbers::minus(toBehavior(a));
  } else {
    return lift([](const auto& x) { return -x; }, a);
  }
}

/// Pointwise logical not.
template <BehaviorType A>
  requires requires(const ValueOf<A>& a) { !a; }
[[nodiscard]] auto operator!(const A& a) {
  if constexpr (std::is_same_v<ValueOf<A>, bool>) {
    return detail::numbers::negate(toBehavior(a));
  } else {
    return lift([](const auto& x) { return !x; }, a);
  }
}

// Pointwise maths on behaviors of numbers (plain numbers keep using <cmath>).
#define FROB_BEHAVIOR_MATH_FUNCTION(name)                         \
  template <BehaviorType A>                                       \
    requires requires(const ValueOf<A>& a) { std::name(a); }      \
  [[nodiscard]] auto name(const A& a) {                           \
    if constexpr (detail::NumberOperand<A>) {                     \
      return detail::numbers::name(toBehavior(a));                \
    } else {                                                      \
      return lift([](const auto& x) { return std::name(x); }, a); \
    }                                                             \
  }
FROB_BEHAVIOR_MATH_FUNCTION(sin)
FROB_BEHAVIOR_MATH_FUNCTION(cos)
FROB_BEHAVIOR_MATH_FUNCTION(tan)
FROB_BEHAVIOR_MATH_FUNCTION(asin)
FROB_BEHAVIOR_MATH_FUNCTION(acos)
FROB_BEHAVIOR_MATH_FUNCTION(atan)
FROB_BEHAVIOR_MATH_FUNCTION(sqrt)
FROB_BEHAVIOR_MATH_FUNCTION(exp)
FROB_BEHAVIOR_MATH_FUNCTION(log)
FROB_BEHAVIOR_MATH_FUNCTION(abs)
FROB_BEHAVIOR_MATH_FUNCTION(floor)
FROB_BEHAVIOR_MATH_FUNCTION(ceil)
#undef FROB_BEHAVIOR_MATH_FUNCTION

/// Pointwise larger of two (behaviors or values).
template <class A, class B>
  requires BehaviorOperands<A, B> && std::totally_ordered_with<ValueOf<A>, ValueOf<B>>
[[nodiscard]] auto max(const A& a, const B& b) {
  if constexpr (detail::NumberOperand<A> && detail::NumberOperand<B>) {
    return detail::numbers::max(detail::number(a), detail::number(b));
  } else {
    return lift([](const auto& x, const auto& y) { return x < y ? std::common_type_t<decltype(x), decltype(y)>(y) : x; }, a, b);
  }
}

/// Pointwise smaller of two (behaviors or values).
template <class A, class B>
  requires BehaviorOperands<A, B> && std::totally_ordered_with<ValueOf<A>, ValueOf<B>>
[[nodiscard]] auto min(const A& a, const B& b) {
  if constexpr (detail::NumberOperand<A> && detail::NumberOperand<B>) {
    return detail::numbers::min(detail::number(a), detail::number(b));
  } else {
    return lift([](const auto& x, const auto& y) { return y < x ? std::common_type_t<decltype(x), decltype(y)>(y) : x; }, a, b);
  }
}

/// Pointwise largest of three or more (behaviors or values): max(sonar(r, 15), sonar(r, 0), sonar(r, 1)).
template <class... Xs>
  requires(sizeof...(Xs) >= 3 && (BehaviorType<Xs> || ...)) && requires { typename std::common_type_t<ValueOf<Xs>...>; }
[[nodiscard]] auto max(const Xs&... xs) {
  if constexpr ((detail::NumberOperand<Xs> && ...)) {
    return detail::numbers::maxOf({detail::number(xs)...});
  } else {
    return lift([](const ValueOf<Xs>&... v) { return std::max({static_cast<std::common_type_t<ValueOf<Xs>...>>(v)...}); }, xs...);
  }
}

/// Pointwise smallest of three or more (behaviors or values): min(sonar(r, 15), sonar(r, 0), sonar(r, 1)).
template <class... Xs>
  requires(sizeof...(Xs) >= 3 && (BehaviorType<Xs> || ...)) && requires { typename std::common_type_t<ValueOf<Xs>...>; }
[[nodiscard]] auto min(const Xs&... xs) {
  if constexpr ((detail::NumberOperand<Xs> && ...)) {
    return detail::numbers::minOf({detail::number(xs)...});
  } else {
    return lift([](const ValueOf<Xs>&... v) { return std::min({static_cast<std::common_type_t<ValueOf<Xs>...>>(v)...}); }, xs...);
  }
}

/// Pointwise `v` limited to [lo, hi].
template <class V, class L, class H>
  requires BehaviorType<V> || BehaviorType<L> || BehaviorType<H>
[[nodiscard]] auto clamp(const V& v, const L& lo, const H& hi) {
  if constexpr (detail::NumberOperand<V> && detail::NumberOperand<L> && detail::NumberOperand<H>) {
    return detail::numbers::clamp(detail::number(v), detail::number(lo), detail::number(hi));
  } else {
    return lift([](double x, double l, double h) { return x < l ? l : (h < x ? h : x); }, v, lo, hi);
  }
}

/// Pointwise atan2(y, x), radians.
template <class Y, class X>
  requires BehaviorOperands<Y, X>
[[nodiscard]] auto atan2(const Y& y, const X& x) {
  if constexpr (detail::NumberOperand<Y> && detail::NumberOperand<X>) {
    return detail::numbers::atan2(detail::number(y), detail::number(x));
  } else {
    return lift([](double a, double b) { return std::atan2(a, b); }, y, x);
  }
}

/// Pointwise `base` to the power `e`.
template <class A, class B>
  requires BehaviorOperands<A, B>
[[nodiscard]] auto pow(const A& base, const B& e) {
  if constexpr (detail::NumberOperand<A> && detail::NumberOperand<B>) {
    return detail::numbers::pow(detail::number(base), detail::number(e));
  } else {
    return lift([](double a, double b) { return std::pow(a, b); }, base, e);
  }
}

/// Pointwise length of a vector behavior.
template <BehaviorType V>
[[nodiscard]] auto norm(const V& v) {
  if constexpr (std::is_same_v<ValueOf<V>, Point2>) {
    return detail::numbers::norm(toBehavior(v));
  } else {
    return lift([](const Vec2& x) { return x.norm(); }, v);
  }
}

/// Pointwise distance between two points (behaviors or values).
template <class A, class B>
  requires BehaviorOperands<A, B>
[[nodiscard]] auto distance(const A& a, const B& b) {
  if constexpr (std::is_same_v<ValueOf<A>, Point2> && std::is_same_v<ValueOf<B>, Point2>) {
    return detail::numbers::distance(detail::behaviorOf(a), detail::behaviorOf(b));
  } else {
    return lift([](const Point2& p, const Point2& q) { return (p - q).norm(); }, a, b);
  }
}

/// Pointwise direction of a vector behavior, radians in (-pi, pi].
template <BehaviorType V>
[[nodiscard]] auto heading(const V& v) {
  if constexpr (std::is_same_v<ValueOf<V>, Point2>) {
    return detail::numbers::heading(toBehavior(v));
  } else {
    return lift([](const Vec2& x) { return std::atan2(x.y(), x.x()); }, v);
  }
}

/// Pointwise angle wrapped to (-pi, pi].
template <BehaviorType A>
[[nodiscard]] auto wrapAngle(const A& a) {
  if constexpr (detail::NumberOperand<A>) {
    return detail::numbers::wrapAngle(toBehavior(a));
  } else {
    return lift([](double x) { return wrapAngle(x); }, a);
  }
}

}  // namespace frob
