#pragma once
/// The one registry of reference worlds, shared by the app, tests and benchmarks.

#include "frob/worlds/world_file.hpp"

#include <filesystem>
#include <span>
#include <string_view>

namespace frob::worlds {

/// A reference world: its name, its file under worldDataDir(), and one line saying what it is.
struct WorldEntry {
  std::string_view name;         ///< short name, e.g. "maze"
  std::string_view file;         ///< file name relative to worldDataDir()
  std::string_view description;  ///< one line for `frob list`
};

/// Every reference world, in a fixed order.
[[nodiscard]] std::span<const WorldEntry> referenceWorlds();
/// The reference world called `name`, or nullptr.
[[nodiscard]] const WorldEntry* findWorld(std::string_view name);
/// Absolute folder of the world files (set by CMake from the source tree).
[[nodiscard]] std::filesystem::path worldDataDir();
/// Absolute path of `entry`'s file.
[[nodiscard]] std::filesystem::path worldPath(const WorldEntry& entry);
/// Loads the reference world called `name` (an error names it when there is none).
[[nodiscard]] Result<WorldDef> loadReferenceWorld(std::string_view name);

}  // namespace frob::worlds
