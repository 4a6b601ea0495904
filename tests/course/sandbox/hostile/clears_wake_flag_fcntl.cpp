// Clears the non-blocking flag of the wake-up channel it shares with the grader with fcntl, and
// takes the grader's wake-ups (steals_wakeups.hpp).
#include "steals_wakeups.hpp"

#include <fcntl.h>
Behavior<Wheels> clearsWakeFlagFcntl(const Robot&) {
  return stealsWakeups([](int fd) { (void)::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK); });
}
FROB_CONTROLLER(clearsWakeFlagFcntl)
