#pragma once
// The machinery behind behavior.hpp's operators and functions: behaviors of numbers, truths and
// points, and plain values beside them, combine through functions compiled once in libfrob
// (frob/src/behavior.cpp), so that a controller's expressions instantiate no nested expression
// types and compile quickly; other value types combine through lift. Included by behavior.hpp
// once Behavior and toBehavior are declared.

#include "frob/geometry.hpp"

#include <initializer_list>
#include <type_traits>

namespace frob::detail {
template <class A>
concept NumberOperand = std::is_same_v<frob::ValueOf<A>, double> || std::is_arithmetic_v<std::remove_cvref_t<A>>;
template <class A>
concept KeptOperand = std::is_same_v<frob::ValueOf<A>, bool> || std::is_same_v<frob::ValueOf<A>, double> || std::is_same_v<frob::ValueOf<A>, Point2>;
// A number operand as a Behavior<double> (a plain number becomes a constant one).
template <NumberOperand A>
Behavior<double> number(const A& a) {
  if constexpr (BehaviorType<A>) {
    return toBehavior(a);
  } else {
    return Behavior<double>(static_cast<double>(a));
  }
}
// A truth, number or point operand as a behavior of its own type.
template <KeptOperand A>
Behavior<frob::ValueOf<A>> behaviorOf(const A& a) {
  if constexpr (BehaviorType<A>) {
    return toBehavior(a);
  } else {
    return Behavior<frob::ValueOf<A>>(a);
  }
}
namespace numbers {
using B = Behavior<double>;
using Truth = Behavior<bool>;
B add(const B& a, const B& b);
B subtract(const B& a, const B& b);
B multiply(const B& a, const B& b);
B divide(const B& a, const B& b);
Truth less(const B& a, const B& b);
Truth lessEqual(const B& a, const B& b);
Truth greater(const B& a, const B& b);
Truth greaterEqual(const B& a, const B& b);
Truth equal(const B& a, const B& b);
Truth notEqual(const B& a, const B& b);
Truth logicalAnd(const Truth& a, const Truth& b);
Truth logicalOr(const Truth& a, const Truth& b);
Truth negate(const Truth& a);
B minus(const B& a);
B sin(const B& a);
B cos(const B& a);
B tan(const B& a);
B asin(const B& a);
B acos(const B& a);
B atan(const B& a);
B sqrt(const B& a);
B exp(const B& a);
B log(const B& a);
B abs(const B& a);
B floor(const B& a);
B ceil(const B& a);
B wrapAngle(const B& a);
B max(const B& a, const B& b);
B min(const B& a, const B& b);
B maxOf(std::initializer_list<B> all);
B minOf(std::initializer_list<B> all);
B clamp(const B& v, const B& lo, const B& hi);
B atan2(const B& y, const B& x);
B pow(const B& base, const B& e);
using P = Behavior<Point2>;
P add(const P& a, const P& b);
P subtract(const P& a, const P& b);
P multiply(const P& a, const B& b);
P multiply(const B& a, const P& b);
P divide(const P& a, const B& b);
B distance(const P& a, const P& b);
B norm(const Behavior<Vec2>& v);
B heading(const Behavior<Vec2>& v);
}  // namespace numbers
}  // namespace frob::detail
