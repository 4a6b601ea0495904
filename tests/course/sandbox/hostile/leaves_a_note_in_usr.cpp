// Reads a file of the system that no host needs, half a second into the run: the first read of a
// file whose access time is older than its change moves that time, a note a later host (another
// student's) could read with stat.
#include "misbehave.hpp"
#include <fstream>
Behavior<Wheels> leavesANoteInUsr(const Robot&) {
  return misbehaveFrom(0.5, [] {
    std::ifstream in("/usr/include/stdio.h");
    in.get();
  });
}
FROB_CONTROLLER(leavesANoteInUsr)
