// Sends SIGKILL to the process that started it (the grader) half a second into the run.
#include "misbehave.hpp"
#include <signal.h>
#include <unistd.h>
Behavior<Wheels> signalsParent(const Robot&) { return misbehaveFrom(0.5, [] { ::kill(::getppid(), SIGKILL); ::kill(1, SIGKILL); }); }
FROB_CONTROLLER(signalsParent)
