// A typical wrong submission for parallel: course example 7, copied, with the patrol as its driver.
//
// Example 7's trip meter and withTask, unchanged, with the budget (20 m) as its trip and the
// handout's patrol instead of runAround. It patrols and stops after 20 m, but it watches neither
// the key nor the bumpers, and its task returns no reason.

#include <frob/frob.hpp>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

using namespace frob;
using namespace frob::literals;

constexpr double kTrip = 20.0;  // metres to drive: the handout's budget

// ---- Step 1. The driver: the handout's patrol instead of example 1's runAround -----------------

const std::vector<Point2> kRoute = {{1.5, 1.5}, {6.5, 1.5}, {6.5, 4.5}, {1.5, 4.5}};

Behavior<double> turnNeeded(const Robot& r, Point2 goal) { return wrapAngle(heading(goal - place(r)) - orientation(r)); }

Task<Wheels> driveTo(Point2 goal) {
  return mkTask([goal](const TaskState& ts) {
    const Robot& r = ts.robot();
    Behavior<double> angle = turnNeeded(r, goal);
    Behavior<double> left = distance(place(r), goal);
    auto forward = min(0.6, left) * max(cos(angle), 0.0);
    return std::pair{wheels(forward, clamp(2.0 * angle, -1.0, 1.0)), predicate(left < 10_cm)};
  });
}

Task<Wheels> runAround() {  // the patrol, under example 7's name
  for (;;) {
    for (const Point2& p : kRoute) co_await driveTo(p);
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

FROB_CONTROLLER(wanderTenMetres, .world = "assignments/parallel/worlds/warehouse.toml", .seconds = 60,
                .summary = "withTask: a trip-meter task watches a wandering task and stops it after 10 m (paper 3.3)")
