#pragma once
/// Reactivity: behaviors that change course when events occur.

#include "frob/detail/switching.hpp"
#include "frob/event.hpp"

namespace frob {

/// The paper's `b 'untilB' e`: follows `b` until `e` first occurs, then the behavior it carries,
/// which starts at the occurrence's instant (a timer's may fall between samples): its time(),
/// integrals and timers count from there, unless another reader had already started it.
template <BehaviorType B, class T = ValueOf<B>>
[[nodiscard]] Behavior<T> untilB(const B& b, const Event<Behavior<T>>& e) {
  return Behavior<T>(detail::makeNode<detail::SwitchNode<T>>(toBehavior(b).node(), e.node(), false));
}

/// Follows `b`, then at every occurrence of `e` the behavior it carries, started at that instant.
template <BehaviorType B, class T = ValueOf<B>>
[[nodiscard]] Behavior<T> switcher(const B& b, const Event<Behavior<T>>& e) {
  return Behavior<T>(detail::makeNode<detail::SwitchNode<T>>(toBehavior(b).node(), e.node(), true));
}

/// The paper's `stepper`: `init` until `e` occurs, then the value of its latest occurrence.
template <class T>
[[nodiscard]] Behavior<T> hold(std::type_identity_t<T> init, const Event<T>& e) {
  return Behavior<T>(detail::makeNode<detail::HoldNode<T>>(std::move(init), e.node()));
}

}  // namespace frob
