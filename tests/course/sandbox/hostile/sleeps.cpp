// Sleeps for a minute in one step half a second into the run.
#include "misbehave.hpp"
#include <unistd.h>
Behavior<Wheels> sleeps(const Robot&) { return misbehaveFrom(0.5, [] { ::sleep(60); }); }
FROB_CONTROLLER(sleeps)
