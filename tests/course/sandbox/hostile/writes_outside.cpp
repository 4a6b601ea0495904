// Writes a file in /tmp (outside its scratch folder) half a second into the run.
#include "misbehave.hpp"
#include <cstdio>
Behavior<Wheels> writesOutside(const Robot&) {
  return misbehaveFrom(0.5, [] {
    if (std::FILE* f = std::fopen("/tmp/frob-hostile-was-here", "w")) std::fclose(f);
  });
}
FROB_CONTROLLER(writesOutside)
