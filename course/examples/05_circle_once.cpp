// Example 5: circleOnce and circleOnceP, with withB and atMin (paper sections 2.3, 3.2 and 4.1).
//
// The heart of the BUG algorithm (example 6): go once round an obstacle and find the point of the
// way round that is closest to a goal. The paper's code:
//
//     circleOnceP g = do (_, p) <- withB closestP (circleOnce g)
//                        return p
//       where closestP ts = let r = taskRobot ts in (distance (place r) g) `atMin` (place r)
//
// atMin(a, b) is a behavior: the value b had when a was smallest so far. withB runs such a
// behavior beside a task and hands back its value when the task ends. So circleOnceP needs no
// variables, no loop and no bookkeeping: the "closest point so far" is one behavior.
//
// Here the robot drives from (1.5, 1.5) towards (13, 13) in the obstacle field, is blocked by a
// round pillar, circles it once, and goes back to the point of its circle closest to the goal.
//
// Run it:  build/app/frob run course/examples/05_circle_once.cpp
// What to look for: after one full circle a green dot marks the point closest to the goal (red);
// the robot carries on round to it and stops there.

#include <frob/frob.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace frob;
using namespace frob::literals;

constexpr double kSpeed = 0.6;        // m/s, the robot's top speed
constexpr double kSetpoint = 25_cm;   // clearance kept between the robot's rim and the wall
constexpr double kThetaMax = 30_deg;  // steepest angle at which the robot closes in on the wall

// ---- Step 1. Getting to the obstacle: drive at the goal until blocked (as in example 4) --------

Task<Wheels, bool> driveTo(Point2 goal) {
  return mkTask([goal](const TaskState& ts) {
    const Robot& r = ts.robot();
    Behavior<double> error = wrapAngle(heading(goal - place(r)) - orientation(r));
    Behavior<double> left = distance(place(r), goal);
    auto forward = min(kSpeed, left) * max(cos(error), 0.0);
    auto ahead = min(sonar(r, 15), sonar(r, 0), sonar(r, 1));
    Event<bool> there = predicate(left < 15_cm).as(true);
    Event<bool> blocked = predicate(ahead < 40_cm).as(false);
    return std::pair{wheels(forward, clamp(2.0 * error, -1.0, 1.0)), there | blocked};
  });
}

// ---- Step 2. followWall: round the obstacle, keeping it on our left ---------------------------
// The paper's rerror (example 2) turned into a follower for walls of any shape. The details are not
// this example's point: followWall runs forever, and raises an error if it loses the wall.

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

// ---- Step 3. The paper's circleOnce and circleOnceP ------------------------------------------

// circleOnce: the task state tells where this task began (initialPlace). First follow the wall for
// 5 s, to get away from there (timeLimit cuts a task short); then follow it until we are back
// (withExit ends a task when an event happens; atPlace occurs within 30 cm of a point).
Task<Wheels> circleOnce() {
  TaskState ts = co_await getTaskState();
  Point2 initp = ts.initialPlace();
  (void)co_await timeLimit(followWall(), 5_s);
  co_await withExit(atPlace(ts.robot(), initp), followWall());
}

// circleOnceP: circleOnce, and where we were closest to `g`. withB's function makes the behavior
// from the task state when the task starts, so atMin starts watching there. circleOnce has no
// result, so withB gives the closest point alone (for a task with a result, a pair of both).
Task<Wheels, Point2> circleOnceP(Point2 g) {
  auto closestP = [g](const TaskState& ts) {
    const Robot& r = ts.robot();
    return atMin(distance(place(r), g), place(r));
  };
  co_return co_await withB(closestP, circleOnce());
}

// ---- Step 4. The controller: to the obstacle, once round it, back to the closest point ---------

// circleTo: follow the wall until we are at `p` (drawn as a green dot meanwhile).
Task<Wheels> circleTo(Point2 p) {
  TaskState ts = co_await getTaskState();
  co_await withPicture(paintAt(p, withColor(green, disc(12_cm))), withExit(atPlace(ts.robot(), p), followWall()));
}

Task<Wheels> roundThePillar(Point2 goal) {
  if (co_await driveTo(goal)) co_return;  // nothing in the way: nothing to circle
  Point2 closest = co_await circleOnceP(goal);
  co_await circleTo(closest);
}

// The goal, drawn in red for the whole run.
Task<Wheels> circleThePillar() {
  Point2 goal{13, 13};
  co_await withPicture(paintAt(goal, withColor(red, disc(10_cm))), roundThePillar(goal));
}

FROB_CONTROLLER(circleThePillar, .world = "obstacles", .seconds = 40,
                .summary = "circleOnceP with withB and atMin: once round a pillar, back to the point nearest the goal (paper 4.1)")
