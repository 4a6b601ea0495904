#pragma once
/// Errors: FROB_ASSERT for programmer mistakes, FrobError for a controller misbehaving at run time.

#include "frob/assert.hpp"
#include "frob/behavior.hpp"
#include "frob/robot_values.hpp"

#include <stdexcept>
#include <string>

namespace frob {

/// A controller misbehaved at run time (a NaN command, an exception, a runaway task chain).
/// Hosts report it with its message and go on; it never takes down a grader.
class FrobError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A library function was called in a way it does not allow (a programmer's mistake).
class UsageError : public std::logic_error {
 public:
  using std::logic_error::logic_error;
};

/// True when every number in `v` is finite (no NaN, no infinity).
[[nodiscard]] inline bool isFinite(double v) { return std::isfinite(v); }
[[nodiscard]] inline bool isFinite(const Vec2& v) { return v.allFinite(); }
[[nodiscard]] inline bool isFinite(const Wheels& w) { return std::isfinite(w.forward) && std::isfinite(w.turn); }
[[nodiscard]] inline bool isFinite(const Pose2& p) { return p.position.allFinite() && std::isfinite(p.heading); }

}  // namespace frob

#include "frob/detail/errors.hpp"  // the machinery behind the declarations below, which needs isFinite

namespace frob {

/// `b`, except that sampling a non-finite value (NaN, infinity) throws FrobError naming `what`
/// and the simulated time, so that a NaN is never hidden.
template <BehaviorType B, class T = ValueOf<B>>
  requires requires(const T& v) { isFinite(v); }
[[nodiscard]] Behavior<T> checkFinite(const B& b, std::string what) {
  return Behavior<T>(detail::makeNode<detail::CheckFiniteNode<T>>(toBehavior(b).node(), std::move(what)));
}

}  // namespace frob
