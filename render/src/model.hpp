#pragma once
// A robot mesh loaded with assimp: flat triangles with a colour each.

#include "frob/base/result.hpp"
#include "frob/picture.hpp"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace frob::render::detail {

struct Mesh {
  std::vector<Eigen::Vector3d> corners;  // three per triangle; unit body radius, x forward, z up
  std::vector<Color> colors;             // one per triangle
  std::vector<bool> tinted;              // per triangle: takes the robot's colour (material "body")
};

// Loads `path` (any format assimp reads). Fails with the file named when missing, unreadable or empty.
[[nodiscard]] Result<Mesh> loadModel(const std::string& path);

}  // namespace frob::render::detail
