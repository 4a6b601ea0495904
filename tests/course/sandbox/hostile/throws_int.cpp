// Throws an int (not a std::exception) half a second into the run.
#include "misbehave.hpp"
Behavior<Wheels> throwsInt(const Robot&) { return misbehaveFrom(0.5, [] { throw 42; }); }
FROB_CONTROLLER(throwsInt)
