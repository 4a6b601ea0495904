// libFuzzer target for the world loader (built with -DFROB_FUZZ=ON and clang): any bytes must give
// either a valid world or a message naming the file, never a crash, a hang or a leak. A valid world
// must also build and step in the simulator.
#include "frob/worlds/registry.hpp"
#include "frob/worlds/simulation.hpp"
#include "frob/worlds/world_file.hpp"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string_view>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace frob::worlds;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  // Map paths resolve against the reference worlds' folder, so seeds that name office.png load it.
  const frob::Result<WorldDef> w = parseWorld(text, "fuzz.toml", worldDataDir());
  if (!w.ok()) {
    if (w.error().rfind("fuzz.toml", 0) != 0) {  // every message starts with the file name
      std::fprintf(stderr, "message without the file name: %s\n", w.error().c_str());
      std::abort();
    }
    return 0;
  }
  if (const frob::Status s = checkWorld(*w); !s) {
    std::fprintf(stderr, "loaded a world that fails its own check: %s\n", s.error().c_str());
    std::abort();
  }
  // Small enough worlds are also simulated for a few steps.
  if (w->robots.size() <= 16 && w->walls.size() <= 4000) {
    Simulation sim(*w);
    const std::vector<frob::Wheels> wheels(sim.robotCount(), frob::Wheels{.forward = 0.5, .turn = 0.3});
    for (int k = 0; k < 3; ++k) {
      sim.sense();
      sim.step(wheels);
    }
  }
  return 0;
}
