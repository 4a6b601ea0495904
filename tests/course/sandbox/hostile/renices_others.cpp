// Half a second into the run, sets every process of its user (a classmate's host runs as the same
// unprivileged user) to the lowest priority.
#include "misbehave.hpp"

#include <sys/resource.h>
Behavior<Wheels> renicesOthers(const Robot&) {
  return misbehaveFrom(0.5, [] { (void)::setpriority(PRIO_USER, 0, 19); });
}
FROB_CONTROLLER(renicesOthers)
