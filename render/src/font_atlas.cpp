#include "font_atlas.hpp"

#include <GL/gl.h>
#include <ft2build.h>
#include FT_FREETYPE_H

#include <cmath>

namespace frob::render::detail {

namespace {
struct FtLibrary {
  FT_Library lib = nullptr;
  ~FtLibrary() {
    if (lib) FT_Done_FreeType(lib);
  }
};
struct FtFace {
  FT_Face face = nullptr;
  ~FtFace() {
    if (face) FT_Done_Face(face);
  }
};
}  // namespace

Result<std::unique_ptr<FontAtlas>> FontAtlas::create(const std::string& sansFile, const std::string& monoFile,
                                                     int pixels) {
  if (pixels < 6 || pixels > 64) {
    return Status::failure("render: text size " + std::to_string(pixels) + " px is outside 6..64");
  }
  FtLibrary ft;
  if (FT_Init_FreeType(&ft.lib) != 0) return Status::failure("render: FreeType could not start");
  auto atlas = std::unique_ptr<FontAtlas>(new FontAtlas());
  // Shelf packing: glyphs left to right in rows; a 2x2 white block first for untextured geometry.
  int x = 4, y = 1, rowHeight = 3;
  for (int j = 1; j < 3; ++j)
    for (int i = 1; i < 3; ++i) atlas->alpha_[j * kSize + i] = 255;
  atlas->whiteU_ = 2.0f / kSize;
  atlas->whiteV_ = 2.0f / kSize;
  const std::string* files[2] = {&sansFile, &monoFile};
  for (int f = 0; f < 2; ++f) {
    FtFace face;
    if (const FT_Error err = FT_New_Face(ft.lib, files[f]->c_str(), 0, &face.face); err != 0) {
      return Status::failure("render: cannot load font '" + *files[f] + "' (FreeType error " +
                             std::to_string(err) + "); install fonts-dejavu-core or set RenderDef::" +
                             (f == 0 ? "fontFile" : "monoFontFile"));
    }
    FT_Set_Pixel_Sizes(face.face, 0, static_cast<FT_UInt>(pixels));
    Face& out = atlas->faces_[f];
    out.ascent = static_cast<int>(face.face->size->metrics.ascender >> 6);
    out.lineHeight = static_cast<int>(face.face->size->metrics.height >> 6);
    for (int c = 32; c < 127; ++c) {
      if (FT_Load_Char(face.face, static_cast<FT_ULong>(c), FT_LOAD_RENDER) != 0) continue;
      const FT_GlyphSlot g = face.face->glyph;
      Glyph& gl = out.glyphs[c - 32];
      gl.left = g->bitmap_left;
      gl.top = g->bitmap_top;
      gl.w = static_cast<int>(g->bitmap.width);
      gl.h = static_cast<int>(g->bitmap.rows);
      gl.advance = static_cast<int>(g->advance.x >> 6);
      if (x + gl.w + 1 >= kSize) {
        x = 1;
        y += rowHeight + 1;
        rowHeight = 0;
      }
      if (y + gl.h + 1 >= kSize) return Status::failure("render: text size too large for the glyph atlas");
      for (int r = 0; r < gl.h; ++r)
        for (int col = 0; col < gl.w; ++col)
          atlas->alpha_[(y + r) * kSize + x + col] = g->bitmap.buffer[r * g->bitmap.pitch + col];
      gl.u0 = static_cast<float>(x) / kSize;
      gl.v0 = static_cast<float>(y) / kSize;
      gl.u1 = static_cast<float>(x + gl.w) / kSize;
      gl.v1 = static_cast<float>(y + gl.h) / kSize;
      x += gl.w + 1;
      rowHeight = std::max(rowHeight, gl.h);
    }
  }
  return atlas;
}

void FontAtlas::upload() {
  if (texture_ == 0) {
    glGenTextures(1, &texture_);
    glBindTexture(GL_TEXTURE_2D, texture_);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_ALPHA, kSize, kSize, 0, GL_ALPHA, GL_UNSIGNED_BYTE, alpha_.data());
    // Glyphs are placed on whole pixels, so nearest sampling copies the FreeType bitmap exactly.
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  }
  glBindTexture(GL_TEXTURE_2D, texture_);
}

const FontAtlas::Glyph& FontAtlas::glyph(Font font, char c) const {
  const auto& glyphs = faces_[static_cast<int>(font)].glyphs;
  const int i = static_cast<unsigned char>(c);
  return (i >= 32 && i < 127) ? glyphs[i - 32] : glyphs['?' - 32];
}

double FontAtlas::width(Font font, std::string_view text) const {
  int w = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if ((static_cast<unsigned char>(text[i]) & 0xC0) == 0x80) continue;  // UTF-8 continuation byte
    w += glyph(font, text[i]).advance;
  }
  return w;
}

double FontAtlas::draw(Canvas& canvas, Font font, Vec2 pen, std::string_view text, Rgba8 col) const {
  // Whole-pixel pen positions keep glyphs crisp and the output exact.
  int px = static_cast<int>(std::lround(pen.x()));
  const int py = static_cast<int>(std::lround(pen.y()));
  for (std::size_t i = 0; i < text.size(); ++i) {
    if ((static_cast<unsigned char>(text[i]) & 0xC0) == 0x80) continue;  // one '?' per non-ASCII character
    const Glyph& g = glyph(font, text[i]);
    if (g.w > 0 && g.h > 0) {
      canvas.textured(px + g.left, py - g.top, px + g.left + g.w, py - g.top + g.h, g.u0, g.v0, g.u1, g.v1, col);
    }
    px += g.advance;
  }
  return px;
}

}  // namespace frob::render::detail
