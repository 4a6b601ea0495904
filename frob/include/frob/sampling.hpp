#pragma once
/// Running a behavior or event on its own, without a simulator (in the spirit of Yampa's `embed`).

#include "frob/event.hpp"

#include <cstdint>
#include <utility>
#include <vector>

namespace frob {

/// `b` sampled at t = 0, dt, 2 dt, ... for `steps` instants, on a fresh clock.
template <BehaviorType B, class T = ValueOf<B>>
[[nodiscard]] std::vector<T> sample(const B& behavior, double dt, std::int64_t steps) {
  Behavior<T> b = toBehavior(behavior);
  Clock clock(dt);
  std::vector<T> out;
  out.reserve(static_cast<std::size_t>(steps));
  for (std::int64_t i = 0; i < steps; ++i) {
    out.push_back(b.at(i == 0 ? clock.now() : clock.advance()));
  }
  return out;
}

/// The occurrences of `e` over t = 0, dt, ... for `steps` instants: (time, value) pairs.
template <class T>
[[nodiscard]] std::vector<std::pair<double, T>> occurrences(const Event<T>& e, double dt, std::int64_t steps) {
  Clock clock(dt);
  std::vector<std::pair<double, T>> out;
  for (std::int64_t i = 0; i < steps; ++i) {
    const Instant& now = i == 0 ? clock.now() : clock.advance();
    if (const std::optional<T>& o = e.at(now)) out.emplace_back(now.time, *o);
  }
  return out;
}

/// The time of the first occurrence of `e` within `steps` instants of `dt`, if any.
template <class T>
[[nodiscard]] std::optional<double> firstOccurrence(const Event<T>& e, double dt, std::int64_t steps) {
  Clock clock(dt);
  for (std::int64_t i = 0; i < steps; ++i) {
    const Instant& now = i == 0 ? clock.now() : clock.advance();
    if (e.at(now)) return now.time;
  }
  return std::nullopt;
}

}  // namespace frob
