// Half a second into the run, writes 15 MB files (each under the 16 MB file limit) into its working
// folder until a write fails, and drives at a speed that says how many megabytes it wrote (1 cm/s
// each). Without a bound on the whole folder it would fill the disk.
#include "misbehave.hpp"

#include <cstdio>
#include <string>
#include <vector>
Behavior<Wheels> fillsScratch(const Robot&) {
  return toBehavior(lift(
      [written = std::make_shared<int>(-1)](double now) {
        if (now >= 0.5 && *written < 0) {
          const std::vector<char> chunk(1 << 20, 'x');
          *written = 0;
          for (int file = 0; file < 64; ++file) {
            FILE* f = std::fopen(("fill" + std::to_string(file)).c_str(), "wb");
            if (f == nullptr) break;
            int mb = 0;
            while (mb < 15 && std::fwrite(chunk.data(), 1, chunk.size(), f) == chunk.size() && std::fflush(f) == 0) ++mb;
            std::fclose(f);
            *written += mb;
            if (mb < 15) break;
          }
        }
        return Wheels{0.01 * std::max(*written, 0), 0.0};
      },
      time()));
}
FROB_CONTROLLER(fillsScratch)
