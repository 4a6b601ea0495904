// The CPU rasterizer of the 2D canvas covers pixels as OpenGL does (centres inside; a centre on an
// edge shared by two triangles in exactly one of them) and blends with rounding.
#include "raster.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace frob::render::detail {
namespace {

struct Frame {
  int w = 16, h = 12;
  std::vector<std::uint8_t> rgba = std::vector<std::uint8_t>(static_cast<std::size_t>(w) * h * 4);
  Frame() { fillRgba(rgba.data(), w, h, {0, 0, 0, 255}); }
  [[nodiscard]] const std::uint8_t* at(int x, int y) const { return &rgba[(static_cast<std::size_t>(y) * w + x) * 4]; }
  [[nodiscard]] int count(std::uint8_t red) const {
    int n = 0;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) n += at(x, y)[0] == red ? 1 : 0;
    return n;
  }
};

TEST(Raster, ARectangleCoversThePixelsWhoseCentresAreInside) {
  Canvas c;
  c.clear();
  c.rect(1.0, 1.0, 4.0, 3.0, {200, 10, 10, 255});  // centres x 1.5 .. 3.5, y 1.5 .. 2.5
  Frame f;
  rasterize(c, f.rgba.data(), f.w, f.h);
  EXPECT_EQ(f.count(200), 6);
  EXPECT_EQ(f.at(1, 1)[0], 200);
  EXPECT_EQ(f.at(3, 2)[0], 200);
  EXPECT_EQ(f.at(4, 2)[0], 0);
  EXPECT_EQ(f.at(3, 3)[0], 0);
  EXPECT_EQ(f.at(1, 1)[3], 255);
}

TEST(Raster, TrianglesSharingAnEdgeBlendEachPixelOnce) {
  Canvas c;
  c.clear();
  // A rotated quad (two triangles sharing a diagonal) and a fan around a centre, half transparent.
  c.quad({2.3, 1.1}, {13.7, 3.2}, {12.1, 10.6}, {1.2, 8.9}, {255, 255, 255, 128});
  Frame f;
  rasterize(c, f.rgba.data(), f.w, f.h);
  const std::uint8_t once = 128;  // (255 * 128 + 0 * 127 + 127) / 255
  int covered = 0;
  for (int y = 0; y < f.h; ++y)
    for (int x = 0; x < f.w; ++x) {
      const std::uint8_t v = f.at(x, y)[0];
      EXPECT_TRUE(v == 0 || v == once) << x << "," << y << " = " << int(v);
      covered += v == once ? 1 : 0;
    }
  EXPECT_GT(covered, 70);

  Canvas fan;
  fan.clear();
  fan.disc({8.0, 6.0}, 5.0, {255, 255, 255, 128});
  Frame g;
  rasterize(fan, g.rgba.data(), g.w, g.h);
  for (int y = 0; y < g.h; ++y)
    for (int x = 0; x < g.w; ++x) EXPECT_TRUE(g.at(x, y)[0] == 0 || g.at(x, y)[0] == once) << x << "," << y;
  EXPECT_EQ(g.at(8, 6)[0], once);
}

TEST(Raster, BlendsRoundedAndKeepsFramesOpaque) {
  Canvas c;
  c.clear();
  c.rect(0, 0, 16, 12, {100, 200, 50, 255});
  c.rect(0, 0, 16, 12, {200, 0, 255, 64});
  Frame f;
  rasterize(c, f.rgba.data(), f.w, f.h);
  // (200 * 64 + 100 * 191 + 127) / 255 = 125.2 -> 125; (0 + 200 * 191 + 127) / 255 -> 150; (255 * 64 + 50 * 191 + 127) / 255 -> 101
  for (int x : {0, 5, 15}) {
    EXPECT_EQ(f.at(x, 11)[0], 125);
    EXPECT_EQ(f.at(x, 11)[1], 150);
    EXPECT_EQ(f.at(x, 11)[2], 101);
    EXPECT_EQ(f.at(x, 11)[3], 255);
  }
}

TEST(Raster, NonFiniteOrHugeTrianglesAreSkippedAndOnlyTheGivenVerticesDrawn) {
  Canvas c;
  c.clear();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  c.triangle({nan, 0}, {5, 5}, {0, 5}, {255, 0, 0, 255});
  c.triangle({-1e30, 0}, {1e30, 5}, {0, 1e30}, {255, 0, 0, 255});
  const std::size_t mark = c.vertices().size();
  c.rect(0, 0, 2, 2, {7, 0, 0, 255});
  Frame f;
  rasterize(c, f.rgba.data(), f.w, f.h, mark);
  EXPECT_EQ(f.count(255), 0);
  EXPECT_EQ(f.count(7), 4);
  Frame g;
  rasterize(c, g.rgba.data(), g.w, g.h, 0, mark);
  EXPECT_EQ(g.count(7), 0);
}

}  // namespace
}  // namespace frob::render::detail
