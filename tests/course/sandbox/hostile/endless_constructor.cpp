// Loops for ever in a global constructor: before any controller is built.
#include "misbehave.hpp"
struct Spin {
  Spin() {
    for (volatile long i = 0;; i = i + 1) {
    }
  }
} spin;
Behavior<Wheels> endlessConstructor(const Robot&) { return Wheels{0.1, 0.0}; }
FROB_CONTROLLER(endlessConstructor)
