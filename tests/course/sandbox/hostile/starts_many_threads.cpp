// Half a second into the run, starts threads that never end, on small stacks, until one cannot
// start, and drives at a speed that says how many started (1 mm/s each). Unbounded, they would
// take the machine's process table.
#include "misbehave.hpp"

#include <pthread.h>
#include <unistd.h>
Behavior<Wheels> startsManyThreads(const Robot&) {
  return toBehavior(lift(
      [started = std::make_shared<int>(-1)](double now) {
        if (now >= 0.5 && *started < 0) {
          pthread_attr_t small;
          pthread_attr_init(&small);
          pthread_attr_setstacksize(&small, 64 << 10);
          *started = 0;
          for (pthread_t t; *started < 3000 && pthread_create(
                                                   &t, &small,
                                                   [](void*) -> void* {
                                                     for (;;) ::pause();
                                                   },
                                                   nullptr) == 0;)
            ++*started;
        }
        return Wheels{0.001 * std::max(*started, 0), 0.0};
      },
      time()));
}
FROB_CONTROLLER(startsManyThreads)
