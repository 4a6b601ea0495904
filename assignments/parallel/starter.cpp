// Parallel: your controller (paper sections 3.3 and 4.2). Read handout.md first.
//
// This file compiles and runs as it is: the robot patrols p1, p2, p3, p4 and round again, for
// ever. It never stops, which earns the points of the patrol check only. Your job, step by step:
//   1. write the watcher: a task that ends, with the reason as its result, on the first of
//        - the operator's key "s" (other keys must not stop the patrol),
//        - a bumper contact,
//        - the 20 m budget used up (its output can be the trip so far, as in example 7);
//   2. run it beside the patrol with withTask, and end the patrol when the watcher ends (withExit);
//   3. make guardedPatrol return the watcher's reason: "key", "bumped" or "budget";
//   4. for your video: show the trip next to the robot, and ring the waypoint it heads for.
//
// Run it:        build/app/frob run my_parallel.cpp --video patrol.mp4
//                build/app/frob run my_parallel.cpp --world assignments/parallel/worlds/warehouse_key.toml
// Check it:      build/app/frob grade parallel my_parallel.cpp --visible-only --report r.html

#include <frob/frob.hpp>

#include <string>
#include <vector>

using namespace frob;
using namespace frob::literals;

// The patrol's waypoints from the handout, in the world frame (metres). The robot starts at
// (1.0, 1.0) facing east, and place(r) reports its position in this same frame.
const std::vector<Point2> kRoute = {{1.5, 1.5}, {6.5, 1.5}, {6.5, 4.5}, {1.5, 4.5}};

constexpr double kSpeed = 0.6;    // m/s, the robot's top speed
constexpr double kBudget = 20.0;  // metres the robot may drive in all
constexpr char kStopKey = 's';    // the operator's stop key

// ---- The patrol (given) ---------------------------------------------------------------------

// How far we must still turn to face `goal`, radians, left positive.
Behavior<double> turnNeeded(const Robot& r, Point2 goal) { return wrapAngle(heading(goal - place(r)) - orientation(r)); }

// Turn on the spot to face the next waypoint.
Task<Wheels> faceGoal(Point2 goal) {
  return mkTask([goal](const TaskState& ts) {
    Behavior<double> error = turnNeeded(ts.robot(), goal);
    return std::pair{wheels(0, clamp(2.0 * error, -1.0, 1.0)), predicate(abs(error) < 3_deg)};
  });
}

// A blind driveTo: no sonars, no "blocked" result (the bumpers are the robot's safety). It ends
// within 10 cm of the goal.
Task<Wheels> driveTo(Point2 goal) {
  co_await faceGoal(goal);
  co_await mkTask([goal](const TaskState& ts) {
    const Robot& r = ts.robot();
    Behavior<double> error = turnNeeded(r, goal);
    Behavior<double> left = distance(place(r), goal);
    auto forward = min(kSpeed, left) * max(cos(error), 0.0);
    return std::pair{wheels(forward, clamp(2.0 * error, -1.0, 1.0)), predicate(left < 10_cm)};
  });
}

// p1, p2, p3, p4, p1, ... for ever.
Task<Wheels> patrol() {
  for (;;) {
    for (const Point2& p : kRoute) co_await driveTo(p);
  }
}

// ---- Yours ----------------------------------------------------------------------------------

// TODO: the watcher, a Task<double, std::string> (or any output you like) that ends with the reason.

// TODO: the patrol beside the watcher (withTask), ended by it (withExit); return its reason.
Task<Wheels, std::string> guardedPatrol() {
  co_await patrol();  // never ends: the lines below are never reached
  co_return "TODO";
}

FROB_CONTROLLER(guardedPatrol, .world = "assignments/parallel/worlds/warehouse.toml", .seconds = 60,
                .summary = "parallel: the starter, a patrol that never stops")
