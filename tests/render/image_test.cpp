// PNG frames: a round trip keeps pixels, and bad output paths fail with the path named.
#include "frob/render/image.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

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
    for (int x = 0; x < w; ++x)
      img.rgba.insert(img.rgba.end(), {std::uint8_t(x * 7), std::uint8_t(y * 13), std::uint8_t(x ^ y), 255});
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
  const fs::path dir = scratch("read_only");
  fs::permissions(dir, fs::perms::owner_read | fs::perms::owner_exec);
  if (::access(dir.c_str(), W_OK) == 0) GTEST_SKIP() << "running as root: permissions are not enforced";
  const Status s = validateOutputDirectory(dir.string());
  fs::permissions(dir, fs::perms::owner_all);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.error().find("is not writable"), std::string::npos) << s.error();
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

}  // namespace
}  // namespace frob::render
