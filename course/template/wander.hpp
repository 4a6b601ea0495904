#pragma once
// The tasks of the controller, in a header of their own so that tests/wander_test.cpp can test them.
#include <frob/frob.hpp>

namespace wander {

using namespace frob;
using namespace frob::literals;

// The nearest echo ahead: the five sonars that look ahead (0 is straight ahead; 1, 2 to the left;
// 15, 14 to the right).
inline Behavior<double> ahead(const Robot& r) {
  return min(min(min(sonar(r, 14), sonar(r, 15)), min(sonar(r, 0), sonar(r, 1))), sonar(r, 2));
}

// Drive ahead until something is less than 60 cm in front.
inline Task<Wheels> goAhead() {
  return mkTask([](const TaskState& ts) { return std::pair{wheels(30_cm, 0), predicate(ahead(ts.robot()) < 60_cm)}; });
}

// Turn on the spot until the way ahead is clear.
inline Task<Wheels> turnLeft() {
  return mkTask([](const TaskState& ts) { return std::pair{wheels(0, 0.8), predicate(ahead(ts.robot()) > 1.5)}; });
}

// One task after the other, forever.
inline Task<Wheels> wander() {
  for (;;) {
    co_await goAhead();
    co_await turnLeft();
  }
}

}  // namespace wander
