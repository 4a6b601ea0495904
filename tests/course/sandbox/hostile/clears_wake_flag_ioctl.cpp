// Clears the non-blocking flag of the wake-up channel it shares with the grader with
// ioctl(FIONBIO), and takes the grader's wake-ups (steals_wakeups.hpp).
#include "steals_wakeups.hpp"

#include <sys/ioctl.h>
Behavior<Wheels> clearsWakeFlagIoctl(const Robot&) {
  return stealsWakeups([](int fd) {
    int off = 0;
    (void)::ioctl(fd, FIONBIO, &off);
  });
}
FROB_CONTROLLER(clearsWakeFlagIoctl)
