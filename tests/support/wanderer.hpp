#pragma once
// The paper's runAround, made robust for simulated sonars, shared by tests and benchmarks that need
// a robot wandering a world: go ahead until something is near, turn left until the way is clear.

#include "frob/frob.hpp"

#include <cmath>
#include <vector>

namespace frob::support {

// The nearest echo among the sonars within 45 degrees of straight ahead: one sonar alone misses
// walls it meets at a grazing angle (they reflect its ping away).
inline Behavior<double> frontArc(const Robot& r) {
  std::vector<double> angles = r.spec().sonarAngles;
  return lift(
      [angles](const std::vector<double>& ranges) {
        double nearest = 1e9;
        for (std::size_t i = 0; i < ranges.size(); ++i) {
          if (std::abs(angles[i]) <= 45.0 * pi / 180.0 + 1e-9) nearest = std::min(nearest, ranges[i]);
        }
        return nearest;
      },
      sonars(r));
}

inline Task<Wheels> goAhead(double speed) {
  return mkTask([speed](const TaskState& ts) {
    const Robot& r = ts.robot();
    return std::pair{wheels(speed, 0), predicate(frontArc(r) < 0.6) | bumper(r).map([] { return Unit{}; })};
  });
}

inline Task<Wheels> turnLeft() {
  return mkTask([](const TaskState& ts) { return std::pair{wheels(0, 0.8), predicate(frontArc(ts.robot()) > 1.5)}; });
}

// Forever: goAhead, then turnLeft (the paper's recursive form, in constant memory).
inline Task<Wheels> runAround(double speed = 0.3) {
  co_await goAhead(speed);
  co_await turnLeft();
  co_await become(runAround(speed));
}

}  // namespace frob::support
