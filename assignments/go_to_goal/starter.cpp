// Go to goal: your controller (paper section 3.2). Read handout.md first.
//
// This file compiles and runs as it is: the robot drives to the first waypoint and stops there,
// which earns no points yet. Your job, step by step:
//   1. visit all four waypoints, in the handout's order (a loop over kWaypoints);
//   2. driveTo returns false when something blocks the way: go round it, then drive on (see
//      example 6's followWall; BUG itself, which circles every obstacle once, is too slow here);
//   3. draw the current goal while driving to it, with withPicture (for your video: the grader
//      cannot see pictures, your instructor will);
//   4. be back within the time limit: all four waypoints within 75 s.
//
// Run it:        build/app/frob run my_go_to_goal.cpp --video go.mp4 --plot go.png
// Check it:      build/app/frob grade go_to_goal my_go_to_goal.cpp --visible-only --report r.html

#include <frob/frob.hpp>

#include <vector>

using namespace frob;
using namespace frob::literals;

// The waypoints from the handout, in the world frame (metres), in the order to visit them. The
// robot starts at (1.5, 1.5) facing east, and place(r) reports its position in this same frame.
const std::vector<Point2> kWaypoints = {{3.0, 2.5}, {3.5, 7.5}, {9.0, 7.0}, {8.5, 2.5}};

constexpr double kSpeed = 0.4;  // m/s; the robot's top speed is 0.6

// How far we must still turn to face `goal`, radians, left positive (as in example 4).
Behavior<double> turnNeeded(const Robot& r, Point2 goal) { return wrapAngle(heading(goal - place(r)) - orientation(r)); }

// Example 4's driveTo: true when within 10 cm of `goal`, false when something is close ahead.
Task<Wheels, bool> driveTo(Point2 goal) {
  return mkTask([goal](const TaskState& ts) {
    const Robot& r = ts.robot();
    Behavior<double> angle = turnNeeded(r, goal);
    Behavior<double> left = distance(place(r), goal);
    auto forward = min(kSpeed, left) * max(cos(angle), 0.0);
    auto turn = clamp(2.0 * angle, -1.0, 1.0);
    Event<bool> there = predicate(left < 10_cm).as(true);
    Event<bool> blocked = predicate(frontSonar(r) < 30_cm).as(false);
    return std::pair{wheels(forward, turn), there | blocked};
  });
}

// TODO: every waypoint in turn, round whatever is in the way, each drawn while it is the goal.
Task<Wheels> visitWaypoints() {
  bool there = co_await driveTo(kWaypoints[0]);
  (void)there;
}

FROB_CONTROLLER(visitWaypoints, .world = "assignments/go_to_goal/worlds/lounge.toml", .seconds = 90,
                .summary = "go to goal: the starter, which drives to the first waypoint only")
