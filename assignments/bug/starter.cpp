// Assignment "bug": BUG in a random obstacle field. Your starting point (read handout.md first).
//
// Steps 0 to 3 are given: what the robot knows, sensing, and the paper's two primitive tasks
// driveTo and followWall (made safe from bumps), with turnToWall. You may change them, but you
// should not need to. Your part comes after them: BUG itself, with circleOnceP (withB and atMin),
// a leave rule, timeLimit on every leg, withExit, and taskCatch.
//
// As given, the robot drives straight at the goal and stops at the first obstacle.
//
// Run it:   build/app/frob run assignments/bug/starter.cpp --video bug.mp4 --plot bug.png
// Check it: build/app/frob grade bug my.cpp --visible-only --report r.html

#include <frob/frob.hpp>

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>
#include <vector>

using namespace frob;
using namespace frob::literals;

// ---- Step 0. What the robot knows -----------------------------------------------------------
//
// The goal of every generated obstacle field, in world coordinates. Odometry reports world
// coordinates too: it starts at the robot's start pose (1.5, 1.5), give or take 2 cm, and drifts
// only a little (some 2 cm after 10 m), so place(r) can be compared with the goal directly.
const Point2 kGoal{13.5, 13.5};

constexpr double kSpeed = 0.6;        // m/s, the robot's top speed
constexpr double kSetpoint = 20_cm;   // clearance kept between the robot's rim and a wall it follows
constexpr double kThetaMax = 30_deg;  // steepest angle at which the follower closes in on a wall
constexpr double kAheadNear = 35_cm;  // something this near straight ahead is the next wall to follow

// ---- Step 1. Sensing (given) ------------------------------------------------------------------

// Where the wall on our left is: its distance (nearest echo) and its direction, radians from our
// heading (+90 degrees for a wall alongside). A sonar hears a wall only when it faces it nearly
// head-on, so the sonars whose echoes are nearly as near as the nearest one point around the
// wall's normal: their average direction, weighted by how near each echo is, is the wall's.
// The side sonars (1 to 8) always count; the two ahead (15, 0) only when their echo is near.
struct Wall {
  double distance = 0.0;
  double direction = 0.0;
};
Behavior<Wall> wallOnLeft(const Robot& r) {
  std::vector<double> angles = r.spec().sonarAngles;
  return lift(
      [angles](const std::vector<double>& range) {
        std::vector<int> seen = {1, 2, 3, 4, 5, 6, 7, 8};
        for (int i : {15, 0}) {
          if (range[i] < kAheadNear) seen.push_back(i);
        }
        double nearest = 1e9;
        for (int i : seen) nearest = std::min(nearest, range[i]);
        double x = 0.0, y = 0.0;
        for (int i : seen) {
          double weight = std::max(0.0, nearest + 0.2 - range[i]);
          x += weight * std::cos(angles[i]);
          y += weight * std::sin(angles[i]);
        }
        return Wall{nearest, std::atan2(y, x)};
      },
      sonars(r));
}

// Something in the way ahead: near straight ahead, or nearer still a little to the side.
Event<Unit> blockedAhead(const Robot& r) {
  return predicate(sonar(r, 0) < 45_cm || min(sonar(r, 1), sonar(r, 15)) < 40_cm ||
                   min(sonar(r, 2), sonar(r, 14)) < 25_cm);
}

// How fast to move forward with `ahead` metres free in front: full speed from 70 cm, slowing to a
// stop at 20 cm, and backing away nearer than 18 cm. A block's corner met at a slant is silent to
// the sonars until the robot is on it (they read their shortest, 15 cm, then): turning on the spot
// there would rub against it, so every turn on the spot backs away from something that near.
Behavior<double> roomAhead(const Robot& r) {
  return lift([](double ahead) { return ahead < 18_cm ? -0.2 : kSpeed * std::clamp((ahead - 20_cm) / 50_cm, 0.0, 1.0); },
              min(sonar(r, 15), sonar(r, 0), sonar(r, 1)));
}

// ---- Step 2. driveTo (given) ------------------------------------------------------------------

// Turn on the spot to face `goal`.
Task<Wheels> faceGoal(Point2 goal) {
  return mkTask([goal](const TaskState& ts) {
    const Robot& r = ts.robot();
    Behavior<double> error = wrapAngle(heading(goal - place(r)) - orientation(r));
    return std::pair{wheels(min(roomAhead(r), 0.0), clamp(2.0 * error, -1.0, 1.0)), predicate(abs(error) < 5_deg)};
  });
}

// After a bump at `angle` (radians from our heading; the corner of a block met at a slant is
// silent to the sonars): reverse, longer if it is in front, then turn 45 degrees away from it.
// The wheels take about 0.6 s to go from full speed ahead to reversing (the robot slides along
// what it hit meanwhile), so a shorter reverse never leaves the obstacle: the robot would turn
// on the spot against it, touching it all the while.
Task<Wheels> recoverFrom(double angle) {
  double reverse = 0.8 + 0.4 * std::max(0.0, std::cos(angle));  // seconds of reversing at 0.2 m/s
  co_await mkTask([reverse](const TaskState&) { return std::pair{wheels(-0.2, 0.0), after(reverse)}; });
  double turn = angle >= 0 ? -1.0 : 1.0;  // rad/s, away from the bump, for 45_deg (0.79) s: about 45 degrees
  co_await mkTask([turn](const TaskState&) { return std::pair{wheels(0.0, turn), after(45_deg)}; });
}

// How the drive ended: there, blocked by an echo, or bumped (and where).
struct DriveEnd {
  enum How { there, blocked, bumped } how;
  double angle = 0.0;
};

// The paper's driveTo: head for `goal`; true when there, false when something blocks the way.
Task<Wheels, bool> driveTo(Point2 goal) {
  co_await faceGoal(goal);
  DriveEnd end = co_await mkTask([goal](const TaskState& ts) {
    const Robot& r = ts.robot();
    Behavior<double> error = wrapAngle(heading(goal - place(r)) - orientation(r));
    Behavior<double> left = distance(place(r), goal);
    auto forward = min(kSpeed, left) * max(cos(error), 0.0);  // slow down at the end
    Event<DriveEnd> there = predicate(left < 5_cm).as(DriveEnd{DriveEnd::there});
    Event<DriveEnd> blocked = blockedAhead(r).as(DriveEnd{DriveEnd::blocked});
    Event<DriveEnd> bumped = bumper(r).map([](const BumperHit& h) { return DriveEnd{DriveEnd::bumped, h.angle}; });
    return std::pair{wheels(forward, clamp(2.0 * error, -1.0, 1.0)), there | bumped | blocked};
  });
  if (end.how == DriveEnd::bumped) co_await recoverFrom(end.angle);
  co_return end.how == DriveEnd::there;
}

// ---- Step 3. followWall (given) ---------------------------------------------------------------

// Turn right on the spot until the obstacle ahead is on our left (at most 2 s).
Task<Wheels> turnToWall() {
  return mkTask([](const TaskState& ts) {
    Behavior<Wall> wall = wallOnLeft(ts.robot());
    auto onLeft = lift([](const Wall& w) { return w.distance < 1.0 && w.direction > 60_deg; }, wall);
    return std::pair{wheels(min(roomAhead(ts.robot()), 0.0), -0.8), predicate(onLeft) | after(2_s)};
  });
}

// Follow the wall on our left while there is one: the paper's rerror (example 2), the speed at
// which we want to move away from the wall, limited so that we never head into it more steeply
// than kThetaMax. Ends when the wall is more than 1 m away (we passed its end).
Task<Wheels> alongWall() {
  return mkTask([](const TaskState& ts) {
    const Robot& r = ts.robot();
    Behavior<Wall> wall = wallOnLeft(r);
    Behavior<double> d = wall.map(&Wall::distance);
    Behavior<double> normal = wall.map(&Wall::direction);
    double m = kSpeed * std::sin(kThetaMax);
    auto rerror = clamp(kSetpoint - d, -m, m);  // wanted speed away from the wall
    auto away = -kSpeed * cos(normal);          // speed away from the wall now
    // In a corner (a wall ahead, nearer than 25 cm), turn right towards the next wall to follow.
    auto ahead = min(sonar(r, 15), sonar(r, 0), sonar(r, 1));
    auto turn = lift([](double t, double a) { return a < 25_cm ? -1.0 : t; }, clamp(-3.0 * (rerror - away), -1.0, 1.0), ahead);
    return std::pair{wheels(roomAhead(r), turn), predicate(d > 1_m)};
  });
}

// Round the end of a wall: curve left until a wall shows up again. If none does within 8 s, the
// wall is lost: an error (the paper: "if for some reason the wall disappears from the sonars,
// this task raises an exception").
Task<Wheels> roundCorner() {
  return mkTaskE([](const TaskState& ts) {
    const Robot& r = ts.robot();
    Behavior<double> d = wallOnLeft(r).map(&Wall::distance);
    double radius = kSetpoint + r.spec().radius;
    return std::tuple{wheels(kSpeed, kSpeed / radius), predicate(d < 80_cm),
                      after(8_s).as(RoboErr("followWall: the wall is lost"))};
  });
}

Task<Wheels> followBySonar() {
  for (;;) {
    co_await alongWall();
    co_await roundCorner();
  }
}

// The paper's followWall: travel round the obstacle on our left, for ever. A bump (a corner the
// sonars did not hear) ends the sonar follower for a moment: back off, then carry on.
Task<Wheels> followWall() {
  TaskState ts = co_await getTaskState();
  for (;;) {
    BumperHit hit = co_await withExit(bumper(ts.robot()), followBySonar());
    co_await recoverFrom(hit.angle);
  }
}

// ---- Your part: steps 4 to 7 (see the handout) ------------------------------------------------
//
// 4. atPlace(r, p, within) and the leave rule mayLeave(r, g, dHit): two events.
// 5. circleOnce and circleOnceP as in the paper (withB, atMin, timeLimit, withExit), ending early
//    when the leave rule allows; circleTo.
// 6. goAround: round the obstacle within a time limit (timeLimit); a leg that runs too long raises
//    an error (taskError); then BUG again from where the robot is (co_await become(bug(g))).
// 7. bug: taskCatch, so that an error restarts BUG instead of stopping the robot.

// The controller. For now it only drives at the goal: it stops at the first obstacle.
Task<Wheels> bugToGoal() {
  co_await withPicture(paintAt(kGoal, withColor(red, disc(10_cm) + text("goal"))), driveTo(kGoal));
}

FROB_CONTROLLER(bugToGoal, .world = "assignments/bug/worlds/trap.toml", .seconds = 120,
                .summary = "the bug assignment's starter: drive at the goal, stop at the first obstacle")
