#pragma once
// Test helper: small scenes are written inline as TOML in the test that uses them.

#include "frob/worlds/simulation.hpp"
#include "frob/worlds/world_file.hpp"

#include <gtest/gtest.h>

#include <string_view>
#include <vector>

namespace frob::worlds::testing {

// The world described by `toml`; fails the calling test (and returns an empty world) on an error.
inline WorldDef scene(std::string_view toml) {
  Result<WorldDef> w = parseWorld(toml, "scene.toml");
  EXPECT_TRUE(w.ok()) << w.error();
  return w.ok() ? *w : WorldDef{};
}

// The world described by `toml` with ideal robots: no wheel slip, no start spread and odometry
// without drift, for tests that check the physics or the sonars to the millimetre.
inline WorldDef ideal(std::string_view toml) {
  WorldDef w = scene(toml);
  for (RobotDef& r : w.robots) r.drive.slip = 0, r.startSpread = {0, 0}, r.odometry = {0, 0, 0};
  return w;
}

// Runs `steps` steps, every robot driven by the same `wheels`, sensing before each step.
inline void drive(Simulation& sim, int steps, Wheels wheels) {
  const std::vector<Wheels> all(sim.robotCount(), wheels);
  for (int k = 0; k < steps; ++k) {
    sim.sense();
    sim.step(all);
  }
}

}  // namespace frob::worlds::testing
