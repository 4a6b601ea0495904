// Drives at its user id and turns at its group id, in millionths: whom the sandbox made it.
#include "misbehave.hpp"

#include <unistd.h>

Behavior<Wheels> tellsItsUser(const Robot&) {
  return toBehavior(lift([](double) { return Wheels{1e-6 * ::getuid(), 1e-6 * ::getgid()}; }, time()));
}
FROB_CONTROLLER(tellsItsUser)
