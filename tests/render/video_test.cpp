// MP4 output decodes to what was written; bad setups fail before any frame; no partial files remain.
#include "frob/render/video.hpp"

#include "decode.hpp"
#include "frob/render/renderer.hpp"
#include "scenes.hpp"

#include <gtest/gtest.h>

#include <filesystem>

namespace frob::render {
namespace {

namespace fs = std::filesystem;

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::path(FROB_ACTUAL_DIR) / "video_test" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

Image solid(int w, int h, std::uint8_t shade) {
  Image img{.width = w, .height = h, .rgba = std::vector<std::uint8_t>(static_cast<std::size_t>(w) * h * 4, shade)};
  for (std::size_t i = 3; i < img.rgba.size(); i += 4) img.rgba[i] = 255;
  return img;
}

using testing::decode;
using testing::Decoded;
using testing::kCodecLumaOutliers;
using testing::lumaOutliers;

// Frames of the test room with the robot driving across it: each frame differs from the others.
std::vector<Image> drivingFrames(int count) {
  Result<Renderer> r = Renderer::create({.width = 320, .height = 240, .hud = true});
  EXPECT_TRUE(r.ok()) << r.error();
  std::vector<Image> frames;
  for (int i = 0; i < count; ++i) {
    FrameScene s = testing::roomScene();
    s.time = i / 30.0;
    s.robots[0].pose = {Point2(0.5 + 0.06 * i, 1.0 + 0.02 * i), 0.05 * i};
    frames.push_back(r.value().render(s));
  }
  return frames;
}

TEST(Video, DecodesToTheFramesWritten) {
  const fs::path dir = scratch("decode");
  const std::string path = (dir / "run.mp4").string();
  Result<VideoWriter> v = VideoWriter::open({.path = path, .width = 320, .height = 240, .fps = 30});
  ASSERT_TRUE(v.ok()) << v.error();
  EXPECT_FALSE(fs::exists(path)) << "the video must not appear under its name before close()";
  EXPECT_TRUE(fs::exists(path + ".partial"));
  // Each frame goes to the video and, as `frob run --frames` would write it, to a PNG.
  const std::vector<Image> frames = drivingFrames(45);
  for (std::size_t i = 0; i < frames.size(); ++i) {
    ASSERT_TRUE(v.value().write(frames[i]).ok());
    ASSERT_TRUE(writePng(framePath(dir.string(), static_cast<long>(i)), frames[i]).ok());
  }
  EXPECT_EQ(v.value().frameCount(), 45);
  const Status closed = v.value().close();
  ASSERT_TRUE(closed.ok()) << closed.error();
  EXPECT_FALSE(fs::exists(path + ".partial"));
  const Decoded d = decode(path, true);
  EXPECT_EQ(d.codec, "h264");
  EXPECT_EQ(d.frames, 45);
  EXPECT_EQ(d.width, 320);
  EXPECT_EQ(d.height, 240);
  ASSERT_EQ(d.images.size(), frames.size());
  std::vector<Image> pngs;
  for (std::size_t i = 0; i < frames.size(); ++i) pngs.push_back(readPng(framePath(dir.string(), static_cast<long>(i))).value());
  for (std::size_t i = 0; i < frames.size(); ++i) {
    // Within the codec's loss of the PNG of the same frame (kCodecLumaOutliers), and nearer to it than to
    // the PNG of any other frame: no frame dropped, repeated, reordered or mangled.
    const long own = lumaOutliers(d.images[i], pngs[i]);
    EXPECT_LE(own, kCodecLumaOutliers) << "frame " << i;
    for (std::size_t j = 0; j < frames.size(); ++j)
      if (j != i) EXPECT_LT(own, lumaOutliers(d.images[i], pngs[j])) << "frame " << i << " looks like frame " << j;
  }
}

// Frames of noise, new each frame: the hardest picture to compress (deterministic, a fixed LCG).
Image noise(int w, int h, std::uint32_t& state) {
  Image img = solid(w, h, 0);
  for (std::size_t i = 0; i < img.rgba.size(); ++i) {
    state = state * 1664525u + 1013904223u;
    if (i % 4 != 3) img.rgba[i] = static_cast<std::uint8_t>(state >> 24);
  }
  return img;
}

// A bitrate cap keeps a video within its budget however hard its pictures are: 10 s of noise at
// 200 kbit/s is about 250 kB (x264's VBV may overshoot a little: 10% allowed); without the cap the
// same frames take megabytes. The capped video still decodes to every frame.
TEST(Video, ACappedBitrateKeepsTheFileWithinItsBudget) {
  const fs::path dir = scratch("capped");
  std::uintmax_t bytes[2] = {};
  for (int capped : {0, 1}) {
    const std::string path = (dir / (capped ? "capped.mp4" : "free.mp4")).string();
    Result<VideoWriter> v = VideoWriter::open({.path = path, .width = 320, .height = 240, .fps = 30, .maxKilobitsPerSecond = capped ? 200 : 0});
    ASSERT_TRUE(v.ok()) << v.error();
    std::uint32_t state = 7;
    for (int i = 0; i < 300; ++i) ASSERT_TRUE(v.value().write(noise(320, 240, state)).ok());
    ASSERT_TRUE(v.value().close().ok());
    bytes[capped] = fs::file_size(path);
  }
  EXPECT_LE(bytes[1], 1.1 * 10 * 200'000 / 8) << bytes[1];
  EXPECT_GT(bytes[0], 4 * bytes[1]) << bytes[0];
  const Decoded d = decode((dir / "capped.mp4").string(), false);
  EXPECT_EQ(d.frames, 300);
}

TEST(Video, OddFrameSizeIsRejectedBeforeAnyFileExists) {
  const fs::path dir = scratch("odd");
  const VideoDef def{.path = (dir / "odd.mp4").string(), .width = 641, .height = 480};
  const Status s = validate(def);
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.error(), "video: H.264 in yuv420p needs an even width and height; got 641x480");
  EXPECT_EQ(VideoWriter::open(def).error(), s.error());
  EXPECT_TRUE(fs::is_empty(dir));
}

TEST(Video, UnwritablePathIsNamed) {
  const Status s = validate(VideoDef{.path = "/nonexistent/out/run.mp4"});
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.error(), "video: cannot write '/nonexistent/out/run.mp4': directory '/nonexistent/out' does not exist");
  const fs::path dir = scratch("is_dir");
  EXPECT_NE(validate(VideoDef{.path = dir.string()}).error().find("it is a directory"), std::string::npos);
}

TEST(Video, DestroyedWithoutCloseLeavesNothing) {
  const fs::path dir = scratch("abandoned");
  const std::string path = (dir / "run.mp4").string();
  {
    Result<VideoWriter> v = VideoWriter::open({.path = path, .width = 64, .height = 64});
    ASSERT_TRUE(v.ok()) << v.error();
    ASSERT_TRUE(v.value().write(solid(64, 64, 100)).ok());
  }  // as if the run failed half way
  EXPECT_TRUE(fs::is_empty(dir));
}

TEST(Video, WrongFrameSizeFailsAndCloseAfterCloseIsAnError) {
  const fs::path dir = scratch("wrong_size");
  const std::string path = (dir / "run.mp4").string();
  Result<VideoWriter> v = VideoWriter::open({.path = path, .width = 64, .height = 64});
  ASSERT_TRUE(v.ok()) << v.error();
  const Status s = v.value().write(solid(32, 32, 0));
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.error(), "video: frame of 32x32 does not match the video's 64x64");
  ASSERT_TRUE(v.value().write(solid(64, 64, 0)).ok());
  ASSERT_TRUE(v.value().close().ok());
  EXPECT_FALSE(v.value().close().ok());
  EXPECT_EQ(decode(path).frames, 1);
}

TEST(FramePicker, ThirtyFpsFromAHundredHertzRun) {
  const FramePicker picker(0.01, 30);
  const std::vector<std::int64_t> steps = picker.steps(6000);  // 60 s
  ASSERT_EQ(steps.size(), 1800u);
  EXPECT_EQ(steps[0], 0);
  EXPECT_EQ(steps[1], 3);  // 1/30 s = 0.0333 s: the last step at or before it is step 3 (0.03 s)
  EXPECT_EQ(steps[2], 6);
  EXPECT_EQ(steps[3], 10);  // 0.1 s exactly
  EXPECT_EQ(steps.back(), 5996);
  EXPECT_EQ(picker.framesAt(0), 1);
  EXPECT_EQ(picker.framesAt(1), 0);
}

TEST(FramePicker, SlowSimulationRepeatsFrames) {
  const FramePicker picker(0.1, 30);  // 10 Hz simulation, 30 fps video: three frames per step
  EXPECT_EQ(picker.framesAt(0), 3);
  EXPECT_EQ(picker.framesAt(7), 3);
  EXPECT_EQ(picker.steps(10).size(), 30u);
}

TEST(FramePicker, EqualRatesGiveEveryStep) {
  const FramePicker picker(1.0 / 30.0, 30);
  const std::vector<std::int64_t> steps = picker.steps(300);
  ASSERT_EQ(steps.size(), 300u);
  for (std::int64_t i = 0; i < 300; ++i) EXPECT_EQ(steps[static_cast<std::size_t>(i)], i);
}

}  // namespace
}  // namespace frob::render
