#pragma once
/// World files: TOML text people write, read and diff, loaded into a WorldDef. The format is
/// described in worlds/data/README.md. Errors name the file, the line and the field, e.g.
/// `maze.toml:12: wall[3].from: expected [x, y]`; nothing throws.

#include "frob/worlds/world_def.hpp"

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace frob::worlds {

/// Either a value or a readable message saying why there is none.
template <class T>
struct Loaded {
  std::optional<T> value;  ///< set on success
  std::string error;       ///< set on failure: "file:line: field: what is wrong"
  /// True when a value was loaded.
  [[nodiscard]] bool ok() const { return value.has_value(); }
  /// True when a value was loaded.
  explicit operator bool() const { return ok(); }
  /// The value; only when ok().
  [[nodiscard]] const T& operator*() const { return *value; }
  /// The value; only when ok().
  [[nodiscard]] const T* operator->() const { return &*value; }
};

/// Loads the world file at `path`. Paths inside it (bitmap, mesh) resolve relative to its folder.
[[nodiscard]] Loaded<WorldDef> loadWorld(const std::filesystem::path& path);
/// Parses world-file text; `fileName` is used in messages and `baseDir` resolves bitmap and mesh paths.
[[nodiscard]] Loaded<WorldDef> parseWorld(std::string_view text, std::string_view fileName,
                                          const std::filesystem::path& baseDir = {});

}  // namespace frob::worlds
