// Allocates (and touches) 64 MB at a time, for ever, half a second into the run.
#include "misbehave.hpp"
#include <cstring>
#include <vector>
Behavior<Wheels> memoryBomb(const Robot&) {
  return misbehaveFrom(0.5, [] {
    static std::vector<char*> kept;
    for (;;) {
      char* block = new char[64 << 20];
      std::memset(block, 1, 64 << 20);
      kept.push_back(block);
    }
  });
}
FROB_CONTROLLER(memoryBomb)
