// Example 7: two tasks in parallel with withTask (paper section 3.3).
//
// So far one task ran at a time. withTask runs two side by side, each seeing what the other
// produces:
//   * the first, a "watcher", sees the second's output (here: its wheel commands);
//   * the second, the "driver", sees the watcher's output, and its end as an event.
//
// Here the driver wanders the room as in example 1, and the watcher is a trip meter: it adds up the
// distance the driver asks for, shows it, and ends when 10 m have been driven. The driver stops
// when the watcher ends, and so the run ends. The driver's code does not change at all: we can add a
// watcher to any task (a trip meter, a safety monitor, a logger) without touching it.
//
// Run it:  build/app/frob run course/examples/07_with_task.cpp
// What to look for: the trip counter next to the robot counts up while it wanders; at 10 m it stops.

#include <frob/frob.hpp>

#include <cmath>
#include <cstdio>
#include <string>

using namespace frob;
using namespace frob::literals;

constexpr double kTrip = 10.0;  // metres to drive

// ---- Step 1. The driver: example 1's runAround, unchanged -------------------------------------

Behavior<double> frontArc(const Robot& r) {
  return min(sonar(r, 14), sonar(r, 15), sonar(r, 0), sonar(r, 1), sonar(r, 2));
}
Behavior<double> sides(const Robot& r) {
  return min(sonar(r, 3), sonar(r, 4), sonar(r, 12), sonar(r, 13));
}
Task<Wheels> goAhead() {
  return mkTask([](const TaskState& ts) {
    const Robot& r = ts.robot();
    return std::pair{wheels(30_cm, 0), predicate(frontArc(r) < 50_cm || sides(r) < 25_cm)};
  });
}
Task<Wheels> turnRight() {
  return mkTask([](const TaskState& ts) {
    const Robot& r = ts.robot();
    return std::pair{wheels(0, -0.5), predicate(frontArc(r) > 1_m && sides(r) > 30_cm)};
  });
}
Task<Wheels> runAround() {
  for (;;) {
    co_await goAhead();
    co_await turnRight();
  }
}

// ---- Step 2. The watcher: a trip meter ----------------------------------------------------------
//
// A task's output need not be wheels: this one's output is a number, the metres driven so far. It
// is the integral over time of the forward speed the driver commands (`driver` is the driver's
// output, handed to us by withTask). The task ends when the trip reaches `metres`.
Task<double> tripMeter(Behavior<Wheels> driver, double metres) {
  return mkTask([driver, metres](const TaskState&) {
    Behavior<double> speed = lift([](const Wheels& w) { return std::abs(w.forward); }, driver);
    Behavior<double> trip = integral(speed);
    return std::pair{trip, predicate(trip > metres)};
  });
}

// ---- Step 3. Show the trip next to the robot ------------------------------------------------------
//
// A picture is a behavior like any other, so it can follow the trip meter's output and the robot.
Behavior<Picture> tripLabel(const Robot& r, const Behavior<double>& trip) {
  return lift(
      [](const Point2& at, double metres) {
        char label[32];
        std::snprintf(label, sizeof label, "trip %.1f m", metres);
        return paintAt(at + Point2{0.3, 0.3}, withColor(blue, text(label)));
      },
      place(r), trip);
}

// ---- Step 4. Put them together with withTask ----------------------------------------------------
//
// withTask takes two functions that make the two tasks:
//   * the first gets the second's output (wheels, one step late) and makes the watcher;
//   * the second gets the watcher's output (the trip) and the event "the watcher has ended", and
//     makes the driver. withExit runs runAround until that event, then the driver (and the run) ends.
// The result of the whole is the second task's result: here the watcher's Outcome, unused.
Task<Wheels> wanderTenMetres() {
  TaskState ts = co_await getTaskState();
  const Robot& r = ts.robot();
  co_await withTask([](Behavior<Wheels> wheelsOut) { return tripMeter(wheelsOut, kTrip); },
                    [r](Behavior<double> trip, auto watcherEnded) {
                      return withPicture(tripLabel(r, trip), withExit(watcherEnded, runAround()));
                    });
}

FROB_CONTROLLER(wanderTenMetres, .world = "empty", .seconds = 60,
                .summary = "withTask: a trip-meter task watches a wandering task and stops it after 10 m (paper 3.3)")
