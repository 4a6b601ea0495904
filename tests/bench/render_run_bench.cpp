// The renderer driven by a real run (issue 6, with RunView): the reference maze (about 200 walls)
// with three robots running the paper's runAround, each publishing a picture. Render-only frame
// rates of a mid-run scene, with parts switched off to see where a frame's time goes, and a 60 s
// run (100 Hz) simulated, viewed, rendered with plots and encoded to a 30 fps 640x480 MP4.
// Run by hand: build/tests/bench/render_run_bench (figures in the render2 branch's report).
#include "../support/wanderer.hpp"
#include "frob/frob.hpp"
#include "frob/render/renderer.hpp"
#include "frob/render/run_view.hpp"
#include "frob/render/video.hpp"
#include "frob/worlds/registry.hpp"

#include <benchmark/benchmark.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>

namespace frob::render {
namespace {

using namespace frob::literals;

int rasterThreads() { return std::getenv("LP_NUM_THREADS") != nullptr ? -1 : 0; }

// runAround with a picture that follows the robot: a ring round it and an arrow ahead.
Behavior<Wheels> wanderer(const Robot& r) {
  Behavior<Picture> pic = lift(
      [](const Point2& at, double heading) {
        const Point2 ahead = at + 0.6 * Vec2(std::cos(heading), std::sin(heading));
        return paintAt(at, circle(0.35)) + withColor(red, arrow(at, ahead)) + paintAt(at + Vec2(0.3, 0.3), text("seek"));
      },
      Behavior<Point2>(place(r)), Behavior<double>(orientation(r)));
  return runTask(r, withPicture(pic, support::runAround(0.4)));
}

// The reference maze with two more robots: three in all.
worlds::WorldDef maze3() {
  worlds::WorldDef w = *worlds::loadReferenceWorld("maze");
  worlds::RobotDef extra = w.robots.at(0);
  extra.name = "second";
  extra.start = {{10.625, 10.625}, 0};
  w.robots.push_back(extra);
  extra.name = "third";
  extra.start = {{18.125, 0.625}, pi / 2};
  w.robots.push_back(extra);
  return w;
}

// A run of `seconds`, viewed step by step.
struct Viewed {
  worlds::Run run{maze3(), {}, {wanderer}};
  RunView view{run, {.plotSeconds = 60.0}};
  explicit Viewed(double seconds) {
    while (run.simulation().time() + 0.005 < seconds) {
      run.step();
      view.update(run);
    }
  }
};

enum Parts { kAll, kNoWalls, kNoSonar, kNoText, kEmpty };

// Render only, mid-run scene (30 s of paths), with parts left out to see what each costs.
void BM_RenderRun(benchmark::State& state, RenderDef def, Parts parts) {
  def.rasterThreads = rasterThreads();
  static const Viewed viewed(30.0);
  FrameScene scene = viewed.view.scene();
  if (parts == kNoWalls || parts == kEmpty) scene.walls.clear(), def.grid = false;
  if (parts == kNoSonar || parts == kEmpty) def.sonar = false;
  if (parts == kNoText || parts == kEmpty) def.hud = false, def.grid = false;
  if (parts == kEmpty) scene.robots.clear(), scene.points.clear();
  Result<Renderer> r = Renderer::create(def);
  if (!r) return state.SkipWithError(r.error().c_str());
  Image img;
  for (auto _ : state) {
    r.value().renderInto(scene, viewed.view.plots(), img);
    benchmark::DoNotOptimize(img.rgba.data());
  }
  state.counters["fps"] = benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK_CAPTURE(BM_RenderRun, all, RenderDef{}, kAll)->UseRealTime();
BENCHMARK_CAPTURE(BM_RenderRun, all_plots, RenderDef{.layout = PanelLayout::PlotRight}, kAll)->UseRealTime();
BENCHMARK_CAPTURE(BM_RenderRun, no_walls_grid, RenderDef{}, kNoWalls)->UseRealTime();
BENCHMARK_CAPTURE(BM_RenderRun, no_sonar, RenderDef{}, kNoSonar)->UseRealTime();
BENCHMARK_CAPTURE(BM_RenderRun, no_text, RenderDef{}, kNoText)->UseRealTime();
BENCHMARK_CAPTURE(BM_RenderRun, empty, RenderDef{}, kEmpty)->UseRealTime();

// The whole 60 s run: simulate, view, render frames with plots at 30 fps, encode (or not).
void BM_SixtySecondMazeRun(benchmark::State& state, bool render, bool video) {
  const RenderDef def{.layout = PanelLayout::PlotRight, .rasterThreads = rasterThreads()};
  const std::string path = (std::filesystem::temp_directory_path() / ("frob_render_run_bench." + std::to_string(::getpid()) + ".mp4")).string();
  const worlds::WorldDef world = maze3();
  for (auto _ : state) {
    worlds::Run run(world, {}, {wanderer});
    RunView view(run, {.plotSeconds = 60.0});
    std::optional<Renderer> r;
    std::optional<VideoWriter> v;
    if (render) {
      Result<Renderer> rr = Renderer::create(def);
      if (!rr) return state.SkipWithError(rr.error().c_str());
      r.emplace(std::move(rr.value()));
    }
    if (video) {
      Result<VideoWriter> vv = VideoWriter::open({.path = path, .width = def.width, .height = def.height, .fps = 30});
      if (!vv) return state.SkipWithError(vv.error().c_str());
      v.emplace(std::move(vv.value()));
    }
    const FramePicker picker(run.simulation().dt(), 30);
    Image img;
    while (run.simulation().time() + 0.005 < 60.0) {
      const std::int64_t step = run.simulation().stepCount();
      run.step();
      view.update(run);
      for (int k = r ? picker.framesAt(step) : 0; k > 0; --k) {
        r->renderInto(view.scene(), view.plots(), img);
        if (v) {
          if (Status s = v->write(img); !s) return state.SkipWithError(s.error().c_str());
        }
      }
    }
    if (v) {
      if (Status s = v->close(); !s) return state.SkipWithError(s.error().c_str());
    }
  }
  std::filesystem::remove(path);
}
BENCHMARK_CAPTURE(BM_SixtySecondMazeRun, simulate_only, false, false)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();
BENCHMARK_CAPTURE(BM_SixtySecondMazeRun, render, true, false)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();
BENCHMARK_CAPTURE(BM_SixtySecondMazeRun, render_mp4, true, true)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();

}  // namespace
}  // namespace frob::render
