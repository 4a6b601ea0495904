#pragma once
// What the controller host's tests share: a host started on modules, a room to run in, and a
// hostile submission's run with what became of it.
#include "../sandbox/hostile.hpp"
#include "frob/run/host.hpp"
#include "frob/worlds/run.hpp"
#include "frob/worlds/world_file.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace frob::course {

inline std::shared_ptr<ControllerHost> startHost(const std::vector<std::filesystem::path>& modules, HostDef def = {}) {
  std::vector<std::string> sources;
  for (const std::filesystem::path& m : modules) sources.push_back(m.stem().string());
  Result<std::shared_ptr<ControllerHost>> host = ControllerHost::start(modules, sources, std::move(def));
  EXPECT_TRUE(host.ok()) << host.error();
  return host.ok() ? host.value() : nullptr;
}

// A 4 x 3 m room with one to four robots.
inline worlds::WorldDef room(int robots = 1) {
  std::string text = "size = [4.0, 3.0]\nseed = 7\n[[robot]]\nname = \"ada\"\nstart = [1.0, 1.0]\n";
  if (robots >= 2) text += "[[robot]]\nname = \"bob\"\nstart = [3.0, 2.0]\nheading_deg = 180\n";
  if (robots >= 3) text += "[[robot]]\nname = \"cy\"\nstart = [1.0, 2.0]\n";
  if (robots >= 4) text += "[[robot]]\nname = \"di\"\nstart = [3.0, 1.0]\nheading_deg = 180\n";
  return *worlds::parseWorld(text, "room.toml");
}

// What became of a hostile submission run for at most two simulated seconds.
struct Outcome {
  std::string startError;                           // why the host could not start, if it could not
  std::vector<worlds::ControllerFailure> failures;  // as the run reports them
  std::string output;                               // what it printed, as passed on
  std::vector<std::string> notes;
  Wheels lastWheels;
  std::vector<sandbox::Layer> layers;
};

inline Outcome runHostile(const std::vector<std::string>& names, HostDef def = {}) {
  Outcome o;
  def.output = [&o](std::string_view text) { o.output.append(text); };
  def.robots = static_cast<std::uint32_t>(names.size());
  std::vector<std::filesystem::path> modules;
  for (const std::string& n : names) modules.push_back(testing::hostileModule(n));
  Result<std::shared_ptr<ControllerHost>> host = ControllerHost::start(modules, names, std::move(def));
  if (!host) {
    o.startError = host.error();
    return o;
  }
  std::vector<std::size_t> modulePerRobot;
  for (std::size_t m = 0; m < names.size(); ++m) modulePerRobot.push_back(m);
  {
    worlds::Run run(room(static_cast<int>(names.size())), {}, host.value()->driver(modulePerRobot, true));
    while (run.failures().empty() && run.simulation().time() < 2.0) run.step();
    o.failures = run.failures();
    o.lastWheels = run.recorder().steps().back().robots[0].wheels;
  }
  o.notes = host.value()->notes();
  o.layers = host.value()->layers();
  return o;
}

}  // namespace frob::course
