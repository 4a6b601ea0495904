// Mesh maps: any model assimp reads, sliced by a horizontal plane at sonar height into thin walls.
#include "frob/worlds/maps.hpp"

#include <assimp/Importer.hpp>

#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>

namespace frob::worlds {

Result<std::vector<WallDef>> wallsFromMesh(const std::filesystem::path& file, const MeshDef& def) {
  const std::string name = file.filename().string();
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec)) return Status::failure(name + ": no such mesh file");
  Assimp::Importer importer;
  const aiScene* scene = importer.ReadFile(file.string(), aiProcess_Triangulate | aiProcess_PreTransformVertices | aiProcess_JoinIdenticalVertices);
  if (!scene || !scene->mRootNode) return Status::failure(name + ": cannot read the mesh (" + importer.GetErrorString() + ")");

  std::vector<WallDef> walls;
  double lowest = INFINITY, highest = -INFINITY;
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    const aiMesh* mesh = scene->mMeshes[m];
    // Mesh vertex -> (world x, world y, height above the floor), metres.
    auto vertex = [&](unsigned i) {
      const aiVector3D& v = mesh->mVertices[i];
      const double x = v.x * def.scale, y = (def.yUp ? -v.z : v.y) * def.scale, up = (def.yUp ? v.y : v.z) * def.scale;
      return std::array<double, 3>{x + def.origin.x(), y + def.origin.y(), up};
    };
    for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
      const aiFace& face = mesh->mFaces[f];
      if (face.mNumIndices != 3) continue;  // points and lines have no area to slice
      std::array<std::array<double, 3>, 3> p{};
      bool valid = true;
      for (int k = 0; k < 3; ++k) {
        if (face.mIndices[k] >= mesh->mNumVertices)
          valid = false;
        else
          p[k] = vertex(face.mIndices[k]);
      }
      if (!valid) continue;
      // Where each edge crosses the plane; a vertex exactly on the plane counts as above it.
      std::vector<Point2> cut;
      for (int k = 0; k < 3; ++k) {
        const auto& a = p[k];
        const auto& b = p[(k + 1) % 3];
        lowest = std::min(lowest, a[2]);
        highest = std::max(highest, a[2]);
        const double da = a[2] - def.height, db = b[2] - def.height;
        if ((da >= 0) == (db >= 0)) continue;
        const double t = da / (da - db);
        cut.emplace_back(a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]));
      }
      if (cut.size() == 2 && (cut[1] - cut[0]).norm() >= 1e-3 && std::isfinite(cut[0].sum() + cut[1].sum()))
        walls.push_back(segmentWall(cut[0], cut[1]));
    }
  }
  if (walls.empty()) {
    std::ostringstream s;
    s << name << ": no geometry at height " << def.height << " m";
    if (std::isfinite(lowest)) s << " (the mesh spans heights " << lowest << " to " << highest << " m)";
    return Status::failure(s.str());
  }
  return std::move(walls);
}

}  // namespace frob::worlds
