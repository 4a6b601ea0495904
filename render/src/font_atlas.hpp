#pragma once
// Text through FreeType: printable ASCII of two fonts rasterized once into one alpha texture.

#include "canvas.hpp"
#include "frob/base/result.hpp"

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace frob::render::detail {

enum class Font { Sans = 0, Mono = 1 };

class FontAtlas {
 public:
  // Loads both fonts at `pixels` size and packs their glyphs. Fails with the font file named.
  [[nodiscard]] static Result<std::unique_ptr<FontAtlas>> create(const std::string& sansFile, const std::string& monoFile, int pixels);
  // Queues `text` on `canvas` with its baseline starting at `pen` (pixels, y down). Returns the end x.
  double draw(Canvas& canvas, Font font, Vec2 pen, std::string_view text, Rgba8 col) const;
  [[nodiscard]] double width(Font font, std::string_view text) const;
  [[nodiscard]] int ascent(Font font) const { return faces_[static_cast<int>(font)].ascent; }
  [[nodiscard]] int lineHeight(Font font) const { return faces_[static_cast<int>(font)].lineHeight; }
  // Composites the canvas's overlay ops onto an RGBA image (top row first), in order.
  void composite(const std::vector<OverlayOp>& ops, std::uint8_t* rgba, int width, int height) const;

 private:
  struct Glyph {
    int left = 0, top = 0, w = 0, h = 0;  // bitmap placement from the pen, pixels (top: above baseline)
    int advance = 0;                      // pixels
    int ax = 0, ay = 0;                   // top-left of its bitmap in the atlas
  };
  struct Face {
    std::array<Glyph, 96> glyphs;  // ' ' .. '~' and '?' for anything else (index 95 unused)
    int ascent = 0, lineHeight = 0;
  };
  [[nodiscard]] const Glyph& glyph(Font font, char c) const;

  static constexpr int kSize = 512;
  std::vector<std::uint8_t> alpha_ = std::vector<std::uint8_t>(kSize * kSize, 0);
  std::array<Face, 2> faces_;
};

}  // namespace frob::render::detail
