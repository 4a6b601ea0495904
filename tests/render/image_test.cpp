// PNG frames: a round trip keeps pixels, and bad output paths fail with the path named.
#include "frob/render/image.hpp"

#include "golden.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

namespace frob::render {
namespace {

namespace fs = std::filesystem;

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::path(FROB_ACTUAL_DIR) / "image_test" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

Image gradient(int w, int h) {
  Image img{.width = w, .height = h, .rgba = {}};
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) img.rgba.insert(img.rgba.end(), {std::uint8_t(x * 7), std::uint8_t(y * 13), std::uint8_t(x ^ y), 255});
  return img;
}

TEST(Png, RoundTripKeepsEveryPixel) {
  const fs::path dir = scratch("round_trip");
  const Image img = gradient(37, 21);
  const std::string path = framePath(dir.string(), 42);
  EXPECT_EQ(fs::path(path).filename(), "frame_000042.png");
  ASSERT_TRUE(writePng(path, img).ok());
  Result<Image> back = readPng(path);
  ASSERT_TRUE(back.ok()) << back.error();
  EXPECT_EQ(back.value().width, 37);
  EXPECT_EQ(back.value().height, 21);
  EXPECT_EQ(back.value().rgba, img.rgba);
  EXPECT_FALSE(fs::exists(path + ".partial"));
}

TEST(Png, MissingDirectoryIsNamed) {
  const Status s = writePng("/nonexistent/dir/frame.png", gradient(4, 4));
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.error(), "png: cannot write '/nonexistent/dir/frame.png': directory '/nonexistent/dir' does not exist");
  const Status d = validateOutputDirectory("/nonexistent/dir");
  ASSERT_FALSE(d.ok());
  EXPECT_NE(d.error().find("directory '/nonexistent/dir' does not exist"), std::string::npos) << d.error();
}

TEST(Png, ParentThatIsAFileIsRejected) {
  const fs::path dir = scratch("parent_file");
  ASSERT_TRUE(writePng((dir / "a.png").string(), gradient(2, 2)).ok());
  const std::string inside = (dir / "a.png" / "b.png").string();
  const Status s = writePng(inside, gradient(2, 2));
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.error(), "png: cannot write '" + inside + "': '" + (dir / "a.png").string() + "' is not a directory");
}

TEST(Png, ReadOnlyDirectoryIsRejectedUpFront) {
  // CI runs as root, for whom a directory's mode bits do not forbid writing. /proc/sys is not
  // writable by anyone, capabilities or not (Linux, fs/proc/proc_sysctl.c), so it refuses root too.
  const std::string dir = "/proc/sys";
  ASSERT_TRUE(fs::is_directory(dir)) << "this test needs Linux's /proc mounted";
  const Status s = validateOutputDirectory(dir);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.error().find("directory '/proc/sys' is not writable"), std::string::npos) << s.error();
  const Status w = writePng(dir + "/frame.png", gradient(2, 2));
  ASSERT_FALSE(w.ok());
  EXPECT_NE(w.error().find("is not writable"), std::string::npos) << w.error();
}

TEST(Png, EmptyImageIsRefused) {
  const fs::path dir = scratch("empty");
  const Status s = writePng((dir / "x.png").string(), Image{});
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.error().find("the image is empty"), std::string::npos) << s.error();
  EXPECT_TRUE(fs::is_empty(dir));
}

TEST(Png, UnreadableFileIsNamed) {
  Result<Image> r = readPng("/nonexistent/golden.png");
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().find("png: cannot read '/nonexistent/golden.png'"), std::string::npos) << r.error();
}

// The golden comparison itself: it fails beyond its tolerance, and always fails when it rewrites.
TEST(Golden, RewritingAGoldenFailsAndSaysSo) {
  const fs::path dir = scratch("golden_update");
  const std::string golden = (dir / "g.png").string();
  const Image img = gradient(16, 8);
  ASSERT_EQ(::setenv("FROB_UPDATE_GOLDENS", "1", 1), 0);
  const ::testing::AssertionResult rewritten = testing::matchesGoldenFile(img, golden, (dir / "actual").string(), testing::kCpuRaster);
  ASSERT_EQ(::unsetenv("FROB_UPDATE_GOLDENS"), 0);
  EXPECT_FALSE(rewritten);
  EXPECT_NE(std::string(rewritten.message()).find("golden rewritten, review and commit it"), std::string::npos) << rewritten.message();
  Result<Image> back = readPng(golden);
  ASSERT_TRUE(back.ok()) << back.error();
  EXPECT_EQ(back.value().rgba, img.rgba);
  EXPECT_TRUE(testing::matchesGoldenFile(img, golden, (dir / "actual").string(), testing::kCpuRaster));
}

TEST(Golden, MorePixelsBeyondTheChannelToleranceThanAllowedFail) {
  const fs::path dir = scratch("golden_tolerance");
  const std::string golden = (dir / "g.png").string();
  const Image img = gradient(16, 8);
  ASSERT_TRUE(writePng(golden, img).ok());
  constexpr testing::Tolerance tol{.channel = 24, .pixels = 3};
  auto changed = [&](long pixels, int by) {
    Image c = img;
    for (long k = 0; k < pixels; ++k) c.rgba[static_cast<std::size_t>(k) * 4 + 2] ^= static_cast<std::uint8_t>(by);
    return testing::matchesGoldenFile(c, golden, (dir / "actual").string(), tol);
  };
  EXPECT_TRUE(changed(100, 16));  // within the channel tolerance: never counted (x ^ 16 moves x by 16)
  EXPECT_TRUE(changed(3, 64));    // beyond it, as many pixels as allowed
  EXPECT_FALSE(changed(4, 64));   // one more
}

}  // namespace
}  // namespace frob::render
