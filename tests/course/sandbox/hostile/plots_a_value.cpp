// Well-behaved: drives forward and plots its sonar 4 as "left" (withPlot), which reaches the trusted
// side with the pictures.
#include "misbehave.hpp"
Task<Wheels> plotsLeft() {
  TaskState ts = co_await getTaskState();
  co_await withPlot("left", sonar(ts.robot(), 4), mkTask([](const TaskState&) { return std::pair{wheels(0.2, 0.0), never<Unit>()}; }));
}
FROB_CONTROLLER(plotsLeft)
