// Renderer throughput (issue 6): render-only frame rate, PNG and H.264 cost per frame, and a
// 60 s simulated run (100 Hz) to a 30 fps 640x480 MP4, end to end. Targets: render-only at least
// 1000 fps; the whole run in at most 5 s. Run by hand: build/tests/bench/render_bench
// (llvmpipe threads: the renderer sets LP_NUM_THREADS=0 unless it is already set in the environment).
#include "frob/render/renderer.hpp"
#include "frob/render/video.hpp"

#include <benchmark/benchmark.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <random>

namespace frob::render {
namespace {

constexpr double kDt = 0.01;        // simulation step, s
constexpr double kRunSeconds = 60;  // simulated run length
constexpr int kRobots = 3;

int rasterThreads() { return std::getenv("LP_NUM_THREADS") != nullptr ? -1 : 0; }

// A 16 x 12 m maze of about 200 one-metre walls, the same every time.
std::vector<Wall> maze() {
  std::mt19937 rng(6);
  std::vector<Wall> walls;
  for (int x = 0; x < 16; ++x) {
    walls.push_back({Point2(x, 0), Point2(x + 1, 0)});
    walls.push_back({Point2(x, 12), Point2(x + 1, 12)});
  }
  for (int y = 0; y < 12; ++y) {
    walls.push_back({Point2(0, y), Point2(0, y + 1)});
    walls.push_back({Point2(16, y), Point2(16, y + 1)});
  }
  for (int x = 1; x < 16; ++x)
    for (int y = 1; y < 12; ++y)
      if (rng() % 3 == 0) walls.push_back(rng() % 2 ? Wall{Point2(x, y), Point2(x + 1, y)} : Wall{Point2(x, y), Point2(x, y + 1)});
  return walls;
}

// Where robot `i` is at time `t`: a Lissajous figure through the maze.
Pose2 poseAt(int i, double t) {
  const double a = 0.11 + 0.03 * i, b = 0.07 + 0.02 * i;
  const Point2 p(8 + 6.5 * std::sin(a * t + i), 6 + 4.5 * std::sin(b * t + 2 * i));
  const Vec2 v(6.5 * a * std::cos(a * t + i), 4.5 * b * std::cos(b * t + 2 * i));
  return {p, std::atan2(v.y(), v.x())};
}

// The whole run as the adapter from the simulator would provide it: scenes for chosen steps, plots.
struct Run {
  FrameScene base;
  PlotSet plots;
  std::vector<std::vector<Point2>> paths, odomPaths;
  RobotSpec spec;

  Run() {
    base.bounds = {Point2(0, 0), Point2(16, 12)};
    base.walls = maze();
    base.points = {{"goal", Point2(14.5, 10.5), {}}, {"start", Point2(1.5, 1.5), {}}};
    for (int k = 0; k < 16; ++k) spec.sonarAngles.push_back(2 * pi * k / 16);
    const auto steps = static_cast<int>(kRunSeconds / kDt);
    paths.resize(kRobots), odomPaths.resize(kRobots);
    Series sonar{"front sonar (m)", {}, {}}, dist{"to goal (m)", {}, {}}, fwd{"forward (m/s)", {}, {}}, turn{"turn (rad/s)", {}, {}};
    for (int s = 0; s < steps; ++s) {
      const double t = s * kDt;
      for (int i = 0; i < kRobots; ++i) {
        const Pose2 p = poseAt(i, t);
        paths[i].push_back(p.position);
        odomPaths[i].push_back(p.position + Vec2(0.02 * t * std::cos(t * 0.05), 0.015 * t));
      }
      sonar.samples.push_back({t, 1.5 + std::sin(t * 0.7)});
      dist.samples.push_back({t, distance(poseAt(0, t).position, Point2(14.5, 10.5))});
      fwd.samples.push_back({t, 0.4 + 0.1 * std::sin(t)});
      turn.samples.push_back({t, 0.5 * std::sin(t * 0.3)});
    }
    plots.plots = {{"range", {sonar, dist}, 0.0, {}}, {"wheels", {fwd, turn}, {}, {}}};
    for (int k = 0; k < 6; ++k) plots.taskMarks.push_back({k * 10.0, k % 2 ? "avoid" : "driveTo"});
    plots.tEnd = kRunSeconds;
  }

  // The scene after simulation step `step`.
  FrameScene scene(std::int64_t step) const {
    FrameScene s = base;
    s.time = static_cast<double>(step) * kDt;
    for (int i = 0; i < kRobots; ++i) {
      RobotView r;
      r.name = "robot " + std::to_string(i);
      r.pose = poseAt(i, s.time);
      r.odometry = Pose2{odomPaths[i][static_cast<std::size_t>(step)], r.pose.heading + 0.01 * s.time};
      r.spec = spec;
      for (int k = 0; k < 16; ++k) r.sonar.push_back(0.3 + std::fmod(0.37 * (k + 1) + s.time, 2.5));
      if (step % 50 < 5) r.bumps = {{.bumper = 0, .angle = 0.3}};
      r.path.assign(paths[i].begin(), paths[i].begin() + step + 1);
      r.odometryPath.assign(odomPaths[i].begin(), odomPaths[i].begin() + step + 1);
      const Point2 goal(14.5, 10.5);
      r.picture = withColor(red, paintAt(goal, circle(0.3))) + arrow(r.pose.position, r.pose.position + 0.8 * (goal - r.pose.position).normalized()) +
                  withColor(green, polyline({r.pose.position, goal})) + paintAt(r.pose.position + Vec2(0.3, 0.3), text("seek"));
      r.task = (step / 1000) % 2 ? "avoid" : "driveTo(goal)";
      r.wheels = {0.4, 0.2 * std::sin(s.time)};
      s.robots.push_back(std::move(r));
    }
    return s;
  }
};

const Run& run() {
  static const Run r;
  return r;
}

void reportFps(benchmark::State& state, std::int64_t frames) {
  state.counters["fps"] = benchmark::Counter(static_cast<double>(frames), benchmark::Counter::kIsRate);
}

// Render only, scene already built (mid-run: paths of 30 s).
void BM_Render(benchmark::State& state, RenderDef def) {
  def.rasterThreads = rasterThreads();
  Result<Renderer> r = Renderer::create(def);
  if (!r) return state.SkipWithError(r.error().c_str());
  const FrameScene scene = run().scene(3000);
  Image img;
  for (auto _ : state) {
    r.value().renderInto(scene, run().plots, img);
    benchmark::DoNotOptimize(img.rgba.data());
  }
  reportFps(state, state.iterations());
}
// fps counters are per wall-clock second (UseRealTime): llvmpipe may rasterize on other threads.
BENCHMARK_CAPTURE(BM_Render, top_down_640x480, RenderDef{.hud = true})->UseRealTime();
BENCHMARK_CAPTURE(BM_Render, top_down_plots_640x480, RenderDef{.layout = PanelLayout::PlotRight})->UseRealTime();
BENCHMARK_CAPTURE(BM_Render, chase_640x480, RenderDef{.view = ViewMode::Chase})->UseRealTime();

void BM_WritePng(benchmark::State& state) {
  Result<Renderer> r = Renderer::create({.rasterThreads = rasterThreads()});
  if (!r) return state.SkipWithError(r.error().c_str());
  const Image img = r.value().render(run().scene(3000));
  const std::string path = (std::filesystem::temp_directory_path() / ("frob_render_bench." + std::to_string(::getpid()) + ".png")).string();
  for (auto _ : state) {
    if (Status s = writePng(path, img); !s) return state.SkipWithError(s.error().c_str());
  }
  std::filesystem::remove(path);
  reportFps(state, state.iterations());
}
BENCHMARK(BM_WritePng)->Unit(benchmark::kMillisecond)->UseRealTime();

// H.264 encoding alone (colour conversion included), on 90 rendered frames of the run in turn.
void BM_Encode(benchmark::State& state, const char* preset) {
  Result<Renderer> r = Renderer::create({.layout = PanelLayout::PlotRight, .rasterThreads = rasterThreads()});
  if (!r) return state.SkipWithError(r.error().c_str());
  std::vector<Image> frames;
  for (int k = 0; k < 90; ++k) frames.push_back(r.value().render(run().scene(2000 + 10 * k), run().plots));
  const std::string path = (std::filesystem::temp_directory_path() / ("frob_render_bench_enc." + std::to_string(::getpid()) + ".mp4")).string();
  Result<VideoWriter> v = VideoWriter::open({.path = path, .fps = 30, .preset = preset});
  if (!v) return state.SkipWithError(v.error().c_str());
  std::size_t k = 0;
  for (auto _ : state) {
    if (Status s = v.value().write(frames[k++ % frames.size()]); !s) return state.SkipWithError(s.error().c_str());
  }
  (void)v.value().close();
  std::filesystem::remove(path);
  reportFps(state, state.iterations());
}
BENCHMARK_CAPTURE(BM_Encode, veryfast, "veryfast")->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_Encode, superfast, "superfast")->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_Encode, ultrafast, "ultrafast")->Unit(benchmark::kMillisecond)->UseRealTime();

// The whole 60 s run: build each frame's scene, render it with plots, encode it to MP4.
void BM_SixtySecondRunToMp4(benchmark::State& state) {
  const RenderDef def{.layout = PanelLayout::PlotRight, .rasterThreads = rasterThreads()};
  const std::string path = (std::filesystem::temp_directory_path() / ("frob_render_bench." + std::to_string(::getpid()) + ".mp4")).string();
  const FramePicker picker(kDt, 30);
  const std::vector<std::int64_t> steps = picker.steps(static_cast<std::int64_t>(kRunSeconds / kDt));
  (void)run();  // the simulated run itself is not part of the figure
  std::int64_t frames = 0;
  for (auto _ : state) {
    Result<Renderer> r = Renderer::create(def);
    Result<VideoWriter> v = VideoWriter::open({.path = path, .width = def.width, .height = def.height, .fps = 30});
    if (!r || !v) return state.SkipWithError((r.error() + v.error()).c_str());
    Image img;
    for (std::int64_t step : steps) {
      r.value().renderInto(run().scene(step), run().plots, img);
      if (Status s = v.value().write(img); !s) return state.SkipWithError(s.error().c_str());
    }
    if (Status s = v.value().close(); !s) return state.SkipWithError(s.error().c_str());
    frames += static_cast<std::int64_t>(steps.size());
  }
  std::filesystem::remove(path);
  state.counters["frames"] = static_cast<double>(steps.size());
  state.counters["seconds"] = benchmark::Counter(static_cast<double>(frames) / static_cast<double>(steps.size()),
                                                 benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  reportFps(state, frames);
}
BENCHMARK(BM_SixtySecondRunToMp4)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();

}  // namespace
}  // namespace frob::render
