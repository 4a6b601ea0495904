// Half a second into the run, cuts the memory it shares with the grader (fd 3) to nothing: unsealed,
// the grader would die of SIGBUS at its next read of the channel.
#include "misbehave.hpp"

#include <unistd.h>
Behavior<Wheels> truncatesChannel(const Robot&) {
  return misbehaveFrom(0.5, [] { (void)::ftruncate(3, 0); });
}
FROB_CONTROLLER(truncatesChannel)
