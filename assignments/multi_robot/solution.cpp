// Assignment "multi_robot": cross the arena without touching anyone. The reference solution.
//
// Several robots share a 10 x 10 m arena, and every one of them runs this same file. Each must
// reach the point opposite its start through the centre of the arena (5, 5), so all their ways
// cross in the middle. The paper left multi-robot systems as future work (section 5); in Frob
// each robot simply runs its own copy of the task, and sees the others only through its sonars.
//
// The plan: work out the goal once, from where the robot started (step 1). Drive at it, but stop
// driving at it whenever someone is close ahead (step 3) and give way by veering right (step 4),
// like traffic at a roundabout. Because every robot keeps right, two robots that meet pass each
// other left side to left side, and a crowd in the middle turns round it the same way.
//
// Run it:   build/app/frob run assignments/multi_robot/solution.cpp --video x.mp4   (in worlds/corners.toml)
//           build/app/frob run assignments/multi_robot/solution.cpp --world assignments/multi_robot/worlds/swap.toml
// Grade it: build/app/frob grade multi_robot assignments/multi_robot/solution.cpp --visible-only

#include <frob/frob.hpp>

#include <utility>

using namespace frob;
using namespace frob::literals;

constexpr double kSpeed = 0.5;       // m/s, a little under the top speed, so that turns stay tight
constexpr double kLookout = 1.0;     // m: anyone nearer than this ahead makes us give way

// ---- Step 1. The goal --------------------------------------------------------------------------
//
// A controller never sees the world file, so the goal must come from what the robot knows: where
// it started. Odometry reports world coordinates, starting at the true start pose, without drift
// here. The point opposite `start` through the centre c is c + (c - start).
const Point2 kCentre{5.0, 5.0};
Point2 oppositeOf(Point2 start) { return kCentre + (kCentre - start); }

// ---- Step 2. Sensing ---------------------------------------------------------------------------
//
// The nearest echo among the five sonars that look ahead (0 = front, 1-2 left, 14-15 right).
// Other robots are round, so some ray always meets them head-on: they echo from every side.
Behavior<double> frontArc(const Robot& r) {
  return min(sonar(r, 14), sonar(r, 15), sonar(r, 0), sonar(r, 1), sonar(r, 2));
}

// ---- Step 3. driveTo, giving up when someone is in the way --------------------------------------

// Turn on the spot to face `goal`.
Task<Wheels> faceGoal(Point2 goal) {
  return mkTask([goal](const TaskState& ts) {
    const Robot& r = ts.robot();
    Behavior<double> error = wrapAngle(heading(goal - place(r)) - orientation(r));
    return std::pair{wheels(0, clamp(2.0 * error, -1.0, 1.0)), predicate(abs(error) < 10_deg)};
  });
}

// Head for `goal`: true when there; false when someone is less than kLookout ahead and nearer
// than the goal (someone standing beyond our goal is not in our way).
Task<Wheels, bool> driveTo(Point2 goal) {
  co_await faceGoal(goal);
  co_return co_await mkTask([goal](const TaskState& ts) {
    const Robot& r = ts.robot();
    Behavior<double> error = wrapAngle(heading(goal - place(r)) - orientation(r));
    Behavior<double> left = distance(place(r), goal);
    Behavior<double> ahead = frontArc(r);
    auto forward = min(kSpeed, left) * max(cos(error), 0.0);  // slow down at the end
    Event<bool> there = predicate(left < 10_cm).map([] { return true; });
    Event<bool> someone = predicate(ahead < kLookout && ahead < left).map([] { return false; });
    return std::pair{wheels(forward, clamp(2.0 * error, -1.0, 1.0)), there | someone};
  });
}

// ---- Step 4. Giving way ------------------------------------------------------------------------

// Keep right: turn 45 degrees to the right on the spot, then drive on for 2 s, slowing down for
// anyone ahead and turning further right while someone is close.
Task<Wheels> keepRight() {
  // 1 rad/s for 45_deg (0.79) seconds: about 45 degrees.
  co_await mkTask([](const TaskState&) { return std::pair{wheels(0.0, -1.0), after(45_deg)}; });
  co_await mkTask([](const TaskState& ts) {
    const Robot& r = ts.robot();
    Behavior<double> ahead = frontArc(r);
    auto forward = kSpeed * clamp((ahead - 30_cm) / 50_cm, 0.0, 1.0);
    auto turn = lift([](double a) { return a < 0.8 ? -0.8 : 0.0; }, ahead);
    return std::pair{wheels(forward, turn), after(2_s)};
  });
}

// ---- Step 5. The controller --------------------------------------------------------------------

// Drive at `goal`, giving way whenever someone is in the way, until there.
Task<Wheels> crossTo(Point2 goal) {
  while (!co_await driveTo(goal)) co_await keepRight();
}

// Work out the goal from where this task began (the robot's start), then cross to it, with the
// goal drawn. Ending the task stops the robot.
Task<Wheels> crossArena() {
  TaskState ts = co_await getTaskState();
  Point2 goal = oppositeOf(ts.initialPlace());
  co_await withPicture(paintAt(goal, withColor(red, circle(15_cm))), crossTo(goal));
}

FROB_CONTROLLER(crossArena, .world = "assignments/multi_robot/worlds/corners.toml", .seconds = 35,
                .summary = "every robot crosses to the point opposite its start, keeping right of the others")
