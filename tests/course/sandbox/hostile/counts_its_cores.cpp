// Drives at 1 cm/s for each core it may run on, and turns at 1 mrad/s for the number of the first
// plus one: what the run's placement of hosts left it.
#include "misbehave.hpp"

#include <sched.h>

Behavior<Wheels> countsItsCores(const Robot&) {
  return toBehavior(lift(
      [](double) {
        cpu_set_t mine;
        CPU_ZERO(&mine);
        if (::sched_getaffinity(0, sizeof mine, &mine) != 0) return Wheels{0.0, 0.0};
        int first = 0;
        while (first < CPU_SETSIZE && !CPU_ISSET(first, &mine)) ++first;
        return Wheels{0.01 * CPU_COUNT(&mine), 0.001 * (first + 1)};
      },
      time()));
}
FROB_CONTROLLER(countsItsCores)
