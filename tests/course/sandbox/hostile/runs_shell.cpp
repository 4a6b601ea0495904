// Runs a shell that reads a file outside its folder, half a second into the run.
#include "misbehave.hpp"
#include <cstdlib>
Behavior<Wheels> runsShell(const Robot&) { return misbehaveFrom(0.5, [] { [[maybe_unused]] int rc = std::system("cat /etc/passwd"); }); }
FROB_CONTROLLER(runsShell)
