#pragma once
/// Logical time: the instants at which behaviors are sampled and events checked.

#include <cstdint>

namespace frob {

/// One sampling instant. Every node is evaluated at most once per instant (glitch freedom).
struct Instant {
  std::uint64_t id = 0;   ///< unique across all clocks of the process; 0 is never used
  std::int64_t step = 0;  ///< steps since the clock started
  double time = 0.0;      ///< step × dt, seconds
  double dt = 0.0;        ///< the clock's step, seconds
  double lag = 0.0;       ///< what is first sampled now began this long before, seconds: an event between samples started it
};

/// A fixed-step logical clock: instants at t = 0, dt, 2 dt, ... Never reads the wall clock.
class Clock {
 public:
  /// A clock with step `dt` seconds (> 0), at step 0.
  explicit Clock(double dt);
  /// The current instant.
  [[nodiscard]] const Instant& now() const { return now_; }
  /// Moves to the next step and returns it.
  const Instant& advance();

 private:
  Instant now_;
};

}  // namespace frob
