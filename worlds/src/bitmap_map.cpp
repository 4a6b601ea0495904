// Bitmap floor plans: dark pixels become solid rectangles, merged greedily so that a wall of many
// pixels becomes one rectangle (as Stage does).
#include "frob/worlds/maps.hpp"

#include <png.h>

#include <cstdint>
#include <vector>

namespace frob::worlds {

Result<std::vector<WallDef>> wallsFromBitmap(const std::filesystem::path& file, const BitmapDef& def) {
  const std::string name = file.filename().string();
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec)) return Status::failure(name + ": no such bitmap file");
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&image, file.string().c_str())) return Status::failure(name + ": not a readable PNG (" + image.message + ")");
  constexpr std::uint32_t kMaxSide = 8192;
  if (image.width == 0 || image.height == 0 || image.width > kMaxSide || image.height > kMaxSide) {
    png_image_free(&image);
    return Status::failure(name + ": the image must be between 1 and 8192 pixels on each side");
  }
  image.format = PNG_FORMAT_GRAY;
  const std::size_t w = image.width, h = image.height;
  std::vector<std::uint8_t> pixels(w * h);
  if (!png_image_finish_read(&image, nullptr, pixels.data(), static_cast<png_int_32>(w), nullptr))
    return Status::failure(name + ": cannot decode the PNG (" + image.message + ")");

  // Greedy merge: from each unclaimed dark pixel, grow right as far as possible, then grow that run
  // downwards while every pixel beneath it is dark and unclaimed.
  std::vector<std::uint8_t> wall(w * h);
  for (std::size_t i = 0; i < w * h; ++i) wall[i] = pixels[i] < def.threshold ? 1 : 0;
  std::vector<WallDef> walls;
  for (std::size_t r = 0; r < h; ++r) {
    for (std::size_t c = 0; c < w; ++c) {
      if (!wall[r * w + c]) continue;
      std::size_t c1 = c;
      while (c1 + 1 < w && wall[r * w + c1 + 1]) ++c1;
      std::size_t r1 = r;
      for (;;) {
        if (r1 + 1 >= h) break;
        bool full = true;
        for (std::size_t k = c; k <= c1 && full; ++k) full = wall[(r1 + 1) * w + k] != 0;
        if (!full) break;
        ++r1;
      }
      for (std::size_t rr = r; rr <= r1; ++rr)
        for (std::size_t k = c; k <= c1; ++k) wall[rr * w + k] = 0;
      // Row 0 is the top of the image: flip so that the plan appears upright in the world.
      const double s = def.scale;
      const Point2 lo = def.origin + Point2(double(c) * s, double(h - 1 - r1) * s);
      const Point2 hi = def.origin + Point2(double(c1 + 1) * s, double(h - r) * s);
      walls.push_back(rectangleWall(lo, hi));
    }
  }
  return std::move(walls);
}

}  // namespace frob::worlds
