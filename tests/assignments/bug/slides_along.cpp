// A cheat's submission for "bug": no BUG at all. It steers at the goal by odometry alone and never
// looks: where an obstacle is in the way it pushes against it and slides round its curve. Where
// the obstacles are round and the way is open enough, it gets there on a short path; the BUG1
// bound asks for a path round the obstacles, not through them, so touching fails it.
#include <frob/frob.hpp>

using namespace frob;
using namespace frob::literals;

const Point2 kGoal{13.5, 13.5};

Task<Wheels> pushOn() {
  return mkTask([](const TaskState& ts) {
    const Robot& r = ts.robot();
    Behavior<double> error = wrapAngle(heading(kGoal - place(r)) - orientation(r));
    Behavior<double> left = distance(place(r), kGoal);
    return std::pair{wheels(min(0.5, left), clamp(2.0 * error, -1.0, 1.0)), predicate(left < 5_cm)};
  });
}

FROB_CONTROLLER(pushOn, .world = "assignments/bug/worlds/field.toml", .seconds = 120, .summary = "steer at the goal, push through")
