// Half a second into the run, asks to run on every core: in a class, its threads would spin on the
// core another run was given.
#include "misbehave.hpp"

#include <sched.h>

Behavior<Wheels> repinsItself(const Robot&) {
  return misbehaveFrom(0.5, [] {
    cpu_set_t every;
    CPU_ZERO(&every);
    for (int c = 0; c < CPU_SETSIZE; ++c) CPU_SET(c, &every);
    (void)::sched_setaffinity(0, sizeof every, &every);
  });
}
FROB_CONTROLLER(repinsItself)
