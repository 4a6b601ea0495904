// Waits forever for a bump that never comes, without moving: a run that looks stuck.
#include <frob/frob.hpp>

using namespace frob;

Task<Wheels> standStill() {
  co_await mkTask([](const TaskState& ts) { return std::pair{wheels(0, 0), bumper(ts.robot())}; });
}
FROB_CONTROLLER(standStill)
