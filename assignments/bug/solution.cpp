// Assignment "bug": BUG in a random obstacle field. The reference solution.
//
// The paper's BUG (section 4.1, course example 06) drives at the goal and, when blocked, goes all
// the way round the obstacle, then on round to the point of it closest to the goal, and starts
// again from there. In a random field that is too slow, it can go round for ever, and it drives
// well past the BUG1 bound. This solution keeps the paper's structure and adds three things:
//
//   1. a leave rule: stop going round as soon as we are clearly nearer the goal than where we met
//      the obstacle and the goal lies on the open side (away from the wall);
//   2. a time limit on every leg (timeLimit): a leg that runs too long raises an error;
//   3. taskCatch, which restarts BUG from wherever the robot is when a leg fails.
//
// Steps 1 to 3 are the primitives the starter gives (sensing, driveTo, followWall); steps 4 to 7
// are the assignment.
//
// Run it:  build/app/frob run assignments/bug/solution.cpp --world assignments/bug/worlds/trap.toml
// Grade it: build/app/frob grade bug assignments/bug/solution.cpp --visible-only

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
// coordinates too: it starts at the field's start (1.5, 1.5), where the robot really starts within
// 2 cm and half a degree, and drifts a few centimetres on the way, so place(r) can be compared
// with the goal directly, give or take some centimetres.
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

// ---- Step 4. Events for circling: atPlace and the leave rule ----------------------------------

// The paper's atPlace: occurs when the robot is within `within` of `p`.
Event<Unit> atPlace(const Robot& r, Point2 p, double within) { return predicate(distance(place(r), p) < within); }

// Nothing within 1.5 m towards `bearing` (radians from our heading): the sonar facing it and its
// two neighbours hear no echo nearer.
Behavior<bool> clearTowards(const Robot& r, Behavior<double> bearing) {
  std::vector<double> angles = r.spec().sonarAngles;
  return lift(
      [angles](double towards, const std::vector<double>& range) {
        int n = static_cast<int>(angles.size()), facing = 0;
        for (int i = 1; i < n; ++i) {
          if (std::abs(wrapAngle(angles[i] - towards)) < std::abs(wrapAngle(angles[facing] - towards))) facing = i;
        }
        return std::min({range[(facing + n - 1) % n], range[facing], range[(facing + 1) % n]}) > 1.5;
      },
      bearing, sonars(r));
}

// The leave rule: we may stop going round when we are at least 30 cm nearer the goal than where
// we met the obstacle (dHit) AND the goal lies on the open side, more than 120 degrees from the
// direction of the wall, or nothing stands within 1.5 m towards it. On a convex obstacle this
// happens just before the point nearest the goal, so the robot drives about half way round
// instead of one and a half times. Round a small block the follower swings wide and hears no
// wall for a while: then only the clear way to the goal lets it leave.
Event<bool> mayLeave(const Robot& r, Point2 g, double dHit) {
  Behavior<double> goalBearing = wrapAngle(heading(g - place(r)) - orientation(r));
  auto openSide = lift(
      [](double bearing, const Wall& w) { return w.distance < 1.0 && std::abs(wrapAngle(bearing - w.direction)) > 120_deg; },
      goalBearing, wallOnLeft(r));
  return predicate(distance(place(r), g) < dHit - 30_cm && (openSide || clearTowards(r, goalBearing))).map([] { return true; });
}

// ---- Step 5. circleOnce and circleOnceP (the paper's, with the leave rule) --------------------

// circleOnce: follow the wall for 5 s to get away from where we started (timeLimit), then until we
// are back there (withExit). Both legs also end when the leave rule allows: true means "we may
// leave here", false "we went all the way round". The circle closes within 45 cm of its start:
// the robot met the wall a little farther out than the follower keeps.
Task<Wheels, bool> circleOnce(Point2 g) {
  TaskState ts = co_await getTaskState();
  const Robot& r = ts.robot();
  Point2 initp = ts.initialPlace();
  double dHit = distance(initp, g);
  std::optional<bool> early = co_await timeLimit(withExit(mayLeave(r, g, dHit), followWall()), 5_s);
  if (early) co_return true;  // the leave rule fired in the first 5 s
  Event<bool> back = atPlace(r, initp, 45_cm).map([] { return false; });
  co_return co_await withExit(mayLeave(r, g, dHit) | back, followWall());
}

// circleOnceP: circleOnce, and the place where we were closest to the goal. withB starts the
// behavior with the task (so atMin watches this circle only) and adds its final value to the
// task's result: atMin(a, b) is the value of b when a was smallest.
Task<Wheels, std::pair<bool, Point2>> circleOnceP(Point2 g) {
  auto closestP = [g](const TaskState& ts) {
    const Robot& r = ts.robot();
    return atMin(distance(place(r), g), place(r));
  };
  co_return co_await withB(closestP, circleOnce(g));
}

// circleTo: follow the wall until we are as near the goal as `p` (within 10 cm), drawn as a green
// dot meanwhile. Not "until we are at p": the next time round the follower may pass p wider.
Task<Wheels> circleTo(Point2 p, Point2 g) {
  TaskState ts = co_await getTaskState();
  Event<Unit> asNear = predicate(distance(place(ts.robot()), g) < distance(p, g) + 10_cm);
  co_await withPicture(paintAt(p, withColor(green, disc(12_cm))), withExit(asNear, followWall()));
}

// ---- Step 6. Going round, with a time limit ---------------------------------------------------

// Round the obstacle: put it on our left, circle it until the leave rule allows; if we came all
// the way round without leaving, go on to the closest point, as the paper's BUG does.
Task<Wheels> roundObstacle(Point2 g) {
  co_await turnToWall();
  auto [leftEarly, closest] = co_await circleOnceP(g);
  if (!leftEarly) co_await circleTo(closest, g);
}

Task<Wheels> bug(Point2 g);

// goAround: round the obstacle in at most 30 s, then BUG again from here (the paper's tail call).
// A robot that follows a wall for longer has lost the obstacle it met: it may be going round a
// neighbour whose circle never passes where it started. timeLimit gives false then, and we
// raise an error for taskCatch.
Task<Wheels> goAround(Point2 g) {
  bool done = co_await timeLimit(roundObstacle(g), 30_s);
  if (!done) co_await taskError(RoboErr("going round one obstacle took more than 30 s"));
  co_await become(bug(g));
}

// ---- Step 7. BUG, with taskCatch --------------------------------------------------------------

// One attempt: drive to the goal (at most 40 s); done when there, otherwise go around.
Task<Wheels> bugAttempt(Point2 g) {
  std::optional<bool> finished = co_await timeLimit(driveTo(g), 40_s);
  if (!finished) co_await taskError(RoboErr("driving to the goal took more than 40 s"));
  if (*finished) co_return;
  co_await become(goAround(g));
}

// The paper's bug: taskCatch restarts BUG from wherever the robot is when a leg fails (a lost
// wall, a time limit). The handler takes the failed task's place, so this runs in bounded memory.
Task<Wheels> bug(Point2 g) {
  return taskCatch(bugAttempt(g), [g](const RoboErr&) { return bug(g); });
}

// The controller: BUG to the field's goal, the goal drawn all along.
Task<Wheels> bugToGoal() {
  co_await withPicture(paintAt(kGoal, withColor(red, disc(10_cm) + text("goal"))), bug(kGoal));
}

FROB_CONTROLLER(bugToGoal, .world = "assignments/bug/worlds/trap.toml", .seconds = 120,
                .summary = "BUG with a leave rule, time limits and taskCatch in a random obstacle field")
