// Example 1: goAhead, turnRight, runAround (paper section 3.1).
//
// The first robot program of the paper: drive straight until something is close, turn right until
// the way is clear, and do that forever. It shows the three ideas every later example builds on:
//   * a Behavior is a value that changes over time (here: sonar ranges, wheel commands);
//   * an Event is something that happens at an instant (here: "the way ahead is blocked");
//   * a Task runs a behavior until an event ends it, and tasks are put in sequence with co_await.
//
// Run it:  build/app/frob run course/examples/01_run_around.cpp
// What to look for: the robot wanders the empty room for a minute and never touches a wall.

#include <frob/frob.hpp>

using namespace frob;
using namespace frob::literals;  // 20_cm, 90_deg, 5_s: every quantity is in SI units

// Step 1. How far away is the nearest thing ahead, and beside us?
//
// The paper reads one sonar, `frontSonar r`. A simulated (and a real) sonar only hears walls it
// faces nearly head-on: a wall met at a grazing angle reflects the ping away and the sonar reports
// nothing. So we look at the five sonars that point ahead and take the nearest echo. The 16 sonars
// are numbered counter-clockwise from the front, 22.5 degrees apart: 0 is straight ahead, 1 and 2
// look ahead-left (22.5 and 45 degrees), 15 and 14 ahead-right.
//
// `min` on behaviors works point by point: at every instant it is the smaller of the two readings.
Behavior<double> frontArc(const Robot& r) {
  return min(sonar(r, 14), sonar(r, 15), sonar(r, 0), sonar(r, 1), sonar(r, 2));
}

// For the same reason a robot driving almost parallel to a wall does not see it ahead, and would
// slowly scrape along it. The sonars at 67.5 and 90 degrees left (3, 4) and right (13, 12) catch that.
Behavior<double> sides(const Robot& r) {
  return min(sonar(r, 3), sonar(r, 4), sonar(r, 12), sonar(r, 13));
}

// Step 2. The paper's goAhead: drive forward until something is close.
//
// mkTask takes a function of the task's state (which holds the robot) and returns two things:
//   * the behavior to drive: wheels(forward speed in m/s, turn rate in rad/s);
//   * the event that ends the task: predicate(condition) happens when the condition becomes true.
// The paper drives at 10 cm/s and stops at 20 cm; we drive at 30 cm/s, so we stop earlier (the
// robot needs a few centimetres to brake and sonars cannot measure closer than 15 cm).
Task<Wheels> goAhead() {
  return mkTask([](const TaskState& ts) {
    const Robot& r = ts.robot();
    return std::pair{wheels(30_cm, 0), predicate(frontArc(r) < 50_cm || sides(r) < 25_cm)};
  });
}

// Step 3. The paper's turnRight: turn on the spot (negative turn rate = clockwise) until the way
// ahead is clear again. The paper waits for 30 cm; we wait for a metre of free space ahead and a
// little room on both sides. These limits are larger than goAhead's (1 m > 50 cm, 30 cm > 25 cm):
// otherwise goAhead could end the moment it starts, then turnRight, and so on without moving.
Task<Wheels> turnRight() {
  return mkTask([](const TaskState& ts) {
    const Robot& r = ts.robot();
    return std::pair{wheels(0, -0.5), predicate(frontArc(r) > 1_m && sides(r) > 30_cm)};
  });
}

// Step 4. The paper's runAround: goAhead, then turnRight, then runAround again, forever.
//
// `co_await` runs a task to its end before going on: this is the paper's `do` block.
// The paper loops by calling runAround from itself. The same in C++ is
//     co_await goAhead(); co_await turnRight(); co_await become(runAround());
// where `become` replaces the running task by the new one instead of nesting it, so that the
// recursion runs forever in constant memory. Compilers warn that such a function "calls itself
// on every path" (true, and meant here), so we write the loop the C++ way instead:
Task<Wheels> runAround() {
  for (;;) {
    co_await goAhead();
    co_await turnRight();
  }
}

// Step 5. Name the controller for `frob run`: which function, which world, for how long.
FROB_CONTROLLER(runAround, .world = "empty", .seconds = 60,
                .summary = "goAhead and turnRight forever: wander a room without touching a wall (paper 3.1)")
