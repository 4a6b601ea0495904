#pragma once
// Private: world checks that can name file and line when the world came from a file.

#include "frob/worlds/world_def.hpp"

#include <string>
#include <vector>

namespace frob::worlds::detail {

// Where each part of a world was written (1-based lines; 0 when unknown).
struct SourceLines {
  std::string file = "world";  // shown before every message
  int size = 0;
  std::vector<int> walls;  // one per WorldDef::walls entry
  std::vector<int> points;
  std::vector<int> robots;  // the line of each robot's start
  std::vector<int> keys;
};

// "file:line: " (or "file: " when the line is unknown).
[[nodiscard]] std::string where(const SourceLines& at, int line);
// Success when `w` is valid, else "file:line: field: what is wrong".
[[nodiscard]] Status checkWorld(const WorldDef& w, const SourceLines& at);
// Shortest distance from `p` to the segment a-b.
[[nodiscard]] double distanceToSegment(const Point2& p, const Point2& a, const Point2& b);

}  // namespace frob::worlds::detail
