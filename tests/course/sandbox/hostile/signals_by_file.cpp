// Asks for SIGIO on its stdout to go to its parent, half a second into the run: a signal sent to
// another process through a file, where Landlock cannot scope signals.
#include "misbehave.hpp"
#include <fcntl.h>
#include <unistd.h>
Behavior<Wheels> signalsByFile(const Robot&) {
  return misbehaveFrom(0.5, [] { (void)::fcntl(1, F_SETOWN, ::getppid()); });
}
FROB_CONTROLLER(signalsByFile)
