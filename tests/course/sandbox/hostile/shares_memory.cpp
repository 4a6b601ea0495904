// Makes a System V shared memory segment half a second into the run: a kernel object that would
// outlive the run and carry notes to the next one.
#include "misbehave.hpp"
#include <sys/shm.h>
Behavior<Wheels> sharesMemory(const Robot&) {
  return misbehaveFrom(0.5, [] { (void)::shmget(IPC_PRIVATE, 1 << 20, IPC_CREAT | 0600); });
}
FROB_CONTROLLER(sharesMemory)
