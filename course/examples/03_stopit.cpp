// Example 3: the paper's `stopit` event (paper section 2.3).
//
//     stopit r = predicate (time > timeMax || frontSonar r < 20)
//
// An event built from a condition: it happens at the first instant the condition is true. Here it
// ends a drive: stop when time is up, or when the wall ahead is closer than 20 cm, whichever comes
// first. The robot drives at the east wall of the room and stops short of it (the sonar wins), turns
// round, and drives back for 4 seconds (the clock wins).
//
// Run it:  build/app/frob run course/examples/03_stopit.cpp
// What to look for: the robot stops about 20 cm from the wall without touching it, turns round,
// and stops again in the middle of the room.

#include <frob/frob.hpp>

using namespace frob;
using namespace frob::literals;

// Step 1. The paper's stopit, with timeMax as a parameter.
//
// `time()` is a behavior: the seconds since it started, and it starts when the task that uses it
// starts. `||` and `<` work point by point on behaviors. predicate turns the condition into an
// event; the event happens when the condition becomes true (or at once if it is true at the start).
Event<Unit> stopit(const Robot& r, double timeMax) {
  return predicate(time() > timeMax || frontSonar(r) < 20_cm);
}

// Step 2. Drive straight ahead until stopit happens.
//
// We drive at 25 cm/s, slowly enough to stop in 3 cm: the sonar reads every 10 ms (the robot moves
// 2.5 mm in that time) and the wheels brake at 1 m/s^2. The front sonar is enough here because we
// meet the wall head-on (see example 1 for walls met at a slant).
Task<Wheels> driveUntilStopit(double timeMax) {
  return mkTask([timeMax](const TaskState& ts) {
    return std::pair{wheels(25_cm, 0), stopit(ts.robot(), timeMax)};
  });
}

// Step 3. Turn on the spot until we face the other way.
//
// The task state remembers the heading the robot had when this task began (initialOrientation).
// angleDiff gives the signed smallest angle between two headings, so we turn until our heading is
// (nearly) the start heading plus 180 degrees.
Task<Wheels> turnAround() {
  return mkTask([](const TaskState& ts) {
    double target = ts.initialOrientation() + 180_deg;
    auto offBy = lift([target](double heading) { return std::abs(angleDiff(heading, target)); }, orientation(ts.robot()));
    return std::pair{wheels(0, 0.6), predicate(offBy < 2_deg)};
  });
}

// Step 4. The whole program. Each drive is a new task, so each gets its own clock: `time()` in the
// second stopit starts at zero when the second drive starts.
Task<Wheels> stopitDemo() {
  co_await driveUntilStopit(30_s);  // ends on the sonar after about 10 s: the wall was 2.8 m away
  co_await turnAround();
  co_await driveUntilStopit(4_s);   // ends on the clock, 1 m later, far from any wall
}

// The task returns after the second drive, and that ends the run.
FROB_CONTROLLER(stopitDemo, .world = "empty", .seconds = 30,
                .summary = "the paper's stopit: a drive that ends on a timeout or a near wall (paper 2.3)")
