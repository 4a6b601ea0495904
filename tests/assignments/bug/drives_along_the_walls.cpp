// A cheat's submission for "bug": no sensing at all. It drives by odometry round the field's edge,
// along the left wall and the top wall, where generated fields used to keep a free margin. Each
// field now has a spur from the left wall and one from the bottom wall beside the start, so it
// meets a wall on either way round.
#include <frob/frob.hpp>

#include <utility>

using namespace frob;
using namespace frob::literals;

// Face `p`, then drive at it by odometry until within 5 cm.
Task<Wheels> driveBlindTo(Point2 p) {
  return mkTask([p](const TaskState& ts) {
    const Robot& r = ts.robot();
    Behavior<double> error = wrapAngle(heading(p - place(r)) - orientation(r));
    Behavior<double> left = distance(place(r), p);
    return std::pair{wheels(min(0.5, left) * max(cos(error), 0.0), clamp(2.0 * error, -1.0, 1.0)), predicate(left < 5_cm)};
  });
}

Task<Wheels> alongTheWalls() {
  for (Point2 p : {Point2{0.5, 1.5}, Point2{0.5, 14.5}, Point2{13.5, 14.5}, Point2{13.5, 13.5}}) co_await driveBlindTo(p);
}

FROB_CONTROLLER(alongTheWalls, .world = "assignments/bug/worlds/field.toml", .seconds = 120, .summary = "drive round the edge, blind")
