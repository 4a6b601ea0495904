#pragma once
/// Walls from maps: a PNG floor plan whose dark pixels are walls, or a 3D mesh sliced at sonar height.

#include "frob/worlds/world_def.hpp"
#include "frob/worlds/world_file.hpp"

#include <filesystem>
#include <vector>

namespace frob::worlds {

/// How to read a bitmap floor plan. Pixel rows run from the top of the image (largest y) down.
struct BitmapDef {
  double scale = 0.05;             ///< metres per pixel
  Point2 origin = Point2::Zero();  ///< world position of the image's bottom-left corner, metres
  int threshold = 128;             ///< grey levels below this (0..255) are walls
};

/// How to slice a mesh (OBJ, STL, glTF, anything assimp reads) into wall segments.
struct MeshDef {
  double height = 0.3;             ///< slicing height above the floor, metres (the sonar ring's height)
  double scale = 1.0;              ///< mesh units to metres
  Point2 origin = Point2::Zero();  ///< world position of the mesh origin, metres
  bool yUp = false;                ///< the mesh's up axis is y (glTF convention) instead of z
};

/// The dark pixels of the PNG at `file`, merged greedily into few solid rectangles (as Stage does).
[[nodiscard]] Result<std::vector<WallDef>> wallsFromBitmap(const std::filesystem::path& file, const BitmapDef& def);
/// The mesh at `file` sliced by the horizontal plane at `def.height`: one thin wall per cut triangle.
[[nodiscard]] Result<std::vector<WallDef>> wallsFromMesh(const std::filesystem::path& file, const MeshDef& def);

}  // namespace frob::worlds
