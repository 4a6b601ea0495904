// Commands a NaN forward speed half a second into the run.
#include "misbehave.hpp"
#include <limits>
Behavior<Wheels> commandsNan(const Robot&) {
  return toBehavior(lift([](double now) { return Wheels{now < 0.5 ? 0.1 : std::numeric_limits<double>::quiet_NaN(), 0.0}; }, time()));
}
FROB_CONTROLLER(commandsNan)
