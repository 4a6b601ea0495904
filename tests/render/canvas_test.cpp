// The CPU-side tessellation: shapes cover the area they should, thinning keeps the shape.
#include "canvas.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace frob::render::detail {
namespace {

// Total area of the canvas's triangles, pixels squared.
double area(const Canvas& c) {
  double sum = 0;
  const auto& v = c.vertices();
  for (std::size_t i = 0; i + 2 < v.size(); i += 3) {
    sum += std::abs((v[i + 1].x - v[i].x) * (v[i + 2].y - v[i].y) - (v[i + 2].x - v[i].x) * (v[i + 1].y - v[i].y)) / 2;
  }
  return sum;
}

TEST(Canvas, ConcavePolygonIsTriangulatedWithoutSpill) {
  // An L shape: 3 x 3 square minus its 2 x 2 upper-right part, area 5, in either orientation.
  const std::vector<Vec2> l = {{0, 0}, {3, 0}, {3, 1}, {1, 1}, {1, 3}, {0, 3}};
  Canvas c;
  EXPECT_TRUE(c.polygon(l, {}));
  EXPECT_NEAR(area(c), 5.0, 1e-9);
  Canvas r;
  EXPECT_TRUE(r.polygon(std::vector<Vec2>(l.rbegin(), l.rend()), {}));
  EXPECT_NEAR(area(r), 5.0, 1e-9);
}

// The ear clipper's worst case (every corner convex and its triangle round the centre, where the
// last half of the vertices cluster): a frame's budget of ear tests runs out and the rest is a fan,
// n - 2 triangles all the same, instead of some 10^10 tests; the next frame has its budget again.
TEST(Canvas, APolygonMadeToBeSlowToFillIsFilledWithinTheFramesBudget) {
  std::vector<Vec2> worst;
  for (int i = 0; i < 2048; ++i) worst.emplace_back(500 + 300 * std::cos(i * (M_PI + 0.01)), 500 + 300 * std::sin(i * (M_PI + 0.01)));
  for (int j = 0; j < 2048; ++j) worst.emplace_back(500 + 0.1 * std::cos(M_PI / 2 * j / 2048), 500 + 0.1 * std::sin(M_PI / 2 * j / 2048));
  const std::vector<Vec2> l = {{0, 0}, {3, 0}, {3, 1}, {1, 1}, {1, 3}, {0, 3}};
  Canvas c;
  EXPECT_FALSE(c.polygon(worst, {}));
  EXPECT_EQ(c.vertices().size(), 3 * (worst.size() - 2));
  EXPECT_FALSE(c.polygon(l, {})) << "the frame's budget is spent";
  c.clear();
  EXPECT_TRUE(c.polygon(l, {}));
  EXPECT_NEAR(area(c), 5.0, 1e-9);
}

TEST(Canvas, DiscAreaIsCloseToPiRSquared) {
  Canvas c;
  c.disc({50, 50}, 40, {});
  EXPECT_NEAR(area(c), pi * 40 * 40, pi * 40 * 40 * 0.01);
}

TEST(Canvas, OpaqueAndTranslucentShapesGoToSeparateRuns) {
  Canvas c;
  c.rect(0, 0, 1, 1, {0, 0, 0, 255});
  c.rect(0, 0, 1, 1, {0, 0, 0, 255});
  c.rect(0, 0, 1, 1, {0, 0, 0, 100});
  c.rect(0, 0, 1, 1, {0, 0, 0, 255});
  ASSERT_EQ(c.runs().size(), 3u);
  EXPECT_EQ(c.runs()[0].mode, Mode::Opaque);
  EXPECT_EQ(c.runs()[1].mode, Mode::Blend);
  EXPECT_EQ(c.runs()[1].first, 12u);
  EXPECT_EQ(c.runs()[2].mode, Mode::Opaque);
}

TEST(Canvas, DashedLineCoversAboutItsDashShare) {
  Canvas c;
  const std::vector<Vec2> line = {{0, 0}, {40, 0}, {100, 0}};  // the pattern carries over the vertex
  c.dashed(line, 2, 6, 4, {});
  EXPECT_NEAR(area(c), 100 * 0.6 * 2, 1e-6);
}

TEST(SimplifyPolyline, StraightRunsCollapseAndCornersStay) {
  std::vector<Vec2> pts;
  for (int i = 0; i <= 100; ++i) pts.emplace_back(i, 0);
  for (int i = 1; i <= 100; ++i) pts.emplace_back(100, i);
  const std::vector<Vec2> out = simplifyPolyline(pts, 0.5);
  ASSERT_EQ(out.size(), 3u);
  EXPECT_EQ(out[1], Vec2(100, 0));
  EXPECT_EQ(out[2], Vec2(100, 100));
}

TEST(SimplifyPolyline, SpikesAndReversalsAreKept) {
  const std::vector<Vec2> spike = {{0, 0}, {1, 0}, {2, 0}, {3, 5}, {4, 0}, {5, 0}};
  EXPECT_GE(simplifyPolyline(spike, 0.5).size(), 4u);
  const std::vector<Vec2> back = {{0, 0}, {10, 0}, {20, 0}, {5, 0}};  // goes out and comes back
  const std::vector<Vec2> out = simplifyPolyline(back, 0.5);
  ASSERT_EQ(out.size(), 3u);
  EXPECT_EQ(out[1], Vec2(20, 0));
}

TEST(SimplifyPolyline, CurvesStayWithinTolerance) {
  std::vector<Vec2> arc;
  for (int i = 0; i <= 1000; ++i) arc.emplace_back(100 * std::cos(i * 0.003), 100 * std::sin(i * 0.003));
  const std::vector<Vec2> out = simplifyPolyline(arc, 0.5);
  EXPECT_LT(out.size(), 60u);
  // Every kept chord stays within about the tolerance of the circle.
  for (std::size_t i = 0; i + 1 < out.size(); ++i) EXPECT_GT(((out[i] + out[i + 1]) / 2).norm(), 100 - 1.0);
}

TEST(Canvas, CircleSegmentsGrowWithRadius) {
  EXPECT_EQ(Canvas::segmentsFor(0.5), 8);
  EXPECT_LT(Canvas::segmentsFor(10), Canvas::segmentsFor(100));
  EXPECT_LE(Canvas::segmentsFor(1e6), 128);
}

}  // namespace
}  // namespace frob::render::detail
