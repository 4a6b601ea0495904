#include "font_atlas.hpp"

#include "raster.hpp"

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

Result<std::unique_ptr<FontAtlas>> FontAtlas::create(const std::string& sansFile, const std::string& monoFile, int pixels) {
  if (pixels < 6 || pixels > 64) {
    return Status::failure("render: text size " + std::to_string(pixels) + " px is outside 6..64");
  }
  FtLibrary ft;
  if (FT_Init_FreeType(&ft.lib) != 0) return Status::failure("render: FreeType could not start");
  auto atlas = std::unique_ptr<FontAtlas>(new FontAtlas());
  // Shelf packing: glyphs left to right in rows.
  int x = 1, y = 1, rowHeight = 0;
  const std::string* files[2] = {&sansFile, &monoFile};
  for (int f = 0; f < 2; ++f) {
    FtFace face;
    if (const FT_Error err = FT_New_Face(ft.lib, files[f]->c_str(), 0, &face.face); err != 0) {
      return Status::failure("render: cannot load font '" + *files[f] + "' (FreeType error " + std::to_string(err) +
                             "); install fonts-dejavu-core or set RenderDef::" + (f == 0 ? "fontFile" : "monoFontFile"));
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
        for (int col = 0; col < gl.w; ++col) atlas->alpha_[(y + r) * kSize + x + col] = g->bitmap.buffer[r * g->bitmap.pitch + col];
      gl.ax = x;
      gl.ay = y;
      x += gl.w + 1;
      rowHeight = std::max(rowHeight, gl.h);
    }
  }
  return atlas;
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
  // Far off-frame or non-finite positions (a controller's NaN) draw nothing.
  if (!(std::abs(pen.x()) < 1e6 && std::abs(pen.y()) < 1e6)) return pen.x();
  // Whole-pixel pen positions keep glyphs crisp and the output exact.
  const int px = static_cast<int>(std::lround(pen.x())), py = static_cast<int>(std::lround(pen.y()));
  canvas.text(static_cast<int>(font), px, py, text, col);
  return px + width(font, text);
}

namespace {
// dst = src over dst with coverage `a` (0..255), rounded.
inline void blend(std::uint8_t* d, const Rgba8& c, unsigned a) {
  d[0] = static_cast<std::uint8_t>((c.r * a + d[0] * (255 - a) + 127) / 255);
  d[1] = static_cast<std::uint8_t>((c.g * a + d[1] * (255 - a) + 127) / 255);
  d[2] = static_cast<std::uint8_t>((c.b * a + d[2] * (255 - a) + 127) / 255);
}
}  // namespace

void FontAtlas::composite(const std::vector<OverlayOp>& ops, std::uint8_t* rgba, int width, int height) const {
  for (const OverlayOp& op : ops) {
    const int cx0 = std::max(0, op.clip[0]), cy0 = std::max(0, op.clip[1]);
    const int cx1 = std::min(width, op.clip[2]), cy1 = std::min(height, op.clip[3]);
    if (op.kind == OverlayOp::Kind::Fill) {
      for (int y = std::max(cy0, op.y0); y < std::min(cy1, op.y1); ++y)
        span(rgba + static_cast<std::size_t>(y) * width * 4, std::max(cx0, op.x0), std::min(cx1, op.x1), op.color, true);
      continue;
    }
    int px = op.x0;
    for (std::size_t i = 0; i < op.text.size(); ++i) {
      if ((static_cast<unsigned char>(op.text[i]) & 0xC0) == 0x80) continue;  // one '?' per non-ASCII character
      const Glyph& g = glyph(static_cast<Font>(op.font), op.text[i]);
      const int gx = px + g.left, gy = op.y0 - g.top;
      for (int r = std::max(0, cy0 - gy); r < std::min(g.h, cy1 - gy); ++r) {
        const std::uint8_t* src = &alpha_[static_cast<std::size_t>(g.ay + r) * kSize + g.ax];
        std::uint8_t* dst = rgba + (static_cast<std::size_t>(gy + r) * width) * 4;
        for (int k = std::max(0, cx0 - gx); k < std::min(g.w, cx1 - gx); ++k) {
          if (src[k] != 0) blend(dst + static_cast<std::size_t>(gx + k) * 4, op.color, (src[k] * op.color.a + 127) / 255);
        }
      }
      px += g.advance;
    }
  }
}

}  // namespace frob::render::detail
