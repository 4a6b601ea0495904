// A RunView joins the renderer to a running world: frames show the robot where the simulation has
// it and the pictures its tasks publish; paths, plots and task marks grow as the run steps; and
// rendering never changes what the simulation computes.
#include "frob/render/run_view.hpp"

#include "../support/wanderer.hpp"
#include "decode.hpp"
#include "frob/frob.hpp"
#include "frob/render/renderer.hpp"
#include "frob/render/video.hpp"
#include "frob/worlds/registry.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace frob::render {
namespace {

namespace fs = std::filesystem;
using namespace frob::literals;

constexpr Color kMagenta{1.0f, 0.0f, 1.0f};
const Point2 kMarker(1.875, 1.875);  // where the controller's picture puts its disc, metres

// The paper's runAround, publishing a magenta disc at kMarker.
Behavior<Wheels> wanderer(const Robot& r) { return runTask(r, withPicture(paintAt(kMarker, withColor(kMagenta, disc(0.3))), support::runAround())); }

worlds::WorldDef world(std::string_view name) {
  Result<worlds::WorldDef> w = worlds::loadReferenceWorld(name);
  EXPECT_TRUE(w.ok()) << w.error();
  return w.ok() ? *w : worlds::WorldDef{};
}

::testing::AssertionResult near(const std::uint8_t* px, Color c, int tol = 6) {
  const int want[3] = {static_cast<int>(std::lround(c.r * 255)), static_cast<int>(std::lround(c.g * 255)), static_cast<int>(std::lround(c.b * 255))};
  for (int k = 0; k < 3; ++k) {
    if (std::abs(px[k] - want[k]) > tol) {
      return ::testing::AssertionFailure() << "pixel (" << int(px[0]) << ", " << int(px[1]) << ", " << int(px[2]) << ") is not (" << want[0] << ", "
                                           << want[1] << ", " << want[2] << ")";
    }
  }
  return ::testing::AssertionSuccess();
}

TEST(RunView, TakesTheWorldsShapesOnce) {
  worlds::WorldDef w;
  w.size = {6.0, 4.0};
  w.walls = {worlds::segmentWall({1, 1}, {2, 1}), worlds::polylineWall({{3, 1}, {4, 1}, {4, 2}}, true), worlds::rectangleWall({1, 2}, {2, 3}),
             worlds::circleWall({5, 3}, 0.2)};
  w.points = {{"goal", {5, 1}}};
  w.robots = {{.name = "", .start = {{0.5, 0.5}, 0}}};
  const worlds::Run run(w, {}, {[](const Robot&) { return Behavior<Wheels>(Wheels{}); }});
  const FrameScene s = RunView(run).scene();
  EXPECT_EQ(s.walls.size(), 1u + 3u + 4u);  // segment, closed triangle, enclosure
  ASSERT_EQ(s.blocks.size(), 1u);
  EXPECT_EQ(s.blocks[0].center, Point2(1.5, 2.5));
  EXPECT_EQ(s.blocks[0].halfExtents, Vec2(0.5, 0.5));
  ASSERT_EQ(s.pillars.size(), 1u);
  EXPECT_EQ(s.pillars[0].radius, 0.2);
  ASSERT_EQ(s.points.size(), 1u);
  EXPECT_EQ(s.points[0].name, "goal");
  EXPECT_EQ(s.bounds.max, Point2(6, 4));
  ASSERT_EQ(s.robots.size(), 1u);
  EXPECT_EQ(s.robots[0].name, "robot0");
}

TEST(RunView, DrawsTheRobotAtItsTruePoseAndThePictureWhereTheControllerPutIt) {
  worlds::Run run(world("maze"), {}, {wanderer});
  RunView view(run);
  while (run.simulation().time() < 2.0) {
    run.step();
    view.update(run);
  }
  const worlds::RobotRecord& last = run.recorder().steps().back().robots[0];
  const RobotView& robot = view.scene().robots[0];
  EXPECT_EQ(robot.pose, last.truePose);
  EXPECT_EQ(robot.task, "goAhead");
  EXPECT_EQ(robot.sonar, last.sonar);
  EXPECT_EQ(robot.wheels, (Wheels{0.3, 0}));
  EXPECT_GT(last.truePose.position.x(), 0.9);  // it really drove

  Result<Renderer> r = Renderer::create({.width = 640, .height = 640, .grid = false});
  ASSERT_TRUE(r.ok()) << r.error();
  const Image img = r.value().render(view.scene(), view.plots());
  // Half a radius behind the centre (clear of the white heading tick): the robot's colour.
  const Point2 behind = last.truePose.position - 0.5 * robot.spec.radius * Vec2(std::cos(last.truePose.heading), std::sin(last.truePose.heading));
  const Vec2 p = r.value().worldToPixel(view.scene(), behind);
  EXPECT_TRUE(near(img.pixel(static_cast<int>(p.x()), static_cast<int>(p.y())), blue)) << "at " << p.transpose();
  const Vec2 m = r.value().worldToPixel(view.scene(), kMarker);
  EXPECT_TRUE(near(img.pixel(static_cast<int>(m.x()), static_cast<int>(m.y())), kMagenta)) << "at " << m.transpose();
}

// Updated after every step, a view needs only the newest step (frob run keeps no more, so its
// memory stays flat): it sees the same paths and plots as with every step kept.
TEST(RunView, AWindowOfOneStepGivesTheSameViewAsTheWholeRun) {
  worlds::Run all(world("maze"), {}, {wanderer}), newest(world("maze"), {}, {wanderer}, {.window = 1});
  RunView a(all, {.plotSeconds = 10.0}), b(newest, {.plotSeconds = 10.0});
  while (all.simulation().time() < 10.0) {
    all.step(), newest.step();
    a.update(all), b.update(newest);
  }
  EXPECT_EQ(newest.recorder().steps().size(), 1u);
  EXPECT_EQ(b.instants(), a.instants());
  EXPECT_EQ(b.scene().robots[0].path, a.scene().robots[0].path);
  ASSERT_EQ(b.plots().plots.size(), a.plots().plots.size());
  for (std::size_t k = 0; k < a.plots().plots.size(); ++k) {  // the same samples, a gap (no echo: NaN) where the other has one
    const std::vector<Sample>&x = b.plots().plots[k].series[0].samples, &y = a.plots().plots[k].series[0].samples;
    ASSERT_EQ(x.size(), y.size()) << k;
    for (std::size_t i = 0; i < x.size(); ++i) {
      EXPECT_TRUE(x[i].t == y[i].t && (x[i].value == y[i].value || (std::isnan(x[i].value) && std::isnan(y[i].value)))) << k << " " << i;
    }
  }
}

TEST(RunView, PathsPlotsAndTaskMarksGrowWithTheRunEvenWhenTheTimelineIsDrained) {
  worlds::Run run(world("maze"), {}, {wanderer});
  RunView view(run, {.plotSeconds = 30.0});
  std::vector<std::string> ended;
  while (run.simulation().time() < 30.0) {
    run.step();
    view.update(run);
    // The app streams the timeline to a file and drains it each step; the view must not need it.
    for (const TaskRecord& t : run.timeline(0).drainEnded()) ended.push_back(t.name);
  }
  const RobotView& robot = view.scene().robots[0];
  const auto& steps = run.recorder().steps();
  ASSERT_EQ(steps.size(), 3000u);
  // Paths start at the start, end at the robot, and keep only points 5 cm apart.
  EXPECT_EQ(robot.path.front(), steps.front().robots[0].truePose.position);
  EXPECT_EQ(robot.path.back(), steps.back().robots[0].truePose.position);
  EXPECT_EQ(robot.odometryPath.back(), steps.back().robots[0].odometry.position);
  EXPECT_LT(robot.path.size(), 30.0 * 0.3 / 0.05 + 2);
  EXPECT_GT(robot.path.size(), 10u);

  const PlotSet& plots = view.plots();
  ASSERT_EQ(plots.plots.size(), 2u);
  EXPECT_EQ(plots.plots[0].series[0].name, "front sonar (m)");
  EXPECT_EQ(plots.plots[0].series[1].name, "to goal (m)");
  EXPECT_EQ(plots.plots[1].series[0].name, "forward (m/s)");
  EXPECT_EQ(plots.plots[0].series[0].samples.size(), 600u);  // every 0.05 s
  // The front sonar's no-echo readings are gaps (NaN), its echoes the readings recorded at that instant.
  int gaps = 0;
  for (const Sample& v : plots.plots[0].series[0].samples) {
    const auto at = std::find_if(steps.begin(), steps.end(), [&](const worlds::StepRecord& r) { return r.time == v.t; });
    ASSERT_NE(at, steps.end()) << v.t;
    const double recorded = at->robots[0].sonar[static_cast<std::size_t>(frontSonarIndex(robot.spec))];
    if (recorded >= robot.spec.sonarMaxRange) {
      EXPECT_TRUE(std::isnan(v.value)) << v.t;
      ++gaps;
    } else {
      EXPECT_EQ(v.value, recorded) << v.t;
    }
  }
  EXPECT_GT(gaps, 0) << "a maze's corridors leave the front sonar without an echo now and then";
  EXPECT_EQ(plots.tEnd, 30.0);
  // Every task the timeline saw start (and end) is marked, in time order, at its start.
  ASSERT_GT(ended.size(), 4u);
  ASSERT_GE(plots.taskMarks.size(), 4u);
  EXPECT_EQ(plots.taskMarks[0].name, "goAhead");
  EXPECT_EQ(plots.taskMarks[0].t, 0.0);
  EXPECT_EQ(plots.taskMarks[1].name, "turnLeft");
  for (std::size_t k = 1; k < plots.taskMarks.size(); ++k) EXPECT_GE(plots.taskMarks[k].t, plots.taskMarks[k - 1].t);
}

// Frames every 30th of a second into an MP4 plus a PNG now and then, or nothing: same trajectory.
std::uint64_t trajectory(double seconds, const std::string& video, const std::string& pngDir) {
  worlds::Run run(world("maze"), {}, {wanderer});
  std::optional<RunView> view;
  std::optional<Renderer> renderer;
  std::optional<VideoWriter> mp4;
  if (!video.empty()) {
    view.emplace(run, RunViewDef{.plotSeconds = seconds});
    Result<Renderer> r = Renderer::create({.width = 320, .height = 240, .layout = PanelLayout::PlotRight});
    Result<VideoWriter> v = VideoWriter::open({.path = video, .width = 320, .height = 240, .fps = 30});
    EXPECT_TRUE(r.ok() && v.ok()) << r.error() << v.error();
    if (!r.ok() || !v.ok()) return 0;
    renderer.emplace(std::move(r.value()));
    mp4.emplace(std::move(v.value()));
  }
  const FramePicker picker(run.simulation().dt(), 30);
  Image frame;
  while (run.simulation().time() + 0.5 * run.simulation().dt() < seconds) {
    const std::int64_t step = run.simulation().stepCount();
    run.step();
    if (!view) continue;
    view->update(run);
    for (int k = picker.framesAt(step); k > 0; --k) {
      renderer->renderInto(view->scene(), view->plots(), frame);
      EXPECT_TRUE(mp4->write(frame).ok());
    }
    if (step % 100 == 0) EXPECT_TRUE(writePng(framePath(pngDir, step / 100), renderer->render(view->scene(), view->plots())).ok());
  }
  if (mp4) EXPECT_TRUE(mp4->close().ok());
  return run.recorder().trajectoryHash();
}

TEST(RunView, RenderingNeverChangesSimulationResultsAndFiveSecondsMake150Frames) {
  const fs::path dir = fs::path(FROB_ACTUAL_DIR) / "run_view_test";
  fs::remove_all(dir);
  fs::create_directories(dir / "frames");
  const std::string video = (dir / "run.mp4").string();
  const std::uint64_t rendered = trajectory(5.0, video, (dir / "frames").string());
  const std::uint64_t plain = trajectory(5.0, "", "");
  EXPECT_EQ(rendered, plain) << std::hex << rendered << " vs " << plain;
  EXPECT_NE(rendered, worlds::kFnvOffset);
  // 500 steps at 100 Hz, one frame every 1/30 s: frames 0 .. 149.
  const testing::Decoded d = testing::decode(video, true);
  ASSERT_EQ(d.frames, 150);
  // PNG frame 4 was drawn at step 400 (4.0 s), as was video frame 120: the same picture within the
  // codec's loss, and not the picture of a second earlier.
  Result<Image> png = readPng(framePath((dir / "frames").string(), 4));
  ASSERT_TRUE(png.ok()) << png.error();
  EXPECT_LE(testing::lumaOutliers(d.images[120], png.value()), testing::kCodecLumaOutliers);
  EXPECT_GT(testing::lumaOutliers(d.images[90], png.value()), testing::kCodecLumaOutliers);
}

}  // namespace
}  // namespace frob::render
