// Example, step by step: from a run's FrameScenes to an MP4, PNG frames and a standalone plot PNG.
// This is how `frob run --video/--frames` is meant to drive the renderer; it runs as a test.
#include "decode.hpp"
#include "frob/render/renderer.hpp"
#include "frob/render/video.hpp"

#include <gtest/gtest.h>

#include <filesystem>

namespace frob::render {
namespace {

namespace fs = std::filesystem;

// Stands in for the simulator: the scene after step `step` of a robot driving a circle.
FrameScene sceneAt(std::int64_t step, double dt, std::vector<Point2>& path) {
  const double t = static_cast<double>(step) * dt;
  FrameScene s;
  s.time = t;
  s.bounds = {Point2(-2, -2), Point2(2, 2)};
  s.walls = {{Point2(-2, -2), Point2(2, -2)}, {Point2(2, -2), Point2(2, 2)}, {Point2(2, 2), Point2(-2, 2)}, {Point2(-2, 2), Point2(-2, -2)}};
  RobotView r;
  r.pose = {Point2(std::cos(t), std::sin(t)), t + pi / 2};
  path.push_back(r.pose.position);
  r.path = path;
  r.task = t < 0.5 ? "start" : "circle";
  r.wheels = {1.0, 1.0};
  r.picture = withColor(red, paintAt(Point2(0, 0), circle(0.1)));
  s.robots.push_back(r);
  return s;
}

TEST(Pipeline, RunToMp4FramesAndPlot) {
  const fs::path dir = fs::path(FROB_ACTUAL_DIR) / "pipeline_test";
  fs::remove_all(dir);
  fs::create_directories(dir / "frames");
  const double dt = 0.01;          // simulation step: 100 Hz
  const std::int64_t steps = 100;  // a 1 s run

  // 1. Describe the outputs, and check them before simulating anything: a bad font, model,
  //    size or path fails here with a readable message, not after a long run.
  const RenderDef look{.width = 320, .height = 160, .layout = PanelLayout::PlotRight};
  const VideoDef video{.path = (dir / "run.mp4").string(), .width = look.width, .height = look.height, .fps = 30};
  ASSERT_TRUE(validate(look).ok());
  ASSERT_TRUE(validate(video).ok());
  ASSERT_TRUE(validateOutputDirectory((dir / "frames").string()).ok());

  // 2. Open the renderer and the video (the video is written to run.mp4.partial until closed).
  Result<Renderer> renderer = Renderer::create(look);
  Result<VideoWriter> mp4 = VideoWriter::open(video);
  ASSERT_TRUE(renderer.ok() && mp4.ok()) << renderer.error() << mp4.error();

  // 3. Step the run; the FramePicker says which steps become video frames (30 of 100 here).
  const FramePicker picker(dt, video.fps);
  PlotSet plots;
  plots.plots = {{"heading", {{"cos (1)", {}, {}}}, -1.0, 1.0}};
  plots.taskMarks = {{0.0, "start"}, {0.5, "circle"}};
  plots.tEnd = static_cast<double>(steps) * dt;
  std::vector<Point2> path;
  Image frame;
  std::vector<Image> pngFrames;  // what went to the PNGs, to check the files against
  long pngs = 0;
  for (std::int64_t step = 0; step < steps; ++step) {
    const FrameScene scene = sceneAt(step, dt, path);
    plots.plots[0].series[0].samples.push_back({scene.time, std::cos(scene.time)});
    for (int k = picker.framesAt(step); k > 0; --k) {
      renderer.value().renderInto(scene, plots, frame);
      ASSERT_TRUE(mp4.value().write(frame).ok());
    }
    // PNG frames can be taken at any step, e.g. every 25th.
    if (step % 25 == 0) {
      renderer.value().renderInto(scene, plots, frame);
      ASSERT_TRUE(writePng(framePath((dir / "frames").string(), pngs++), frame).ok());
      pngFrames.push_back(frame);
    }
  }

  // 4. Close: the encoder is flushed and run.mp4 appears under its name.
  ASSERT_TRUE(mp4.value().close().ok());
  EXPECT_EQ(mp4.value().frameCount(), 30);
  EXPECT_FALSE(fs::exists(video.path + ".partial"));

  // 5. The plots alone, over the whole run, as a PNG of their own.
  Result<Renderer> plotter = Renderer::create({.width = 400, .height = 200});
  ASSERT_TRUE(plotter.ok());
  const Image plotImage = plotter.value().renderPlots(plots);
  ASSERT_TRUE(writePng((dir / "plots.png").string(), plotImage).ok());

  // What the files hold: each PNG frame is the frame rendered at its step; the video decodes to 30
  // frames of the look's size, and where a video frame and a PNG frame show the same step (steps
  // 0 and 50: video frames 0 and 15) they agree within the codec's loss; the plot PNG is the plots.
  for (long i = 0; i < pngs; ++i) {
    Result<Image> png = readPng(framePath((dir / "frames").string(), i));
    ASSERT_TRUE(png.ok()) << png.error();
    EXPECT_EQ(png.value().rgba, pngFrames[static_cast<std::size_t>(i)].rgba) << "frame " << i;
  }
  EXPECT_FALSE(fs::exists(framePath((dir / "frames").string(), pngs)));
  const testing::Decoded d = testing::decode(video.path, true);
  ASSERT_EQ(d.frames, 30);
  EXPECT_EQ(d.width, look.width);
  EXPECT_EQ(d.height, look.height);
  EXPECT_LE(testing::lumaOutliers(d.images[0], pngFrames[0]), testing::kCodecLumaOutliers);
  EXPECT_LE(testing::lumaOutliers(d.images[15], pngFrames[2]), testing::kCodecLumaOutliers);
  EXPECT_GT(testing::lumaOutliers(d.images[15], pngFrames[0]), testing::kCodecLumaOutliers) << "the run moves";
  Result<Image> plotPng = readPng((dir / "plots.png").string());
  ASSERT_TRUE(plotPng.ok()) << plotPng.error();
  EXPECT_EQ(plotPng.value().rgba, plotImage.rgba);
  EXPECT_NE(plotImage.rgba, plotter.value().renderPlots(PlotSet{}).rgba) << "the plots are drawn";
}

}  // namespace
}  // namespace frob::render
