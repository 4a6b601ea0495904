// A typical wrong submission for go_to_goal: course example 4, copied, with the handout's waypoints.
//
// Example 4's driveTo and driveToWithPicture, unchanged, called for each waypoint in turn. It
// reaches wp1; then the sofa blocks the way to wp2, driveTo returns false, and, as in example 4, the
// controller gives up: it has no way round an obstacle.

#include <frob/frob.hpp>

#include <vector>

using namespace frob;
using namespace frob::literals;

constexpr double kSpeed = 0.4;  // m/s

// Step 1. Behaviors describing where the goal is, seen from the robot.
//
// place(r) is where the robot believes it is (odometry), orientation(r) its heading. `goal - place`
// is the vector to the goal (computed at every instant), heading() its direction, and wrapAngle
// brings the difference into (-180, 180] degrees: how far we must still turn, left positive.
Behavior<double> turnNeeded(const Robot& r, Point2 goal) {
  return wrapAngle(heading(goal - place(r)) - orientation(r));
}

// Step 2. driveTo: steer towards the goal, slow down when facing away or near the end.
//
// The wheels are a behavior built from behaviors: turn rate proportional to the angle still to
// turn (limited to the robot's 1 rad/s); forward speed reduced by cos(angle), so that the robot
// turns on the spot when the goal is behind it. The task ends with one of two events, each
// carrying the result: `there` gives true, `blocked` gives false. `|` takes whichever comes first.
Task<Wheels, bool> driveTo(Point2 goal) {
  return mkTask([goal](const TaskState& ts) {
    const Robot& r = ts.robot();
    Behavior<double> angle = turnNeeded(r, goal);
    Behavior<double> left = distance(place(r), goal);
    auto forward = min(kSpeed, left) * max(cos(angle), 0.0);
    auto turn = clamp(2.0 * angle, -1.0, 1.0);
    Event<bool> there = predicate(left < 10_cm).map([] { return true; });
    Event<bool> blocked = predicate(frontSonar(r) < 30_cm).map([] { return false; });
    return std::pair{wheels(forward, turn), there | blocked};
  });
}

// Step 3. The paper's driveToWithPicture: the same task, with the goal drawn while it runs.
// paintAt moves a picture (a circle around the origin) to the goal; withColor colours it.
Task<Wheels, bool> driveToWithPicture(Point2 goal) {
  return withPicture(paintAt(goal, withColor(red, circle(10_cm))), driveTo(goal));
}

// Step 4. Visit the handout's four waypoints. co_await gives the task's result: false means
// "blocked", in which case we give up, as example 4 does.
const std::vector<Point2> kWaypoints = {{3.0, 2.5}, {3.5, 7.5}, {9.0, 7.0}, {8.5, 2.5}};

Task<Wheels> visitWaypoints() {
  for (const Point2& p : kWaypoints) {
    if (!co_await driveToWithPicture(p)) co_return;
  }
}

FROB_CONTROLLER(visitWaypoints, .world = "assignments/go_to_goal/worlds/lounge.toml", .seconds = 90)
