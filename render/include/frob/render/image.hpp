#pragma once
/// RGBA images and PNG files.

#include "frob/base/result.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace frob::render {

/// An 8-bit RGBA image, top row first.
struct Image {
  int width = 0;                   ///< pixels
  int height = 0;                  ///< pixels
  std::vector<std::uint8_t> rgba;  ///< width * height * 4 bytes
  /// The 4 bytes of pixel (x, y), y counted down from the top.
  [[nodiscard]] const std::uint8_t* pixel(int x, int y) const { return &rgba[(static_cast<std::size_t>(y) * width + x) * 4]; }
};

/// Writes `image` as an RGB PNG (alpha dropped; compression 1, no filter) via `path`.partial, renamed when complete.
[[nodiscard]] Status writePng(const std::string& path, const Image& image);
/// Reads a PNG file into RGBA.
[[nodiscard]] Result<Image> readPng(const std::string& path);
/// Checks that `dir` is an existing directory this process can create files in.
[[nodiscard]] Status validateOutputDirectory(const std::string& dir);
/// The path of frame `index` in `dir`: dir/frame_000123.png.
[[nodiscard]] std::string framePath(const std::string& dir, long index);

}  // namespace frob::render
