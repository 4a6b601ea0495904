// Reads the machine's count of threads through sysinfo, a channel between two hosts (one starts
// threads, the other sees the count move), and its uptime and load; drives at 0.1 m/s if what it
// read is the sandbox's fixed answer, 0.3 m/s if it is the machine's.
#include "misbehave.hpp"

#include <sys/sysinfo.h>

Behavior<Wheels> countsThreadsBySysinfo(const Robot&) {
  return toBehavior(lift(
      [](double) {
        struct sysinfo s {};
        const bool fixed = ::sysinfo(&s) == 0 && s.procs == 1 && s.uptime == 0 && s.loads[0] == 0 && s.totalram == 4UL << 30;
        return Wheels{fixed ? 0.1 : 0.3, 0.0};
      },
      time()));
}
FROB_CONTROLLER(countsThreadsBySysinfo)
