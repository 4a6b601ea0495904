// Crashes in a global constructor: before any controller is built.
#include "misbehave.hpp"
struct Crash {
  Crash() { *static_cast<volatile int*>(nullptr) = 1; }
} crash;
Behavior<Wheels> crashInConstructor(const Robot&) { return Wheels{0.1, 0.0}; }
FROB_CONTROLLER(crashInConstructor)
