// Starts a second process half a second into the run.
#include "misbehave.hpp"
#include <unistd.h>
Behavior<Wheels> forks(const Robot&) {
  return misbehaveFrom(0.5, [] {
    if (::fork() == 0) ::_exit(0);
  });
}
FROB_CONTROLLER(forks)
