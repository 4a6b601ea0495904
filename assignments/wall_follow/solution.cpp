// Wall follow: the reference solution (paper section 2.3, rerror).
//
// Keep the wall on the RIGHT, 40 cm from the robot's rim, and go on round every corner for ever:
//   * along a wall, steer with the paper's rerror: the speed at which we want to move away from
//     the wall, limited so that we never head into it (or away from it) more steeply than
//     kThetaMax, compared with the speed at which we do move away from it;
//   * at a concave corner (a wall ahead), turn left on the spot until the new wall is on our right;
//   * at a convex corner (the wall on our right ends), curve right round its end until the next
//     wall is beside us again.
// Each of the three is a task; the loop of step 5 puts them together, as the paper's runAround
// puts goAhead and turnRight together.
//
// Run it:  build/app/frob run assignments/wall_follow/solution.cpp --frames /tmp/frames --fps 1

#include <frob/frob.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace frob;
using namespace frob::literals;

constexpr double kSpeed = 0.4;         // cruising speed, m/s
constexpr double kSetpoint = 40_cm;    // wanted distance from the robot's rim to the wall
constexpr double kThetaMax = 25_deg;   // steepest angle at which we close in on (or leave) the wall

// Step 1. Sensing.
//
// Where is the wall on our right? A sonar hears a wall only when it faces it nearly head-on, so
// the sonars whose echoes are nearly as near as the nearest one point round the wall's normal:
// their average direction, weighted by how near each echo is, is the direction of the wall (-90
// degrees when it runs alongside on the right). This is example 2's wallDirection, on the right.
struct Wall {
  double distance = 0.0;   // the nearest echo, m
  double direction = 0.0;  // radians from our heading
};
Behavior<Wall> wallOnRight(const Robot& r) {
  std::vector<double> angles = r.spec().sonarAngles;  // sonar i points angles[i] from the heading
  const std::vector<int> rightSide = {1, 0, 15, 14, 13, 12, 11, 10, 9, 8};  // ahead-left round to behind
  return lift(
      [angles, rightSide](const std::vector<double>& range) {
        double nearest = 1e9;
        for (int i : rightSide) nearest = std::min(nearest, range[i]);
        double x = 0.0, y = 0.0;
        for (int i : rightSide) {
          double weight = std::max(0.0, nearest + 0.2 - range[i]);
          x += weight * std::cos(angles[i]);
          y += weight * std::sin(angles[i]);
        }
        return Wall{nearest, std::atan2(y, x)};
      },
      sonars(r));
}

// The nearest echo ahead (sonar 0, and 15 and 1 at 22.5 degrees right and left of it). Sonar 12
// looks straight right, sonar 13 22.5 degrees ahead of it, sonar 11 22.5 degrees behind it.
Behavior<double> ahead(const Robot& r) { return min(sonar(r, 15), sonar(r, 0), sonar(r, 1)); }

// Step 2. Along the wall: the paper's rerror, for a wall on the right.
//
//     rerror r = limit (velocity r * sin thetamax) (setpoint - rightSonar r)
//
// is the speed at which we want to move away from the wall (positive when too close). Driving at
// speed v with the wall in direction d, we do move away from it at -v * cos(d). We turn left (a
// positive turn rate) in proportion to how much slower than rerror we move away: a feedback loop.
// We slow down when a wall comes near ahead, to turn at the corner where the setpoint says.
Behavior<Wheels> alongWall(const Robot& r) {
  Behavior<Wall> wall = wallOnRight(r);
  Behavior<double> d = wall.map(&Wall::distance);
  Behavior<double> normal = wall.map(&Wall::direction);
  double m = kSpeed * std::sin(kThetaMax);
  auto rerror = clamp(kSetpoint - d, -m, m);  // wanted speed away from the wall
  auto away = -kSpeed * cos(normal);          // speed away from the wall now
  auto turn = clamp(4.0 * (rerror - away), -1.0, 1.0);
  auto forward = kSpeed * clamp((ahead(r) - kSetpoint) / 40_cm, 0.3, 1.0);
  return wheels(forward, turn);
}

// At the start the wall is further than the setpoint: close in on it along rerror until the sonar
// that looks straight right reads about the setpoint.
Task<Wheels> closeIn() {
  return mkTask([](const TaskState& ts) {
    const Robot& r = ts.robot();
    return std::pair{alongWall(r), predicate(sonar(r, 12) < kSetpoint + 10_cm)};
  });
}

// Then follow the wall until a corner comes, and say which: a wall ahead (a concave corner) or no
// more wall to the right, neither straight right (sonar 12) nor just ahead of it (13): a convex
// corner. (Sonar 13 keeps us from taking the start of the next wall, heard ahead, for a corner
// just after we have rounded one.) The task's result is the event's value.
enum class Corner { concave, convex };

Task<Wheels, Corner> untilCorner() {
  return mkTask([](const TaskState& ts) {
    const Robot& r = ts.robot();
    Event<Corner> wallAhead = predicate(ahead(r) < kSetpoint + 5_cm).map([] { return Corner::concave; });
    Event<Corner> wallEnds = predicate(min(sonar(r, 12), sonar(r, 13)) > kSetpoint + 40_cm).map([] { return Corner::convex; });
    return std::pair{alongWall(r), wallAhead | wallEnds};
  });
}

// Step 3. A concave corner: turn left on the spot until the wall that was ahead is on our right:
// the way ahead is clear, and the sonar that looks straight right (12) hears the wall no further
// than the one 22.5 degrees ahead of it (13), so that we are nearly parallel to the wall.
Task<Wheels> turnInside() {
  return mkTask([](const TaskState& ts) {
    const Robot& r = ts.robot();
    auto parallel = sonar(r, 12) < kSetpoint + 20_cm && sonar(r, 12) <= sonar(r, 13);
    return std::pair{wheels(0, 0.8), predicate(ahead(r) > kSetpoint + 30_cm && parallel)};
  });
}

// Step 4. A convex corner: the wall on our right has ended, so curve right round its end until the
// next wall is beside us and we are nearly parallel to it: both sonar 12 and sonar 13 hear it.
// Sonar 12's cone is 25 degrees wide, so it hears the wall's end until we are some 12 cm past it:
// we curve that much tighter than (setpoint + body radius), to pass the end at the setpoint. The
// wheels slip, so the curve is never quite the one commanded: should a wall come up ahead, we stop
// curving into it, and untilCorner takes it for the concave corner it is.
Task<Wheels> roundCorner() {
  return mkTask([](const TaskState& ts) {
    const Robot& r = ts.robot();
    double radius = kSetpoint + r.spec().radius - 12_cm;
    auto parallel = sonar(r, 12) < kSetpoint + 25_cm && sonar(r, 13) < kSetpoint + 25_cm;
    auto blocked = ahead(r) < kSetpoint + 5_cm;
    return std::pair{wheels(kSpeed, -kSpeed / radius), predicate(parallel || blocked)};
  });
}

// Step 5. Follow the wall for ever: along it, then round whichever corner comes, and again.
// timeLimit gives up a concave turn after 4 s (half a turn), in case the sonars never agree.
Task<Wheels> followRightWall() {
  co_await closeIn();
  for (;;) {
    Corner next = co_await untilCorner();
    if (next == Corner::concave) {
      (void)co_await timeLimit(turnInside(), 4_s);
    } else {
      co_await roundCorner();
    }
  }
}

FROB_CONTROLLER(followRightWall, .world = "assignments/wall_follow/worlds/l_room.toml", .seconds = 90,
                .summary = "follow the wall on the right 40 cm away, round every corner (paper 2.3)")
