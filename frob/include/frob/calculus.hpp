#pragma once
/// Behaviors that exploit the flow of time: integral, derivative, the value at an extremum. Each starts
/// at its first sample: when the task that first drives it starts (the paper's untilB), wherever built.
#include "frob/behavior.hpp"
#include "frob/detail/calculus.hpp"

namespace frob {

/// The integral of `b` over time since this behavior started (trapezoidal rule); numbers and Vec2.
template <BehaviorType B>
[[nodiscard]] Behavior<ValueOf<B>> integral(const B& b) {
  using T = ValueOf<B>;
  return Behavior<T>(detail::makeNode<detail::IntegralNode<T>>(toBehavior(b).node()));
}

/// The rate of change of `b` (backward difference over one step); zero at the first sample, as
/// though `b` had held its first value since its start (as integral takes it).
template <BehaviorType B>
[[nodiscard]] Behavior<ValueOf<B>> derivative(const B& b) {
  using T = ValueOf<B>;
  return Behavior<T>(detail::makeNode<detail::DerivativeNode<T>>(toBehavior(b).node()));
}

/// The value of `b` at the instant `key` was smallest since this behavior started.
template <BehaviorType K, BehaviorType B>
[[nodiscard]] Behavior<ValueOf<B>> atMin(const K& key, const B& b) {
  using Node = detail::AtExtremumNode<ValueOf<K>, ValueOf<B>>;
  return Behavior<ValueOf<B>>(detail::makeNode<Node>(toBehavior(key).node(), toBehavior(b).node(), false));
}

/// The value of `b` at the instant `key` was largest since this behavior started.
template <BehaviorType K, BehaviorType B>
[[nodiscard]] Behavior<ValueOf<B>> atMax(const K& key, const B& b) {
  using Node = detail::AtExtremumNode<ValueOf<K>, ValueOf<B>>;
  return Behavior<ValueOf<B>>(detail::makeNode<Node>(toBehavior(key).node(), toBehavior(b).node(), true));
}

}  // namespace frob
