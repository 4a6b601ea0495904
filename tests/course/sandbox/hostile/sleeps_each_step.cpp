// From half a second on, sleeps 0.9 s in every step: each answer comes just inside the step's
// deadline, so only a deadline that follows the run's simulated time stops it.
#include "misbehave.hpp"

#include <time.h>
Behavior<Wheels> sleepsEachStep(const Robot&) {
  return misbehaveFrom(0.5, [] {
    const timespec nap{0, 900'000'000};
    ::nanosleep(&nap, nullptr);
  });
}
FROB_CONTROLLER(sleepsEachStep)
