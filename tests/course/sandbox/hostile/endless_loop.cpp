// Loops for ever inside a behavior half a second into the run.
#include "misbehave.hpp"
Behavior<Wheels> endlessLoop(const Robot&) {
  return misbehaveFrom(0.5, [] {
    for (volatile long i = 0;; i = i + 1) {
    }
  });
}
FROB_CONTROLLER(endlessLoop)
