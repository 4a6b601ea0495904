// A typical wrong submission for go_to_goal: a route worked out by hand for the lounge.
//
// The student looked at worlds/lounge.toml and added via points that lead round its sofa, pillar
// and table, then drove from point to point with example 4's driveTo, without looking where it
// goes. It gets full marks in the lounge, and runs into the furniture of the hidden rooms, which
// has the same waypoints and other furniture: a controller cannot know the furniture, it must look.

#include <frob/frob.hpp>

#include <vector>

using namespace frob;
using namespace frob::literals;

constexpr double kSpeed = 0.6;

// The waypoints, with via points round the lounge's furniture between them.
const std::vector<Point2> kRoute = {
    {3.0, 2.5},                            // wp1
    {4.7, 3.9}, {4.7, 5.7},                // east of the sofa
    {3.5, 7.5},                            // wp2
    {5.2, 6.5}, {7.2, 6.5},                // south of the pillar
    {9.0, 7.0},                            // wp3
    {7.3, 5.6}, {7.3, 3.8},                // west of the table
    {8.5, 2.5},                            // wp4
};

Behavior<double> turnNeeded(const Robot& r, Point2 goal) { return wrapAngle(heading(goal - place(r)) - orientation(r)); }

Task<Wheels> driveTo(Point2 goal) {
  return mkTask([goal](const TaskState& ts) {
    const Robot& r = ts.robot();
    Behavior<double> angle = turnNeeded(r, goal);
    Behavior<double> left = distance(place(r), goal);
    auto forward = min(kSpeed, left) * max(cos(angle), 0.0);
    return std::pair{wheels(forward, clamp(2.0 * angle, -1.0, 1.0)), predicate(left < 10_cm)};
  });
}

Task<Wheels> followRoute() {
  for (const Point2& p : kRoute) co_await withPicture(paintAt(p, withColor(red, circle(20_cm))), driveTo(p));
}

FROB_CONTROLLER(followRoute, .world = "assignments/go_to_goal/worlds/lounge.toml", .seconds = 90)
