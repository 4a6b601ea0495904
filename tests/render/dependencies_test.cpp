// The render target brings OSMesa, libpng, FreeType and libavcodec: each is called once here.
#include <GL/osmesa.h>
#include <ft2build.h>
#include FT_FREETYPE_H
#include <gtest/gtest.h>
#include <png.h>

extern "C" {
#include <libavcodec/avcodec.h>
}

#include <cstdint>
#include <vector>

namespace {

TEST(RenderDependencies, OsmesaClearsAnOffscreenBuffer) {
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, nullptr);
  ASSERT_NE(ctx, nullptr);
  std::vector<std::uint8_t> pixels(16 * 8 * 4);
  ASSERT_TRUE(OSMesaMakeCurrent(ctx, pixels.data(), GL_UNSIGNED_BYTE, 16, 8));
  glClearColor(1.0f, 0.5f, 0.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glFinish();
  EXPECT_EQ(pixels[0], 255);
  EXPECT_NEAR(pixels[1], 128, 1);  // 0.5 rounds to 127 or 128
  EXPECT_EQ(pixels[2], 0);
  EXPECT_EQ(pixels[3], 255);
  OSMesaDestroyContext(ctx);
}

TEST(RenderDependencies, LibpngWritesToMemory) {
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  image.width = 4;
  image.height = 4;
  image.format = PNG_FORMAT_RGBA;
  std::vector<std::uint8_t> rgba(4 * 4 * 4, 200);
  png_alloc_size_t size = 0;
  ASSERT_TRUE(png_image_write_to_memory(&image, nullptr, &size, 0, rgba.data(), 0, nullptr));
  std::vector<std::uint8_t> out(size);
  ASSERT_TRUE(png_image_write_to_memory(&image, out.data(), &size, 0, rgba.data(), 0, nullptr));
  EXPECT_EQ(out[1], 'P');
  EXPECT_EQ(out[2], 'N');
  EXPECT_EQ(out[3], 'G');
}

TEST(RenderDependencies, FreetypeLoadsTheDejaVuFont) {
  FT_Library lib = nullptr;
  ASSERT_EQ(FT_Init_FreeType(&lib), 0);
  FT_Face face = nullptr;
  ASSERT_EQ(FT_New_Face(lib, FROB_FONT_FILE, 0, &face), 0) << FROB_FONT_FILE;
  EXPECT_STREQ(face->family_name, "DejaVu Sans");
  FT_Done_Face(face);
  FT_Done_FreeType(lib);
}

TEST(RenderDependencies, LibavcodecHasAnH264Encoder) {
  const AVCodec* codec = avcodec_find_encoder(AV_CODEC_ID_H264);
  ASSERT_NE(codec, nullptr);
  EXPECT_NE(avcodec_find_encoder_by_name("libx264"), nullptr);
}

}  // namespace
