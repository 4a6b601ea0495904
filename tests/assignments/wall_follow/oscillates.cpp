// A typical wrong submission: a bang-bang wall follower. It turns left at full rate when the right
// sonar reads less than 40 cm (or a wall is near ahead) and right when it reads more, never slowing
// down. So it weaves along the wall instead of keeping its distance, and it cannot turn tightly
// enough at a concave corner: it bumps into the wall ahead.
#include <frob/frob.hpp>

using namespace frob;
using namespace frob::literals;

Task<Wheels> followRightWall() {
  return mkTask([](const TaskState& ts) {
    const Robot& r = ts.robot();
    auto ahead = min(min(sonar(r, 15), sonar(r, 0)), sonar(r, 1));
    // Too close (or a wall ahead): turn left; too far: turn right.
    auto turn = lift([](double right, double front) { return right < 0.4 || front < 0.6 ? 0.8 : -0.8; }, rightSonar(r), ahead);
    return std::pair{wheels(0.4, turn), never<Unit>()};
  });
}

FROB_CONTROLLER(followRightWall, .world = "assignments/wall_follow/worlds/l_room.toml", .seconds = 90)
