// A typical wrong submission: it stops when anything is within 50 cm ahead (the five front sonars)
// and always turns a quarter turn to the right. The door posts stop it in the doorway, and quarter
// turns to the right only ever send it back down the hall: it never gets into the room.
#include <frob/frob.hpp>

using namespace frob;
using namespace frob::literals;

Behavior<double> frontArc(const Robot& r) {
  return min(min(min(sonar(r, 14), sonar(r, 15)), min(sonar(r, 0), sonar(r, 1))), sonar(r, 2));
}

// Drive ahead until something is less than 50 cm ahead.
Task<Wheels> goAhead() {
  return mkTask([](const TaskState& ts) {
    return std::pair{wheels(40_cm, 0), predicate(frontArc(ts.robot()) < 50_cm)};
  });
}

// A quarter turn to the right: 0.5 rad/s for pi seconds.
Task<Wheels> quarterTurnRight() {
  return mkTask([](const TaskState&) { return std::pair{wheels(0, -0.5), after(pi)}; });
}

Task<Wheels> runAround() {
  for (;;) {
    co_await goAhead();
    co_await quarterTurnRight();
  }
}

FROB_CONTROLLER(runAround, .world = "assignments/wander/worlds/living_room.toml", .seconds = 120)
