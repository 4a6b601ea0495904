// Closes its stdout and stderr half a second into the run, so that the pipe the grader reads them
// from hangs up, then sleeps for a minute in that step.
#include "misbehave.hpp"

#include <unistd.h>
Behavior<Wheels> closesOutput(const Robot&) {
  return misbehaveFrom(0.5, [] {
    ::close(1);
    ::close(2);
    ::sleep(60);
  });
}
FROB_CONTROLLER(closesOutput)
