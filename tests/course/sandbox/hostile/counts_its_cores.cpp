// Drives at 1 cm/s for each core it may run on: what the run's placement of hosts left it.
#include "misbehave.hpp"

#include <sched.h>

Behavior<Wheels> countsItsCores(const Robot&) {
  return toBehavior(lift(
      [](double) {
        cpu_set_t mine;
        CPU_ZERO(&mine);
        const int cores = ::sched_getaffinity(0, sizeof mine, &mine) == 0 ? CPU_COUNT(&mine) : 0;
        return Wheels{0.01 * cores, 0.0};
      },
      time()));
}
FROB_CONTROLLER(countsItsCores)
