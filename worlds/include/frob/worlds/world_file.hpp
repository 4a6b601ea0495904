#pragma once
/// World files: TOML text people write, read and diff, loaded into a WorldDef. The format is
/// described in worlds/data/README.md. Errors name the file, the line and the field, e.g.
/// `maze.toml:12: wall[3].from: expected [x, y]`; nothing throws.

#include "frob/base/result.hpp"
#include "frob/worlds/world_def.hpp"

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace frob::worlds {

/// Loads the world file at `path`. Paths inside it (bitmap, mesh) resolve relative to its folder.
[[nodiscard]] Result<WorldDef> loadWorld(const std::filesystem::path& path);
/// Parses world-file text; `fileName` is used in messages and `baseDir` resolves bitmap and mesh paths.
[[nodiscard]] Result<WorldDef> parseWorld(std::string_view text, std::string_view fileName, const std::filesystem::path& baseDir = {});

}  // namespace frob::worlds
