// Assignment "multi_robot": cross the arena without touching anyone. Your starting point (read
// handout.md first).
//
// Every robot of the world runs this same file. As given, each robot drives straight to the
// centre of the arena and stops there: run it and watch them crash into each other. Your part:
//   1. work out this robot's goal, the point opposite its start through the centre (5, 5),
//      from where the robot started (the task state's initialPlace());
//   2. make driveTo give up when someone is close ahead (an event), and
//   3. give way (a task), then try again, until the robot is at its goal.
//
// Run it:   build/app/frob run assignments/multi_robot/starter.cpp --video x.mp4   (in worlds/corners.toml)
// Check it: build/app/frob grade multi_robot my.cpp --visible-only --report r.html

#include <frob/frob.hpp>

#include <utility>

using namespace frob;
using namespace frob::literals;

constexpr double kSpeed = 0.5;  // m/s

// The centre of the arena, in world coordinates (odometry reports world coordinates too).
const Point2 kCentre{5.0, 5.0};

// The nearest echo among the five sonars that look ahead (0 = front, 1-2 left, 14-15 right).
// Other robots echo too.
Behavior<double> frontArc(const Robot& r) {
  return min(sonar(r, 14), sonar(r, 15), sonar(r, 0), sonar(r, 1), sonar(r, 2));
}

// Turn on the spot to face `goal`.
Task<Wheels> faceGoal(Point2 goal) {
  return mkTask([goal](const TaskState& ts) {
    const Robot& r = ts.robot();
    Behavior<double> error = wrapAngle(heading(goal - place(r)) - orientation(r));
    return std::pair{wheels(0, clamp(2.0 * error, -1.0, 1.0)), predicate(abs(error) < 10_deg)};
  });
}

// Head for `goal` until there (true). It never looks out for anyone: that is for you to add.
Task<Wheels, bool> driveTo(Point2 goal) {
  co_await faceGoal(goal);
  co_return co_await mkTask([goal](const TaskState& ts) {
    const Robot& r = ts.robot();
    Behavior<double> error = wrapAngle(heading(goal - place(r)) - orientation(r));
    Behavior<double> left = distance(place(r), goal);
    auto forward = min(kSpeed, left) * max(cos(error), 0.0);  // slow down at the end
    Event<bool> there = predicate(left < 10_cm).as(true);
    return std::pair{wheels(forward, clamp(2.0 * error, -1.0, 1.0)), there};
  });
}

// The controller. For now every robot drives to the centre: replace kCentre by the robot's goal.
Task<Wheels> crossArena() {
  TaskState ts = co_await getTaskState();
  Point2 start = ts.initialPlace();  // where this robot started, in world coordinates
  (void)start;
  Point2 goal = kCentre;  // TODO: the point opposite `start` through the centre
  co_await withPicture(paintAt(goal, withColor(red, circle(15_cm))), driveTo(goal));
}

FROB_CONTROLLER(crossArena, .world = "assignments/multi_robot/worlds/corners.toml", .seconds = 35,
                .summary = "the multi_robot assignment's starter: every robot drives to the centre")
