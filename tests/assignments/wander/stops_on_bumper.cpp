// A typical wrong submission: a good explorer that finds the walls with its bumpers. It drives
// ahead until a bumper is pressed, backs off and turns towards the open side, so it explores the
// rooms well, but it touches every wall and piece of furniture it turns away from.
#include <frob/frob.hpp>

#include <cmath>
#include <vector>

using namespace frob;
using namespace frob::literals;

// How much more room there is on the left than on the right (sum of the side sonars' ranges).
Behavior<double> roomOnLeft(const Robot& r) {
  return lift(
      [](const std::vector<double>& range) {
        double left = 0.0, right = 0.0;
        for (int i = 1; i <= 7; ++i) left += range[i], right += range[16 - i];
        return left - right;
      },
      sonars(r));
}

// Drive ahead until a bumper is pressed; say whether the left has more room then.
Task<Wheels, bool> goAhead() {
  return mkTask([](const TaskState& ts) {
    const Robot& r = ts.robot();
    Event<bool> bumped = snapshot(bumper(r), roomOnLeft(r)).map([](const auto& p) { return p.second > 0; });
    return std::pair{wheels(0.5, 0.0), bumped};
  });
}

// Back off for a second.
Task<Wheels> backOff() {
  return mkTask([](const TaskState&) { return std::pair{wheels(-0.2, 0.0), after(1.0)}; });
}

// Turn for `seconds`, then on until the front sonars read more than 2 m (at most 6 s more).
Task<Wheels> turnFor(bool left, double seconds) {
  return mkTask([left, seconds](const TaskState&) { return std::pair{wheels(0, left ? 1.0 : -1.0), after(seconds)}; });
}
Task<Wheels> turnUntilOpen(bool left) {
  return mkTask([left](const TaskState& ts) {
    const Robot& r = ts.robot();
    auto ahead = min(min(sonar(r, 15), sonar(r, 0)), sonar(r, 1));
    return std::pair{wheels(0, left ? 1.0 : -1.0), predicate(ahead > 2.0) | after(6.0)};
  });
}

Task<Wheels> runAround() {
  for (int k = 1;; ++k) {
    bool left = co_await goAhead();
    co_await backOff();
    co_await turnFor(left, 0.5 + 1.5 * (k * 0.618034 - std::floor(k * 0.618034)));
    co_await turnUntilOpen(left);
  }
}

FROB_CONTROLLER(runAround, .world = "assignments/wander/worlds/living_room.toml", .seconds = 120)
