#pragma once
// Text through FreeType: printable ASCII of two fonts rasterized once into one alpha texture.

#include "canvas.hpp"
#include "frob/render/result.hpp"

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
  [[nodiscard]] static Result<std::unique_ptr<FontAtlas>> create(const std::string& sansFile,
                                                                 const std::string& monoFile, int pixels);
  // Uploads the atlas as a texture of the current GL context and binds it.
  void upload();
  // Draws `text` with its baseline starting at `pen` (pixels, y down). Returns the end x.
  double draw(Canvas& canvas, Font font, Vec2 pen, std::string_view text, Rgba8 col) const;
  [[nodiscard]] double width(Font font, std::string_view text) const;
  [[nodiscard]] int ascent(Font font) const { return faces_[static_cast<int>(font)].ascent; }
  [[nodiscard]] int lineHeight(Font font) const { return faces_[static_cast<int>(font)].lineHeight; }
  [[nodiscard]] float whiteU() const { return whiteU_; }
  [[nodiscard]] float whiteV() const { return whiteV_; }

 private:
  struct Glyph {
    int left = 0, top = 0, w = 0, h = 0;  // bitmap placement from the pen, pixels (top: above baseline)
    int advance = 0;                       // pixels
    float u0 = 0, v0 = 0, u1 = 0, v1 = 0;
  };
  struct Face {
    std::array<Glyph, 96> glyphs;  // ' ' .. '~' and '?' for anything else (index 95 unused)
    int ascent = 0, lineHeight = 0;
  };
  [[nodiscard]] const Glyph& glyph(Font font, char c) const;

  static constexpr int kSize = 512;
  std::vector<std::uint8_t> alpha_ = std::vector<std::uint8_t>(kSize * kSize, 0);
  std::array<Face, 2> faces_;
  float whiteU_ = 0, whiteV_ = 0;
  unsigned texture_ = 0;
};

}  // namespace frob::render::detail
