// Ends its program with exit status 127, what a loader says when the host program cannot load, in a
// global constructor: a controller's doing all the same, never frob's failure.
#include "misbehave.hpp"

#include <cstdlib>
static const int ended = (std::_Exit(127), 0);
Behavior<Wheels> exits127InConstructor(const Robot&) { return misbehaveFrom(0.5, [] {}); }
FROB_CONTROLLER(exits127InConstructor)
