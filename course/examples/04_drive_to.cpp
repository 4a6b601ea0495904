// Example 4: driveTo, and withPicture to see what it is doing (paper sections 3.2 and 4.1).
//
// driveTo is one of the two building blocks of the BUG algorithm (example 6): head for a point and
// return true when there, false if something blocks the way. withPicture is a task transformer: it
// adds a drawing to a task, shown while the task runs. The paper's example:
//
//     driveToWithPicture goal = driveTo goal `withPicture` paintAt goal (withColor red circle)
//
// Run it:  build/app/frob run course/examples/04_drive_to.cpp
// What to look for: a red circle marks each goal while the robot drives to it; the robot visits two
// corners of the room and stops on the second goal.

#include <frob/frob.hpp>

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
    Event<bool> there = predicate(left < 10_cm).as(true);
    Event<bool> blocked = predicate(frontSonar(r) < 30_cm).as(false);
    return std::pair{wheels(forward, turn), there | blocked};
  });
}

// Step 3. The paper's driveToWithPicture: the same task, with the goal drawn while it runs.
// paintAt moves a picture (a circle around the origin) to the goal; withColor colours it.
Task<Wheels, bool> driveToWithPicture(Point2 goal) {
  return withPicture(paintAt(goal, withColor(red, circle(10_cm))), driveTo(goal));
}

// Step 4. Visit two points. co_await gives the task's result: false would mean "blocked", in which
// case we give up (co_return ends this task, and the run).
Task<Wheels> visitTwoPoints() {
  if (!co_await driveToWithPicture(Point2{5.0, 3.0})) co_return;
  (void)co_await driveToWithPicture(Point2{1.0, 1.0});
}

FROB_CONTROLLER(visitTwoPoints, .world = "empty", .seconds = 60,
                .summary = "driveTo with withPicture: drive to two points, each drawn while it is the goal (paper 3.2)")
