#include "model.hpp"

#include <assimp/Importer.hpp>

#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <filesystem>

namespace frob::render::detail {

Result<Mesh> loadModel(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    return Status::failure("render: robot model '" + path + "' does not exist (set RenderDef::robotModelFile)");
  }
  Assimp::Importer importer;
  const aiScene* scene = importer.ReadFile(path, aiProcess_Triangulate);
  if (scene == nullptr || scene->mRootNode == nullptr) {
    return Status::failure("render: cannot load robot model '" + path + "': " + importer.GetErrorString());
  }
  Mesh mesh;
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    const aiMesh* am = scene->mMeshes[m];
    Color col = gray;
    bool tint = false;
    if (am->mMaterialIndex < scene->mNumMaterials) {
      const aiMaterial* mat = scene->mMaterials[am->mMaterialIndex];
      aiColor3D kd(0.5f, 0.5f, 0.5f);
      if (mat->Get(AI_MATKEY_COLOR_DIFFUSE, kd) == aiReturn_SUCCESS) col = {kd.r, kd.g, kd.b, 1.0f};
      tint = mat->GetName() == aiString("body");
    }
    for (unsigned f = 0; f < am->mNumFaces; ++f) {
      const aiFace& face = am->mFaces[f];
      if (face.mNumIndices != 3) continue;  // points and lines left by triangulation
      for (unsigned k = 0; k < 3; ++k) {
        const aiVector3D& v = am->mVertices[face.mIndices[k]];
        mesh.corners.emplace_back(v.x, v.y, v.z);
      }
      mesh.colors.push_back(col);
      mesh.tinted.push_back(tint);
    }
  }
  if (mesh.colors.empty()) return Status::failure("render: robot model '" + path + "' has no triangles");
  return mesh;
}

}  // namespace frob::render::detail
