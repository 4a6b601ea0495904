// Example 2: the paper's `rerror` wall follower (paper section 2.3).
//
// The paper shows this line as a taste of programming with behaviors:
//
//     rerror r = limit (velocity r * sin thetamax) (setpoint - leftSonar r)
//       where limit m v = (-m) `max` v `min` m
//
// "how far we are from where we want to be", clipped to a bound that depends on the speed. Here we
// finish the controller around it: the robot drives down a corridor keeping the wall on its left at
// a set distance, and stops when that wall ends (at the corridor's bend).
//
// Run it:  build/app/frob run course/examples/02_wall_follower.cpp
// What to look for: after a few seconds the left sonar (sonar 4) stays close to 50 cm all the way.

#include <frob/frob.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace frob;
using namespace frob::literals;

constexpr double kSpeed = 0.4;        // forward speed, m/s
constexpr double kSetpoint = 50_cm;   // wanted distance from the wall (the left sonar's reading)
constexpr double kThetaMax = 20_deg;  // steepest angle at which we may close in on (or leave) the wall

// Step 1. The paper's rerror, nearly word for word.
//
// Read it as a speed: to get back to the setpoint we want to move sideways, away from the wall, at
// (setpoint - leftSonar) metres per second (too close: positive, move away; too far: negative).
// But moving sideways at speed s while driving forward at speed v means heading at an angle
// asin(s / v) to the wall. `limit` keeps |s| below v * sin(thetaMax): we never aim at the wall (or
// away from it) more steeply than thetaMax, however far from the setpoint we are.
//
// Operators on behaviors work point by point, so this is ordinary-looking code over values that
// change with time. We use the speed we command, kSpeed, where the paper reads `velocity r`: it is
// the same once we are moving, and it lets the robot steer from its very first instant.
Behavior<double> rerror(const Robot& r) {
  auto limit = [](double m, const Behavior<double>& v) { return min(max(-m, v), m); };
  return limit(kSpeed * std::sin(kThetaMax), kSetpoint - leftSonar(r));
}

// Step 2. Which way does the wall run, compared with our heading?
//
// rerror says how fast we WANT to move away from the wall; to steer we must also know how fast we
// DO. A sonar only hears a wall it faces nearly head-on, so among the sonars on the left, those
// with the nearest echoes point roughly along the wall's normal. Their average direction (weighted
// by how near each echo is) is the direction of the wall: +90 degrees when it runs alongside.
// `lift` applies an ordinary function to a behavior, instant by instant.
Behavior<double> wallDirection(const Robot& r) {
  std::vector<double> angles = r.spec().sonarAngles;  // sonar i points angles[i] from the heading
  return lift(
      [angles](const std::vector<double>& range) {
        double nearest = *std::min_element(range.begin() + 1, range.begin() + 8);
        double x = 0.0, y = 0.0;
        for (int i = 1; i <= 7; ++i) {  // sonars 1 to 7: from ahead-left round to behind-left
          double weight = std::max(0.0, nearest + 0.2 - range[i]);
          x += weight * std::cos(angles[i]);
          y += weight * std::sin(angles[i]);
        }
        return std::atan2(y, x);
      },
      sonars(r));
}

// Step 3. The wall follower as a task.
//
// Driving forward at speed v with the wall in direction d, we move towards the wall at v * cos(d),
// so away from it at -v * cos(d). Turning right (a negative turn rate) makes us move away faster.
// So we turn right in proportion to how much slower than `rerror` we move away: a feedback loop.
// The task ends when the wall is gone: no echo on the left nearer than 1.5 m.
Task<Wheels> followLeftWall() {
  return mkTask([](const TaskState& ts) {
    const Robot& r = ts.robot();
    Behavior<double> away = -kSpeed * cos(wallDirection(r));  // how fast we move away now
    auto turn = clamp(-4.0 * (rerror(r) - away), -1.0, 1.0);  // rad/s, the robot's limit is 1
    auto wallGone = predicate(min(sonar(r, 3), sonar(r, 4), sonar(r, 5)) > 1.5_m);
    return std::pair{wheels(kSpeed, turn), wallGone};
  });
}

// Step 4. Draw the setpoint: a line 50 cm to our left (plus the body radius) while we follow.
// withPicture adds a picture to a task; it is shown in the video, and ignored by a real robot.
Task<Wheels> wallFollower() {
  TaskState ts = co_await getTaskState();
  const Robot& r = ts.robot();
  double offset = r.spec().radius + kSetpoint;  // from the robot's centre to the setpoint
  Behavior<Picture> guide = lift(
      [offset](const Point2& p, double heading) {
        Point2 side = p + offset * unitVector(heading + pi / 2);
        return withColor(green, line(side - 0.5 * unitVector(heading), side + 0.5 * unitVector(heading)));
      },
      place(r), orientation(r));
  co_await withPicture(guide, followLeftWall());
}

FROB_CONTROLLER(wallFollower, .world = "corridor", .seconds = 60,
                .summary = "the paper's rerror: follow the corridor's left wall 50 cm away until it ends (paper 2.3)")
