// Writes 4 MB to stdout in each of its first 20 steps (80 MB), then drives on quietly.
#include "misbehave.hpp"
#include <cstdio>
#include <string>
Behavior<Wheels> floodsOutput(const Robot&) {
  return toBehavior(lift(
      [](double now) {
        static const std::string line(4 << 20, 'x');
        if (now < 0.2) std::fwrite(line.data(), 1, line.size(), stdout);
        return Wheels{0.1, 0.0};
      },
      time()));
}
FROB_CONTROLLER(floodsOutput)
