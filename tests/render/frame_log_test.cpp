// A FrameLog notes a run's frames as it goes and draws them after it: every frame drawn afterwards has
// the pixels it had when drawn at its instant (moving pictures, growing paths, a chart that appears
// mid-run, task marks, the HUD's note), and frames repeated at one instant are repeated.
#include "frob/render/frame_log.hpp"

#include "../support/wanderer.hpp"
#include "frob/frob.hpp"
#include "frob/render/renderer.hpp"
#include "frob/render/video.hpp"
#include "frob/worlds/registry.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace frob::render {
namespace {

constexpr Color kMagenta{1.0f, 0.0f, 1.0f};

// For 2 s a disc that moves with time, then it wanders charting its left sonar as "left".
Task<Wheels> filmed() {
  TaskState ts = co_await getTaskState();
  co_await withPicture(lift([](double t) { return paintAt(Point2(1.0 + 0.5 * t, 1.875), withColor(kMagenta, disc(0.2))); }, time()),
                       mkTask([](const TaskState&) {
                         return std::pair{wheels(0.2, 0.3), after(2.0)};
                       }));
  co_await withPlot("left", sonar(ts.robot(), 4), support::runAround());
}

TEST(FrameLog, FramesDrawnAfterTheRunAreTheFramesDrawnDuringIt) {
  Result<worlds::WorldDef> world = worlds::loadReferenceWorld("maze");
  ASSERT_TRUE(world.ok()) << world.error();
  worlds::Run run(world.value(), {}, {[](const Robot& r) { return runTask(r, filmed()); }}, {.window = 1});
  RunView view(run, {.plotSeconds = 6.0});
  Result<Renderer> renderer = Renderer::create({.width = 320, .height = 180, .layout = PanelLayout::PlotRight});
  ASSERT_TRUE(renderer.ok()) << renderer.error();
  const FramePicker picker(run.simulation().dt(), 40.0);  // more frames than steps at times: some instants twice
  FrameLog film;
  std::vector<Image> during;
  while (run.simulation().time() < 6.0) {
    const std::int64_t step = run.simulation().stepCount();
    run.step();
    view.update(run);
    if (run.simulation().time() >= 4.0 && view.scene().note.empty()) view.setNote("a note from 4 s");
    for (int k = picker.framesAt(step); k > 0; --k) {
      during.push_back(renderer.value().render(view.scene(), view.plots()));
      film.note(view);
    }
  }
  ASSERT_EQ(film.size(), during.size());
  ASSERT_GT(during.size(), 200u);
  std::size_t k = 0, changed = 0;
  const Status s = film.replay(view, [&](const FrameScene& scene, const PlotSet& plots) {
    const Image after = renderer.value().render(scene, plots);
    EXPECT_TRUE(after.rgba == during.at(k).rgba) << "frame " << k << " at " << scene.time << " s";
    changed += k > 0 && during[k].rgba != during[k - 1].rgba ? 1 : 0;
    ++k;
    return Status();
  });
  EXPECT_TRUE(s.ok()) << s.error();
  EXPECT_EQ(k, during.size());
  EXPECT_GT(changed, during.size() / 2);  // the frames show a run going on, not one instant
  EXPECT_GT(view.plots().plots.size(), 2u) << "no chart of \"left\" appeared";
}

// Charts made once the run is over (what an assignment measures) are drawn in each frame below the
// noted ones, up to the frame's instant, with their levels; the noted charts are as they were.
TEST(FrameLog, ChartsMadeAfterTheRunGrowWithTheFrames) {
  Result<worlds::WorldDef> world = worlds::loadReferenceWorld("maze");
  ASSERT_TRUE(world.ok()) << world.error();
  worlds::Run run(world.value(), {}, {[](const Robot& r) { return runTask(r, support::runAround()); }}, {.window = 1});
  RunView view(run);
  FrameLog film;
  for (int k = 0; k < 100; ++k) {
    run.step();
    view.update(run);
    if (k % 10 == 9) film.note(view);
  }
  Plot measured{.title = "judged: clearance", .series = {{"clearance (m)", {}, green}}, .yMin = {}, .yMax = {}, .levels = {0.1}};
  for (int k = 0; k < 100; ++k) measured.series[0].samples.push_back({k * 0.01, 0.5 + 0.001 * k});
  std::vector<std::pair<double, std::size_t>> seen;  // each frame's instant, and the samples of the chart made afterwards
  const Status s = film.replay(view,
                               [&](const FrameScene& scene, const PlotSet& plots) {
                                 EXPECT_EQ(plots.plots.size(), view.plots().plots.size() + 1);
                                 EXPECT_EQ(plots.plots.back().title, "judged: clearance");
                                 EXPECT_EQ(plots.plots.back().levels, std::vector<double>{0.1});
                                 seen.emplace_back(scene.time, plots.plots.back().series[0].samples.size());
                                 return Status();
                               },
                               {measured});
  ASSERT_TRUE(s.ok()) << s.error();
  ASSERT_EQ(seen.size(), 10u);
  for (const auto& [t, samples] : seen) EXPECT_EQ(samples, static_cast<std::size_t>(std::llround(t / 0.01)) + 1) << t;
}

TEST(FrameLog, AReplayStopsAtTheFirstFrameThatFails) {
  Result<worlds::WorldDef> world = worlds::loadReferenceWorld("maze");
  ASSERT_TRUE(world.ok()) << world.error();
  worlds::Run run(world.value(), {}, {[](const Robot& r) { return runTask(r, support::runAround()); }}, {.window = 1});
  RunView view(run);
  FrameLog film;
  for (int k = 0; k < 10; ++k) {
    run.step();
    view.update(run);
    film.note(view);
  }
  int calls = 0;
  const Status s = film.replay(view, [&](const FrameScene&, const PlotSet&) { return ++calls == 3 ? Status::failure("disk full") : Status(); });
  EXPECT_EQ(s.error(), "disk full");
  EXPECT_EQ(calls, 3);
}

}  // namespace
}  // namespace frob::render
