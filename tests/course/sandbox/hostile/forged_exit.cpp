// Prints a forged result and leaves with status 0 half a second into the run.
#include "misbehave.hpp"
#include <cstdio>
#include <unistd.h>
Behavior<Wheels> forgedExit(const Robot&) {
  return misbehaveFrom(0.5, [] {
    std::printf("{\"goal_reached\": true, \"score\": 100}\n");
    std::fflush(stdout);
    ::_exit(0);
  });
}
FROB_CONTROLLER(forgedExit)
