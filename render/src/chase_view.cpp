// The chase view: ground decals from the top-down pass lifted into 3D, extruded walls, robot meshes.
#include "chase_view.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace frob::render::detail {

namespace {

using V3 = Eigen::Vector3d;

// Lambert shading with a fixed light from above and behind the default camera.
Rgba8 shade(const Color& c, const V3& a, const V3& b, const V3& d) {
  static const V3 light = V3(-0.35, -0.45, 0.82).normalized();
  const V3 n = (b - a).cross(d - a);
  const double len = n.norm();
  const double lambert = len > 0 ? std::abs(n.dot(light)) / len : 1.0;
  const double k = 0.45 + 0.55 * lambert;
  return rgba8({static_cast<float>(c.r * k), static_cast<float>(c.g * k), static_cast<float>(c.b * k), c.a});
}

void tri(Canvas& c, const Color& col, const V3& a, const V3& b, const V3& d) { c.triangle3(a, b, d, shade(col, a, b, d)); }

// A vertical prism over a convex footprint (counter-clockwise), from z0 to z1.
void prism(Canvas& c, const std::vector<Point2>& foot, double z0, double z1, const Color& col) {
  const std::size_t n = foot.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Point2& p = foot[i];
    const Point2& q = foot[(i + 1) % n];
    const V3 a(p.x(), p.y(), z0), b(q.x(), q.y(), z0), e(q.x(), q.y(), z1), f(p.x(), p.y(), z1);
    tri(c, col, a, b, e);
    tri(c, col, a, e, f);
  }
  for (std::size_t i = 1; i + 1 < n; ++i) {
    tri(c, col, V3(foot[0].x(), foot[0].y(), z1), V3(foot[i].x(), foot[i].y(), z1), V3(foot[i + 1].x(), foot[i + 1].y(), z1));
  }
}

Eigen::Matrix4d lookAt(const V3& eye, const V3& target, const V3& up) {
  const V3 f = (target - eye).normalized();
  const V3 s = f.cross(up).normalized();
  const V3 u = s.cross(f);
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.block<1, 3>(0, 0) = s.transpose();
  m.block<1, 3>(1, 0) = u.transpose();
  m.block<1, 3>(2, 0) = -f.transpose();
  m(0, 3) = -s.dot(eye);
  m(1, 3) = -u.dot(eye);
  m(2, 3) = f.dot(eye);
  return m;
}

Eigen::Matrix4d perspective(double fovy, double aspect, double zNear, double zFar) {
  const double t = 1.0 / std::tan(fovy / 2);
  Eigen::Matrix4d m = Eigen::Matrix4d::Zero();
  m(0, 0) = t / aspect;
  m(1, 1) = t;
  m(2, 2) = (zFar + zNear) / (zNear - zFar);
  m(2, 3) = 2 * zFar * zNear / (zNear - zFar);
  m(3, 2) = -1;
  return m;
}

}  // namespace

void buildChase(ChaseLayers& layers, Canvas& overlay, const FontAtlas& fonts, const RenderDef& def, const FrameScene& scene, const Mesh& robot,
                const Viewport& vp) {
  // Camera: behind and above the followed robot, looking a little ahead of it. With no robot,
  // from the south of the world looking at its centre.
  V3 eye, target;
  const Point2 centre = (scene.bounds.min + scene.bounds.max) / 2;
  if (def.chaseRobot >= 0 && static_cast<std::size_t>(def.chaseRobot) < scene.robots.size()) {
    const Pose2& p = scene.robots[static_cast<std::size_t>(def.chaseRobot)].pose;
    const Vec2 u = unitVector(p.heading);
    eye = V3(p.position.x() - 1.8 * u.x(), p.position.y() - 1.8 * u.y(), 1.4);
    target = V3(p.position.x() + 1.0 * u.x(), p.position.y() + 1.0 * u.y(), 0.0);
  } else {
    const double size = (scene.bounds.max - scene.bounds.min).norm();
    eye = V3(centre.x(), centre.y() - size * 0.8, size * 0.7);
    target = V3(centre.x(), centre.y(), 0.0);
  }
  layers.viewProj = perspective(55.0 * pi / 180.0, vp.w / std::max(vp.h, 1.0), 0.05, 200.0) * lookAt(eye, target, V3(0, 0, 1));

  // Labels are projected to the screen and drawn flat, so they stay legible.
  const Eigen::Matrix4d vpm = layers.viewProj;
  const TextSink text = [&](const Point2& at, const std::string& s, Color col) {
    const Eigen::Vector4d clip = vpm * Eigen::Vector4d(at.x(), at.y(), 0.02, 1.0);
    if (clip.w() <= 0.05) return;  // behind the camera
    const double x = vp.x + (clip.x() / clip.w() + 1) / 2 * vp.w, y = vp.y + (1 - clip.y() / clip.w()) / 2 * vp.h;
    if (x < vp.x - 200 || x > vp.x + vp.w || y < vp.y || y > vp.y + vp.h + 20) return;
    fonts.draw(overlay, Font::Sans, {x, y}, s, rgba8(col));
  };

  // Ground: the top-down pass in metres (canvas y = -world y), then lifted to z = 0.
  layers.ground.clear();
  drawGround(layers.ground, fonts, def, scene, Mapping{.origin = Vec2(0, 0), .scale = 1.0, .pixel = 0.01}, false, text);

  layers.solid.clear();
  Canvas& c = layers.solid;
  for (const Wall& w : scene.walls) {
    const Vec2 d = (w.b - w.a).normalized() * w.thickness / 2, n(-d.y(), d.x());
    if (!std::isfinite(d.x())) continue;
    prism(c, {w.a - d - n, w.b + d - n, w.b + d + n, w.a - d + n}, 0.0, def.wallHeight, palette::wall);
  }
  for (const Block& k : scene.blocks) {
    const Vec2 u = unitVector(k.angle), v(-u.y(), u.x());
    const Vec2 ex = u * k.halfExtents.x(), ey = v * k.halfExtents.y();
    prism(c, {k.center - ex - ey, k.center + ex - ey, k.center + ex + ey, k.center - ex + ey}, 0.0, def.wallHeight, palette::obstacle);
  }
  for (const Pillar& p : scene.pillars) {
    std::vector<Point2> foot;
    for (int i = 0; i < 16; ++i) foot.push_back(p.center + p.radius * unitVector(2 * pi * i / 16));
    prism(c, foot, 0.0, def.wallHeight, palette::obstacle);
  }
  for (std::size_t ri = 0; ri < scene.robots.size(); ++ri) {
    const RobotView& r = scene.robots[ri];
    const Color body = palette::robot(r, ri);
    const double s = r.spec.radius, ch = std::cos(r.pose.heading), sh = std::sin(r.pose.heading);
    auto place = [&](const V3& v) {
      return V3(r.pose.position.x() + s * (ch * v.x() - sh * v.y()), r.pose.position.y() + s * (sh * v.x() + ch * v.y()), s * v.z());
    };
    for (std::size_t t = 0; t < robot.colors.size(); ++t) {
      tri(c, robot.tinted[t] ? body : robot.colors[t], place(robot.corners[3 * t]), place(robot.corners[3 * t + 1]), place(robot.corners[3 * t + 2]));
    }
  }
}

}  // namespace frob::render::detail
