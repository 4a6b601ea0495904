// Assignment "multi_robot": cross the arena without touching anyone. The reference solution.
//
// Several robots share a 10 x 10 m arena with pillars in it, and every one of them runs this same
// file. Each must reach the point opposite its start through the centre of the arena (5, 5), so
// all their ways cross in the middle. The paper left multi-robot systems as future work (section
// 5); in Frob each robot simply runs its own copy of the task, and sees the others only through
// its sonars.
//
// The plan: work out the goal once, from where the robot started (step 1). Look out along the
// way to the goal (step 2): when anything is in it, a robot or a pillar, head for the nearest way
// to its right that is clear instead (step 3), like traffic at a roundabout. Because every robot
// keeps right, two robots that meet pass each other left side to left side, a crowd in the middle
// turns round it the same way, and a robot goes round a pillar keeping it on its left.
//
// Run it:   build/app/frob run assignments/multi_robot/solution.cpp --video x.mp4   (in worlds/corners.toml)
//           build/app/frob run assignments/multi_robot/solution.cpp --world assignments/multi_robot/worlds/swap.toml
// Grade it: build/app/frob grade multi_robot assignments/multi_robot/solution.cpp --visible-only

#include <frob/frob.hpp>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

using namespace frob;
using namespace frob::literals;

constexpr double kSpeed = 0.5;    // m/s, a little under the top speed, so that turns stay tight
constexpr double kLookout = 1.0;  // m: anything nearer than this in a way closes it
constexpr double kMargin = 0.3;   // m kept beside the body when passing something (a sonar's cone is 25 degrees wide)

// ---- Step 1. The goal --------------------------------------------------------------------------
//
// A controller never sees the world file, so the goal must come from what the robot knows: where
// it started. Odometry reports world coordinates, starting at the true start pose, without drift
// here. The point opposite `start` through the centre c is c + (c - start).
const Point2 kCentre{5.0, 5.0};
Point2 oppositeOf(Point2 start) { return kCentre + (kCentre - start); }

// ---- Step 2. Looking out -----------------------------------------------------------------------
//
// Each sonar's echo is a point on something's surface, `body + range` from our centre along the
// sonar's direction. Driving in `direction` (radians from our heading), our body sweeps a band as
// wide as itself plus kMargin each side: the nearest echo in that band ahead of us is how far we
// can drive that way. Other robots are round, so some ray always meets them head-on: they echo
// from every side, and so do the pillars.
double clearRun(const std::vector<double>& range, const std::vector<double>& angles, double body, double direction) {
  double run = INFINITY;
  for (std::size_t i = 0; i < range.size(); ++i) {
    const double d = body + range[i], a = angles[i] - direction;
    const double along = d * std::cos(a) - body, across = std::abs(d * std::sin(a));
    if (along > 0 && across < body + kMargin) run = std::min(run, along);
  }
  return run;
}

// The way to go, radians from our heading: straight at the goal if nothing is within kLookout that
// way (or nearer than the goal: someone standing beyond it is not in our way); else the clear way
// nearest to it, in steps of 15 degrees, a way to the right counting as half as far as one to the
// left (keep right). Boxed in, we turn right on the spot.
Behavior<double> wayToGo(const Robot& r, Point2 goal) {
  Behavior<double> toGoal = wrapAngle(heading(goal - place(r)) - orientation(r));
  Behavior<double> left = distance(place(r), goal);
  return lift(
      [angles = r.spec().sonarAngles, body = r.spec().radius](const std::vector<double>& range, double toGoal, double left) {
        for (double off = 0; off <= 180_deg; off += 15_deg) {
          for (double way : {toGoal - off, toGoal + off / 2}) {
            if (clearRun(range, angles, body, way) > std::min(kLookout, left)) return std::remainder(way, 2 * pi);
          }
        }
        return -90.0_deg;
      },
      sonars(r), toGoal, left);
}

// How far we can drive straight ahead.
Behavior<double> clearAhead(const Robot& r) {
  return lift([angles = r.spec().sonarAngles, body = r.spec().radius](const std::vector<double>& range) { return clearRun(range, angles, body, 0); },
              sonars(r));
}

// ---- Step 3. Driving, keeping right ------------------------------------------------------------

// Head for `goal` along the way to go, slowing down for anything close ahead, until there.
Task<Wheels> crossTo(Point2 goal) {
  return mkTask([goal](const TaskState& ts) {
    const Robot& r = ts.robot();
    Behavior<double> way = wayToGo(r, goal);
    Behavior<double> left = distance(place(r), goal);
    auto forward = min(kSpeed, left) * max(cos(way), 0.0) * clamp((clearAhead(r) - 20_cm) / 50_cm, 0.0, 1.0);
    // A way far behind on our left: we turn round to the right, not one way and the other.
    auto turn = lift([](double a) { return a > 120_deg ? -1.0 : std::clamp(2.0 * a, -1.0, 1.0); }, way);
    return std::pair{wheels(forward, turn), predicate(left < 10_cm)};
  });
}

// ---- Step 4. The controller --------------------------------------------------------------------

// Work out the goal from where this task began (the robot's start), then cross to it, with the
// goal drawn. Ending the task stops the robot.
Task<Wheels> crossArena() {
  TaskState ts = co_await getTaskState();
  Point2 goal = oppositeOf(ts.initialPlace());
  co_await withPicture(paintAt(goal, withColor(red, circle(15_cm))), crossTo(goal));
}

FROB_CONTROLLER(crossArena, .world = "assignments/multi_robot/worlds/corners.toml", .seconds = 35,
                .summary = "every robot crosses to the point opposite its start, keeping right of the others")
