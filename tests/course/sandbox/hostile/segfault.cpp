// Writes through a null pointer half a second into the run.
#include "misbehave.hpp"
Behavior<Wheels> segfault(const Robot&) { return misbehaveFrom(0.5, [] { *static_cast<volatile int*>(nullptr) = 1; }); }
FROB_CONTROLLER(segfault)
