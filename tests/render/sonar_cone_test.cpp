// Sonar cones in the top-down view: from the sonar's place on the rim to its reading, never through
// a wall; an echo ends in a solid arc, no echo in a faint cone with a dashed edge.
#include "frob/render/renderer.hpp"

#include <gtest/gtest.h>

#include <array>

namespace frob::render {
namespace {

// A 4 x 3 m room split by a wall at x = 2.5, and a robot at (1, 1.5) facing it, with one sonar
// straight ahead reading `range`.
FrameScene facingAWall(double range) {
  FrameScene s;
  s.bounds = {Point2(0, 0), Point2(4, 3)};
  s.walls = {{Point2(2.5, 0), Point2(2.5, 3)}};
  RobotView r;
  r.pose = {Point2(1.0, 1.5), 0.0};
  r.spec.sonarAngles = {0.0};
  r.sonar = {range};
  s.robots.push_back(r);
  return s;
}

struct Probe {
  Image withSonar, without;
  Renderer* renderer = nullptr;
  FrameScene scene;
  // The pixel at world point `p`, with the cones drawn and without.
  [[nodiscard]] std::array<int, 2> red(const Point2& p) const {
    const Vec2 px = renderer->worldToPixel(scene, p);
    const int x = static_cast<int>(px.x()), y = static_cast<int>(px.y());
    return {withSonar.pixel(x, y)[0], without.pixel(x, y)[0]};
  }
};

Probe render(double range) {
  static Result<Renderer> on = Renderer::create({.width = 400, .height = 300, .hud = false, .grid = false, .paths = false});
  static Result<Renderer> off = Renderer::create({.width = 400, .height = 300, .hud = false, .grid = false, .sonar = false, .paths = false});
  EXPECT_TRUE(on.ok() && off.ok());
  Probe p{.renderer = &on.value(), .scene = facingAWall(range)};
  p.withSonar = on.value().render(p.scene);
  p.without = off.value().render(p.scene);
  return p;
}

// No echo: the cone stops at the wall it would pass through (6.5 m would reach x = 7.7).
TEST(SonarCone, WithoutAnEchoStopsAtTheWall) {
  const Probe p = render(6.5);
  const auto [inFront, inFrontBare] = p.red({2.0, 1.5});
  EXPECT_NE(inFront, inFrontBare);  // the cone is drawn before the wall
  const auto [behind, behindBare] = p.red({3.2, 1.5});
  EXPECT_EQ(behind, behindBare);  // and not behind it
}

// An echo 0.77 m out is drawn 0.77 m from the rim (x = 2.0), not from the centre (x = 1.77): the
// arc is there, and beyond it the floor shows.
TEST(SonarCone, AnEchoEndsInAnArcMeasuredFromTheRim) {
  const Probe p = render(0.77);
  const auto [arc, arcBare] = p.red({2.0, 1.5});
  EXPECT_LT(arc, arcBare - 60);  // the dark arc, 2 px wide
  const auto [cone, coneBare] = p.red({1.6, 1.5});
  EXPECT_LT(cone, coneBare);  // the cone's faint fill
  EXPECT_GT(cone, arc);       // lighter than the arc
  const auto [beyond, beyondBare] = p.red({2.2, 1.5});
  EXPECT_EQ(beyond, beyondBare);
}

}  // namespace
}  // namespace frob::render
