// Calls abort() half a second into the run.
#include "misbehave.hpp"
#include <cstdlib>
Behavior<Wheels> aborts(const Robot&) { return misbehaveFrom(0.5, [] { std::abort(); }); }
FROB_CONTROLLER(aborts)
