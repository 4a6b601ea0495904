// The controller: `frob run wander.cpp --video wander.mp4`.
#include "wander.hpp"

FROB_CONTROLLER(wander::wander, .world = "empty", .seconds = 60)
