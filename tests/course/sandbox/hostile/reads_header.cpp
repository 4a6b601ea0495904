// Maps the memory it shares with the grader (fd 3) and drives at a speed drawn from the header's
// settled fields (its first 64 bytes, before the first doorbell): were any of them to differ
// between kinds of run (graded alone, in a class, filmed), it would drive differently in each.
#include "misbehave.hpp"

#include <sys/mman.h>

#include <cstdint>

Behavior<Wheels> readsHeader(const Robot&) {
  return toBehavior(lift(
      [](double) {
        static double speed = -1.0;
        if (speed < 0) {
          void* page = ::mmap(nullptr, 4096, PROT_READ, MAP_SHARED, 3, 0);
          std::uint64_t hash = 1469598103934665603ULL;  // FNV-1a over the 64 bytes
          if (page != MAP_FAILED) {
            for (int i = 0; i < 64; ++i) hash = (hash ^ static_cast<const unsigned char*>(page)[i]) * 1099511628211ULL;
            ::munmap(page, 4096);
          }
          speed = page == MAP_FAILED ? 0.0 : 0.05 + 0.01 * static_cast<double>(hash % 16);
        }
        return Wheels{speed, 0.0};
      },
      time()));
}
FROB_CONTROLLER(readsHeader)
