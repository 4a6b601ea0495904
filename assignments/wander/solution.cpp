// Wander: the reference solution (paper section 3.1, runAround).
//
// The paper's runAround drives ahead until something is close, turns right until the way is
// clear, and does that for ever. In a furnished house that is not enough: a robot that stops for
// anything beside it cannot get through a doorway, and one that always turns the same way to the
// first clear heading runs round the same loop again and again. This runAround
//   1. drives ahead, steering away from whatever passes close beside it (so it goes through a
//      doorway instead of stopping in it), and brakes as something comes near ahead;
//   2. when blocked, turns towards the side with more room: first by an angle that differs at
//      every stop, then on until there is a long way ahead, so that no loop repeats.
//
// Run it:  build/app/frob run assignments/wander/solution.cpp --frames /tmp/frames --fps 1

#include <frob/frob.hpp>

#include <cmath>
#include <vector>

using namespace frob;
using namespace frob::literals;

constexpr double kSpeed = 0.6;      // forward speed, m/s: the robot's top speed
constexpr double kTurnRate = 1.0;   // turning on the spot, rad/s
constexpr double kStop = 45_cm;     // stop when something ahead is nearer than this
constexpr double kClear = 90_cm;    // a heading is clear when nothing is nearer than this ahead
constexpr double kOpen = 2_m;       // a long way ahead: worth driving down
constexpr double kSide = 35_cm;     // steer away from anything nearer than this beside us

// Step 1. Sensing. A sonar hears a wall only when it faces it nearly head-on, so each direction is
// the nearest echo of a few neighbouring sonars (0 is ahead, numbered counter-clockwise 22.5
// degrees apart). Ahead is only sonars 15, 0 and 1: the posts of a doorway, 45 degrees to each
// side as we drive through it, must not stop us.
Behavior<double> nearest(const Robot& r, std::initializer_list<int> which) {
  Behavior<double> d = constant(6.5);  // 6.5 m: no echo
  for (int i : which) d = min(d, sonar(r, i));
  return d;
}
Behavior<double> ahead(const Robot& r) { return nearest(r, {15, 0, 1}); }
Behavior<double> leftSide(const Robot& r) { return nearest(r, {2, 3, 4}); }
Behavior<double> rightSide(const Robot& r) { return nearest(r, {12, 13, 14}); }

// How much more room there is on the left than on the right: the sum of the ranges of the seven
// sonars on each side (a sonar with no echo counts 6.5 m, plenty of room).
Behavior<double> roomOnLeft(const Robot& r) {
  return lift(
      [](const std::vector<double>& range) {
        double left = 0.0, right = 0.0;
        for (int i = 1; i <= 7; ++i) left += range[i], right += range[16 - i];
        return left - right;
      },
      sonars(r));
}

// Step 2. goAhead: drive forward until the way is blocked.
//   * Whatever comes within kSide on one side pushes us to the other, the harder the nearer it
//     is: we do not scrape along a wall met at a grazing angle, and a doorway's two posts push
//     equally, which keeps us in its middle.
//   * We slow down as something comes near ahead: at top speed the robot needs 18 cm to stop.
//   * The task ends with the side that has more room, true for the left: snapshot pairs the
//     blocking event with the value of roomOnLeft at that instant.
Task<Wheels, bool> goAhead() {
  return mkTask([](const TaskState& ts) {
    const Robot& r = ts.robot();
    auto push = [](const Behavior<double>& d) { return clamp((kSide - d) / kSide, 0.0, 1.0); };
    auto turn = 2.0 * (push(rightSide(r)) - push(leftSide(r)));  // positive: to the left
    auto forward = kSpeed * clamp((ahead(r) - 25_cm) / 50_cm, 0.2, 1.0);
    Event<bool> blocked = snapshot(predicate(ahead(r) < kStop), roomOnLeft(r)).map([](const auto& p) { return p.second > 0; });
    return std::pair{wheels(forward, clamp(turn, -1.0, 1.0)), blocked};
  });
}

// Step 3. turnFor: turn on the spot, to the left or to the right, for `seconds` (after(s) occurs
// s seconds after the task starts). Turning on the spot never touches anything: the robot is round.
Task<Wheels> turnFor(bool left, double seconds) {
  return mkTask([left, seconds](const TaskState&) { return std::pair{wheels(0, left ? kTurnRate : -kTurnRate), after(seconds)}; });
}

// Step 4. turnUntilClear: turn on the spot until nothing is nearer than `clear` ahead.
Task<Wheels> turnUntilClear(bool left, double clear) {
  return mkTask([left, clear](const TaskState& ts) {
    return std::pair{wheels(0, left ? kTurnRate : -kTurnRate), predicate(ahead(ts.robot()) > clear)};
  });
}

// Step 5. runAround, as in the paper: goAhead, turn, again and again.
// The first part of each turn lasts from 0.5 to 2 s (30 to 115 degrees): the fractional parts of
// k times the golden ratio, a sequence that never repeats and spreads evenly over [0, 1). Then we
// turn on until the way ahead is long (at most one full turn: timeLimit gives false when time
// is up); in a tight spot, where there is no long way, until it is merely clear.
Task<Wheels> runAround() {
  for (int k = 1;; ++k) {
    bool left = co_await goAhead();
    double spread = k * 0.6180339887 - std::floor(k * 0.6180339887);
    co_await turnFor(left, 0.5 + 1.5 * spread);
    if (!co_await timeLimit(turnUntilClear(left, kOpen), 2 * pi / kTurnRate)) co_await turnUntilClear(left, kClear);
  }
}

FROB_CONTROLLER(runAround, .world = "assignments/wander/worlds/living_room.toml", .seconds = 120,
                .summary = "wander out of the hall and round a furnished room, never touching anything (paper 3.1)")
