// Wall follow: your starting point (paper section 2.3, rerror).
//
// The paper's rerror, used the simplest way: turn towards the wall when the right sonar reads more
// than the setpoint, away from it when it reads less. It compiles and runs, but it goes round in
// circles by the wall, bumping into it: as soon as it turns towards the wall, its right sonar no
// longer faces the wall and hears nothing (6.5 m, "far too far"), so it turns further. Make it
// follow the right wall as the handout asks. Read the handout first, then course/examples/02
// (rerror, and which way the wall runs) and the followWall of course/examples/06 (corners).
//
// Run it:   build/app/frob run assignments/wall_follow/starter.cpp --frames /tmp/frames --fps 1
// Check it: build/app/frob grade wall_follow assignments/wall_follow/starter.cpp --visible-only --report r.html

#include <frob/frob.hpp>

#include <cmath>

using namespace frob;
using namespace frob::literals;

constexpr double kSpeed = 0.3;         // forward speed, m/s
constexpr double kSetpoint = 40_cm;    // wanted distance from the robot's rim to the wall on the right
constexpr double kThetaMax = 25_deg;   // steepest angle at which to close in on (or leave) the wall

// The paper's rerror for a wall on the right: how fast we want to move away from the wall
// (positive when too close), limited to kSpeed * sin(kThetaMax).
Behavior<double> rerror(const Robot& r) {
  auto limit = [](double m, const Behavior<double>& v) { return min(max(-m, v), m); };
  return limit(kSpeed * std::sin(kThetaMax), kSetpoint - rightSonar(r));
}

// TODO: steer on how fast you DO move away from the wall, not only on how fast you want to
// (example 02's wallDirection); handle a wall ahead (a concave corner) and the end of the wall
// (a convex corner), and go on for ever.
Task<Wheels> followRightWall() {
  return mkTask([](const TaskState& ts) {
    const Robot& r = ts.robot();
    auto turn = clamp(5.0 * rerror(r), -1.0, 1.0);  // too close: turn left (positive)
    return std::pair{wheels(kSpeed, turn), never<Unit>()};
  });
}

FROB_CONTROLLER(followRightWall, .world = "assignments/wall_follow/worlds/l_room.toml", .seconds = 90,
                .summary = "wall_follow starter: the paper's rerror, used the simplest way")
