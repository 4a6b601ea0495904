#pragma once
// The 3D chase view: a perspective camera behind and above one robot, walls extruded.

#include "draw.hpp"
#include "model.hpp"

#include <Eigen/Core>

namespace frob::render::detail {

struct ChaseLayers {
  Canvas ground;             // floor decals (grid, paths, sonar, pictures), 3D at z = 0, drawn in order
  Canvas solid;              // walls, obstacles and robots, drawn with the depth test
  Eigen::Matrix4d viewProj;  // world to clip space
};

// Fills `layers` for `scene` seen in viewport `vp`; labels are projected and drawn into `overlay`.
void buildChase(ChaseLayers& layers, Canvas& overlay, const FontAtlas& fonts, const RenderDef& def, const FrameScene& scene, const Mesh& robot,
                const Viewport& vp);

}  // namespace frob::render::detail
