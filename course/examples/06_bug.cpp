// Example 6: the BUG algorithm (paper section 4.1).
//
// BUG navigates to a goal around unknown obstacles: drive straight at the goal; when blocked, circle
// the obstacle once, remembering the point of its boundary closest to the goal; go back to that
// point and start again from there. The paper writes it from two primitive tasks, driveTo and
// followWall, glued by the task combinators of section 3: withB, atMin, timeLimit, withExit,
// taskCatch. This file keeps the paper's structure, function by function.
//
// Run it:  build/app/frob run course/examples/06_bug.cpp
// What to look for: in the obstacle field the robot circles a pillar, a U-shaped trap and a block,
// each time marking the closest point it found (green), and reaches the goal (red).

#include <frob/frob.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace frob;
using namespace frob::literals;

constexpr double kSpeed = 0.6;         // cruising speed, m/s: the robot's top speed
constexpr double kSetpoint = 25_cm;    // clearance kept between the robot's rim and the wall
constexpr double kThetaMax = 30_deg;   // steepest angle at which the robot closes in on the wall

// ---- Sensing ---------------------------------------------------------------------------------

// The nearest echo among the five sonars that look ahead (0 = front, 1-2 left, 14-15 right).
Behavior<double> frontArc(const Robot& r) {
  return min(sonar(r, 14), sonar(r, 15), sonar(r, 0), sonar(r, 1), sonar(r, 2));
}

// Where the wall on our left is: its distance (nearest echo) and its direction, radians from our
// heading (+90 degrees for a wall alongside). A sonar only hears a wall it faces nearly head-on, so
// the sonars whose echoes are nearly as near as the nearest one point around the wall's normal:
// their average direction, weighted by how near each echo is, is the direction of the wall.
struct Wall {
  double distance = 0.0;
  double direction = 0.0;
};
Behavior<Wall> wallOnLeft(const Robot& r) {
  std::vector<double> angles = r.spec().sonarAngles;
  const std::vector<int> leftSide = {15, 0, 1, 2, 3, 4, 5, 6, 7, 8};  // just right of ahead, round to behind
  return lift(
      [angles, leftSide](const std::vector<double>& range) {
        double nearest = 1e9;
        for (int i : leftSide) nearest = std::min(nearest, range[i]);
        double x = 0.0, y = 0.0;
        for (int i : leftSide) {
          double weight = std::max(0.0, nearest + 0.2 - range[i]);
          x += weight * std::cos(angles[i]);
          y += weight * std::sin(angles[i]);
        }
        return Wall{nearest, std::atan2(y, x)};
      },
      sonars(r));
}

// ---- The two primitive tasks: driveTo and followWall -----------------------------------------

// Turn on the spot to face `goal` (so that the obstacle we just left is not "in the way").
Task<Wheels> faceGoal(Point2 goal) {
  return mkTask([goal](const TaskState& ts) {
    const Robot& r = ts.robot();
    Behavior<double> error = wrapAngle(heading(goal - place(r)) - orientation(r));
    return std::pair{wheels(0, clamp(2.0 * error, -1.0, 1.0)), predicate(abs(error) < 5_deg)};
  });
}

// The paper's driveTo: head for `goal`; true when there, false when something blocks the way.
Task<Wheels, bool> driveTo(Point2 goal) {
  co_await faceGoal(goal);
  co_return co_await mkTask([goal](const TaskState& ts) {
    const Robot& r = ts.robot();
    Behavior<double> error = wrapAngle(heading(goal - place(r)) - orientation(r));
    Behavior<double> left = distance(place(r), goal);
    auto forward = min(kSpeed, left) * max(cos(error), 0.0);  // slow down at the end
    Event<bool> there = predicate(left < 15_cm).as(true);
    Event<bool> blocked = predicate(frontArc(r) < 40_cm).as(false);
    return std::pair{wheels(forward, clamp(2.0 * error, -1.0, 1.0)), there | blocked};
  });
}

// The vocabulary's driveToWithPicture: driveTo, with the goal drawn while it runs.
Task<Wheels, bool> driveToWithPicture(Point2 goal) {
  return withPicture(paintAt(goal, withColor(red, circle(15_cm))), driveTo(goal));
}

// Follow the wall on our left while there is one. This is the paper's rerror (example 2): the
// speed at which we want to move away from the wall, limited so that we never head into the wall
// more steeply than kThetaMax. We turn until we really move away from the wall at that speed.
Task<Wheels> alongWall() {
  return mkTask([](const TaskState& ts) {
    const Robot& r = ts.robot();
    Behavior<Wall> wall = wallOnLeft(r);
    Behavior<double> d = wall.map(&Wall::distance);
    Behavior<double> normal = wall.map(&Wall::direction);
    double m = kSpeed * std::sin(kThetaMax);
    auto rerror = clamp(kSetpoint - d, -m, m);  // wanted speed away from the wall
    auto away = -kSpeed * cos(normal);          // speed away from the wall now
    auto turn = clamp(-3.0 * (rerror - away), -1.0, 1.0);
    auto ahead = min(sonar(r, 15), sonar(r, 0), sonar(r, 1));
    auto forward = kSpeed * clamp((ahead - 20_cm) / 50_cm, 0.0, 1.0);
    return std::pair{wheels(forward, turn), predicate(d > 1_m)};
  });
}

// Round a corner: the wall on our left has vanished (we passed its end), so curve left, around
// the end. If no wall shows up within 8 seconds (most of a circle) the wall is really lost: an
// error (paper: "if for some reason the wall disappears from the sonars, this task raises an
// exception").
Task<Wheels> roundCorner() {
  return mkTaskE([](const TaskState& ts) {
    const Robot& r = ts.robot();
    Behavior<double> d = wallOnLeft(r).map(&Wall::distance);
    double radius = kSetpoint + r.spec().radius;  // the robot's centre keeps this far from the end
    return std::tuple{wheels(kSpeed, kSpeed / radius), predicate(d < 80_cm),
                      after(8_s).as(RoboErr("followWall: the wall is lost"))};
  });
}

// The paper's followWall: travel around the obstacle, forever, keeping it on our left.
Task<Wheels> followWall() {
  for (;;) {
    co_await alongWall();
    co_await roundCorner();
  }
}

// ---- BUG, as in the paper ---------------------------------------------------------------------

// A marker for a point, drawn while a task runs.
Behavior<Picture> marker(const Behavior<Point2>& p) {
  return paintAt(p, withColor(green, disc(12_cm)));
}

// circleOnce: follow the wall for 5 s to get away from where we started, then until we are back
// (atPlace: within 30 cm).
Task<Wheels> circleOnce() {
  TaskState ts = co_await getTaskState();
  Point2 initp = ts.initialPlace();
  (void)co_await timeLimit(followWall(), 5_s);
  co_await withExit(atPlace(ts.robot(), initp), followWall());
}

// circleOnceP: circleOnce, and the place where we were closest to the goal. withB runs a behavior
// beside a task and gives its final value (with the task's result, if it has one); atMin(a, b)
// is the value of b when a was smallest. We also draw that point as it changes.
Task<Wheels, Point2> circleOnceP(Point2 g) {
  TaskState ts = co_await getTaskState();
  const Robot& r = ts.robot();
  Behavior<Point2> closest = atMin(distance(place(r), g), place(r));
  auto closestP = [closest](const TaskState&) { return closest; };
  co_return co_await withB(closestP, withPicture(marker(closest), circleOnce()));
}

// circleTo: follow the wall until we are at `p`.
Task<Wheels> circleTo(Point2 p) {
  TaskState ts = co_await getTaskState();
  co_await withPicture(marker(p), withExit(atPlace(ts.robot(), p), followWall()));
}

Task<Wheels> bug(Point2 g);

// goAround: circle the obstacle, go back to its closest point, and restart BUG from there.
Task<Wheels> goAround(Point2 g) {
  Point2 closestPoint = co_await circleOnceP(g);
  co_await circleTo(closestPoint);
  co_await become(bug(g));  // the paper's tail call `bug g`
}

// One attempt: drive to the goal; done when there, otherwise go around what blocked us.
Task<Wheels> bugAttempt(Point2 g) {
  bool finished = co_await driveToWithPicture(g);
  if (finished) co_return;
  co_await become(goAround(g));
}

// The paper's bug: taskCatch restarts BUG when a task fails (the wall was lost).
Task<Wheels> bug(Point2 g) {
  return taskCatch(bugAttempt(g), [g](const RoboErr&) { return bug(g); });
}

// The controller: BUG to the obstacle world's goal at (13, 13), the goal drawn all along.
Task<Wheels> bugToGoal() {
  Point2 goal{13, 13};
  co_await withPicture(paintAt(goal, withColor(red, disc(10_cm) + text("goal"))), bug(goal));
}

// BUG goes all the way round each obstacle, so this takes a while: 127 to 139 s of simulated time.
FROB_CONTROLLER(bugToGoal, .world = "obstacles", .seconds = 160,
                .summary = "the BUG algorithm: around a pillar, a U-shaped trap and a block to the goal (paper 4.1)")
