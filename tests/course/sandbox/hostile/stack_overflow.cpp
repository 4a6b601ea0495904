// Recurses without end half a second into the run.
#include "misbehave.hpp"
int deeper(int n) {
  volatile char frame[256] = {};
  frame[n % 256] = 1;
  return deeper(n + frame[(n + 1) % 256]) + frame[n % 256];
}
Behavior<Wheels> stackOverflow(const Robot&) { return misbehaveFrom(0.5, [] { deeper(1); }); }
FROB_CONTROLLER(stackOverflow)
