// A typical wrong submission for parallel: the watcher forgets the bumpers.
//
// The reference solution with one change: the watcher ends on the key or on the budget, but a
// bumper contact does not stop the patrol. The robot pushes on past the box in the aisle.

#include <frob/frob.hpp>

#include <cstdio>
#include <string>
#include <vector>

using namespace frob;
using namespace frob::literals;

// The patrol's waypoints from the handout, in the world frame (odometry starts at the robot's true
// start pose and has no error in this assignment's worlds, so place(r) is in the same frame).
const std::vector<Point2> kRoute = {{1.5, 1.5}, {6.5, 1.5}, {6.5, 4.5}, {1.5, 4.5}};

constexpr double kSpeed = 0.6;     // m/s, the robot's top speed
constexpr double kBudget = 20.0;   // metres the robot may drive in all
constexpr char kStopKey = 's';     // the operator's stop key

// ---- Step 1. The patrol: driveTo each waypoint in turn, for ever ----------------------------

// How far we must still turn to face `goal`, radians, left positive.
Behavior<double> turnNeeded(const Robot& r, Point2 goal) { return wrapAngle(heading(goal - place(r)) - orientation(r)); }

// Turn on the spot to face the next waypoint, so that each leg is a straight line.
Task<Wheels> faceGoal(Point2 goal) {
  return mkTask([goal](const TaskState& ts) {
    Behavior<double> error = turnNeeded(ts.robot(), goal);
    return std::pair{wheels(0, clamp(2.0 * error, -1.0, 1.0)), predicate(abs(error) < 3_deg)};
  });
}

// A blind driveTo: no sonars, no "blocked" result. It ends within 10 cm of the goal.
Task<Wheels> driveTo(Point2 goal) {
  co_await faceGoal(goal);
  co_await mkTask([goal](const TaskState& ts) {
    const Robot& r = ts.robot();
    Behavior<double> error = turnNeeded(r, goal);
    Behavior<double> left = distance(place(r), goal);
    auto forward = min(kSpeed, left) * max(cos(error), 0.0);  // slow down in the last metre
    return std::pair{wheels(forward, clamp(2.0 * error, -1.0, 1.0)), predicate(left < 10_cm)};
  });
}

// The patrol never ends by itself: p1, p2, p3, p4, p1, ... The waypoint it heads for is ringed in
// red while it drives there (withPicture). A loop of tasks that repeats for ever is Lyons'
// synchronous loop P <> Q (syncLoop); a plain loop says the same here.
Task<Wheels> patrol() {
  for (;;) {
    for (const Point2& p : kRoute) co_await withPicture(paintAt(p, withColor(red, circle(20_cm))), driveTo(p));
  }
}

// ---- Step 2. The watcher: why and when the patrol must end -----------------------------------
//
// Its output is a number, the trip: the metres driven so far, the integral of the speed the
// wheels measure. It ends with the reason, the first of three events (`|` takes the first; on the
// same instant the left one wins):
//   * keyboard(r) occurs at every key press with the key; filter keeps the stop key only;
//   * bumper(r) occurs when a bumper touches something;
//   * predicate(trip >= budget) occurs when the budget is used up.
// The watcher gets a fresh copy of the task state, so its trip starts at 0 when the patrol starts.
Task<double, std::string> watcher() {
  return mkTask([](const TaskState& ts) {
    const Robot& r = ts.robot();
    Behavior<double> trip = integral(abs(velocity(r)));
    Event<std::string> key = keyboard(r).filter([](char c) { return c == kStopKey; }).map([] { return std::string("key"); });
    Event<std::string> bumped = bumper(r).map([] { return std::string("bumped"); });
    Event<std::string> spent = predicate(trip >= kBudget).map([] { return std::string("budget"); });
    (void)bumped;  // the bumpers are not watched
    return std::pair{trip, key | spent};
  });
}

// The trip, written above the robot (as in example 7).
Behavior<Picture> tripLabel(const Robot& r, const Behavior<double>& trip) {
  return lift(
      [](const Point2& at, double metres) {
        char label[48];
        std::snprintf(label, sizeof label, "trip %.1f of %.0f m", metres, kBudget);
        return paintAt(at + Point2{-0.8, 0.35}, withColor(blue, text(label)));
      },
      place(r), trip);
}

// ---- Step 3. Both together with withTask -------------------------------------------------------
//
// withTask(first, second):
//   * first gets the second's output (the patrol's wheels, unused here) and makes the watcher;
//   * second gets the watcher's output (the trip) and the event "the watcher has ended", carrying
//     its Outcome (the reason, or the error that ended it). withExit runs the patrol until that
//     event and returns the event's value.
// The whole returns the second's result: the watcher's Outcome. We return its reason, which ends
// the controller's task: the robot stops (a finished task drives zero wheels).
Task<Wheels, std::string> guardedPatrol() {
  TaskState ts = co_await getTaskState();
  const Robot& r = ts.robot();
  Outcome<std::string> why = co_await withTask([](Behavior<Wheels>) { return watcher(); },
                                               [r](Behavior<double> trip, Event<Outcome<std::string>> watcherEnded) {
                                                 return withPicture(tripLabel(r, trip), withExit(watcherEnded, patrol()));
                                               });
  co_return why.value.value_or("the watcher failed");  // ours raises no error: it always has a reason
}

FROB_CONTROLLER(guardedPatrol, .world = "assignments/parallel/worlds/warehouse.toml", .seconds = 60,
                .summary = "parallel: a patrol with a watcher task that stops it on a key, a bump or its distance budget (paper 3.3, 4.2)")
