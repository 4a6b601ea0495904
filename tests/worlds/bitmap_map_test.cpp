// Bitmap floor plans: dark pixels become few merged rectangles, the right way up.
#include "frob/worlds/maps.hpp"

#include <gtest/gtest.h>
#include <png.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace frob::worlds {
namespace {

// Writes an 8-bit grey PNG from rows of text: '#' is black, anything else white. Row 0 is the top.
std::filesystem::path writePng(const std::string& name, const std::vector<std::string>& rows) {
  const auto path = std::filesystem::path(::testing::TempDir()) / name;
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  image.width = static_cast<png_uint_32>(rows[0].size());
  image.height = static_cast<png_uint_32>(rows.size());
  image.format = PNG_FORMAT_GRAY;
  std::vector<png_byte> pixels;
  for (const auto& r : rows)
    for (char c : r) pixels.push_back(c == '#' ? 0 : 255);
  EXPECT_TRUE(png_image_write_to_file(&image, path.c_str(), 0, pixels.data(), 0, nullptr)) << image.message;
  return path;
}

TEST(BitmapMap, MergesDarkPixelsIntoFewRectangles) {
  const auto png = writePng("plan.png", {
                                            "##########",
                                            "#........#",
                                            "#..##....#",
                                            "#..##....#",
                                            "##########",
                                        });
  Result<std::vector<WallDef>> walls = wallsFromBitmap(png, {.scale = 0.5, .origin = Point2(1, 2)});
  ASSERT_TRUE(walls.ok()) << walls.error();
  // Top row; left and right columns below it; the block, which grows down into the bottom row;
  // the bottom row's two remaining runs.
  EXPECT_EQ(walls->size(), 6u);
  double area = 0;
  for (const WallDef& w : *walls) {
    ASSERT_EQ(w.shape, WallShape::Rectangle);
    area += (w.points[1] - w.points[0]).prod();
  }
  EXPECT_DOUBLE_EQ(area, (10 + 10 + 3 + 3 + 4) * 0.25);  // 30 dark pixels of 0.25 m^2
  // The top row of the image is the top of the world: y from 2 + 4 * 0.5 to 2 + 5 * 0.5.
  EXPECT_EQ((*walls)[0].points[0], Point2(1, 4));
  EXPECT_EQ((*walls)[0].points[1], Point2(6, 4.5));
}

TEST(BitmapMap, ThresholdDecidesWhatIsDark) {
  const auto png = writePng("light.png", {"#.", ".#"});
  EXPECT_EQ(wallsFromBitmap(png, {.threshold = 0})->size(), 0u);  // nothing is below 0
  EXPECT_EQ(wallsFromBitmap(png, {.threshold = 128})->size(), 2u);
}

TEST(BitmapMap, BadFilesGiveMessages) {
  EXPECT_EQ(wallsFromBitmap("/nonexistent/x.png", {}).error(), "x.png: no such bitmap file");
  const auto notPng = std::filesystem::path(::testing::TempDir()) / "not.png";
  std::ofstream(notPng) << "this is not a png";
  Result<std::vector<WallDef>> w = wallsFromBitmap(notPng, {});
  ASSERT_FALSE(w.ok());
  EXPECT_TRUE(w.error().starts_with("not.png: not a readable PNG")) << w.error();
}

}  // namespace
}  // namespace frob::worlds
