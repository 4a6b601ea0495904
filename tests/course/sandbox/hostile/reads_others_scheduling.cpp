// Reads what the kernel shows of another process's scheduling (here the grader's, its parent), a
// channel between two hosts that set their own; drives at 0.3 m/s if it could, 0.1 m/s if not. It
// also takes a lock on a file every host may read, which another host would see.
#include "misbehave.hpp"

#include <fcntl.h>
#include <sched.h>
#include <sys/file.h>
#include <sys/resource.h>
#include <unistd.h>

#include <cerrno>
Behavior<Wheels> readsOthersScheduling(const Robot&) {
  return toBehavior(lift(
      [](double) {
        cpu_set_t cores;
        errno = 0;
        const int priority = ::getpriority(PRIO_PROCESS, static_cast<id_t>(::getppid()));
        const bool read = (priority != -1 || errno == 0) || ::sched_getaffinity(::getppid(), sizeof cores, &cores) == 0;
        const int fd = ::open("/etc/ld.so.cache", O_RDONLY);
        const bool locked = fd >= 0 && ::flock(fd, LOCK_SH | LOCK_NB) == 0;
        if (fd >= 0) ::close(fd);
        return Wheels{read ? 0.3 : 0.1, locked ? 0.5 : 0.0};
      },
      time()));
}
FROB_CONTROLLER(readsOthersScheduling)
