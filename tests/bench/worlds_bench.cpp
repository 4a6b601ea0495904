// Benchmarks of the simulator (issue 5): real-time factor (simulated seconds per wall second) in
// the 20 x 20 m reference maze, our ray caster against Box2D's own, and Enki side by side with
// the same number of rays per robot per step. Run by hand for figures:
//   build/tests/bench/worlds_bench --benchmark_min_time=2
// At the end a table pairs each of our runs with the Enki run of the same rays and robots.
#include "frob/worlds/registry.hpp"
#include "frob/worlds/simulation.hpp"
#include "ray_caster.hpp"  // private header of worlds/, for the ray-cast micro benchmark

#include <benchmark/benchmark.h>
#include <box2d/box2d.h>
#include <enki/PhysicalEngine.h>
#include <enki/robots/e-puck/EPuck.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace {

using namespace frob;
using namespace frob::worlds;

constexpr double kDt = 0.01;  // 100 Hz

const WorldDef& maze() {
  static const WorldDef w = *loadReferenceWorld("maze");
  return w;
}

// The maze with `robots` robots in distinct cells (the cell centres of a 16 x 16 grid of 1.25 m),
// each with `sonars` sonars of `rays` rays.
WorldDef mazeWith(int robots, int sonars, int rays) {
  WorldDef w = maze();
  const RobotDef proto = w.robots.at(0);
  w.robots.clear();
  for (int k = 0; k < robots; ++k) {
    const int cell = (k * 37) % 256;  // 37 is coprime with 256: distinct cells
    RobotDef r = proto;
    r.start = {.position = Point2((cell % 16 + 0.5) * 1.25, (cell / 16 + 0.5) * 1.25), .heading = 0.7 * k};
    r.sonar.count = sonars;
    r.sonar.rays = rays;
    w.robots.push_back(r);
  }
  return w;
}

// Wander: ahead while the front sonar is clear, else turn on the spot.
Wheels wander(const SensorFrame& f) {
  const bool clear = f.sonar.empty() || f.sonar[0] > 0.6;
  return {.forward = clear ? 0.5 : 0.0, .turn = clear ? 0.1 : 1.0};
}

// Our simulator: one iteration is one 10 ms step (sense, controllers, physics).
void Ours(benchmark::State& state) {
  const int robots = static_cast<int>(state.range(0)), sonars = static_cast<int>(state.range(1)),
            rays = static_cast<int>(state.range(2)), threads = static_cast<int>(state.range(3));
  Simulation sim(mazeWith(robots, sonars, rays), {.dt = kDt, .threads = threads});
  std::vector<Wheels> wheels(sim.robotCount());
  for (auto _ : state) {
    sim.sense();
    for (std::size_t i = 0; i < wheels.size(); ++i) wheels[i] = wander(sim.frame(i));
    sim.step(wheels);
  }
  state.counters["rtf"] = benchmark::Counter(kDt, benchmark::Counter::kIsIterationInvariantRate);
  state.counters["rays/s"] =
      benchmark::Counter(double(robots) * sonars * rays, benchmark::Counter::kIsIterationInvariantRate);
}
// Args: robots, sonars, rays per sonar, threads.
BENCHMARK(Ours)->ArgNames({"robots", "sonars", "rays", "threads"})
    ->Args({1, 16, 5, 1})     // the target: >= 2000x real time
    ->Args({100, 16, 5, 1})
    ->Args({100, 16, 5, 2})   // the target: >= 30x real time on both cores
    ->Args({1, 8, 3, 1})      // as many rays as an Enki e-puck (8 IR sensors x 3 rays)
    ->Args({100, 8, 3, 1})
    ->Args({1, 16, 3, 1})     // as many rays as an e-puck given 16 long-range sensors
    ->Args({100, 16, 3, 1})
    ->UseRealTime()->Unit(benchmark::kMicrosecond);
// A fixed number of steps from the same start, so that instruction counts (valgrind --tool=callgrind,
// which counts independent of load) compare between builds:
//   valgrind --tool=callgrind build/tests/bench/worlds_bench --benchmark_filter=OursFixedSteps
BENCHMARK(Ours)->Name("OursFixedSteps")->ArgNames({"robots", "sonars", "rays", "threads"})
    ->Args({1, 16, 5, 1})->Args({100, 16, 5, 1})->Iterations(300)
    ->UseRealTime()->Unit(benchmark::kMicrosecond);

// Enki, the same maze in centimetres, walls as static thin boxes. With range(1) == 8 the e-pucks
// keep their own 8 infrared sensors (3 rays each, 12 cm range); with 16 they get 16 sensors of 3
// rays reaching 6.5 m, as far as our sonars.
void Enki(benchmark::State& state) {
  const int robots = static_cast<int>(state.range(0)), sensors = static_cast<int>(state.range(1));
  const WorldDef& w = maze();
  std::vector<std::unique_ptr<Enki::IRSensor>> extra;  // declared first: outlives the world and its robots
  Enki::World world(w.size.x() * 100, w.size.y() * 100);
  world.setRandomSeed(1);
  for (const WallDef& wall : w.walls) {
    const Point2 a = wall.points[0] * 100, b = wall.points[1] * 100;
    auto* o = new Enki::PhysicalObject;  // the world owns and deletes it
    o->setRectangular((b - a).norm() + 2.0, 2.0, 10.0, -1.0);
    o->pos = Enki::Point((a.x() + b.x()) / 2, (a.y() + b.y()) / 2);
    o->angle = std::atan2(b.y() - a.y(), b.x() - a.x());
    world.addObject(o);
  }
  std::vector<Enki::EPuck*> pucks;
  const WorldDef placed = mazeWith(robots, 0, 1);
  for (const RobotDef& r : placed.robots) {
    auto* e = new Enki::EPuck(sensors == 8 ? Enki::EPuck::CAPABILITY_BASIC_SENSORS : Enki::EPuck::CAPABILITY_NONE);
    e->pos = Enki::Point(r.start.position.x() * 100, r.start.position.y() * 100);
    e->angle = r.start.heading;
    if (sensors != 8)
      for (int k = 0; k < sensors; ++k) {
        const double a = 2 * pi * k / sensors;
        extra.push_back(std::make_unique<Enki::IRSensor>(e, Enki::Vector(3.7 * std::cos(a), 3.7 * std::sin(a)), 2.5,
                                                         a, 650.0, 3731.0, 0.3, 0.7, 0.0));
        e->addLocalInteraction(extra.back().get());
      }
    world.addObject(e);
    pucks.push_back(e);
  }
  for (auto _ : state) {
    for (std::size_t i = 0; i < pucks.size(); ++i) {
      Enki::EPuck* e = pucks[i];
      const double front = sensors == 8 ? e->infraredSensor0.getDist() : extra[i * sensors]->getDist();
      const bool clear = front > (sensors == 8 ? 5.0 : 60.0);
      e->leftSpeed = clear ? 10.0 : -5.0;
      e->rightSpeed = clear ? 10.5 : 5.0;
    }
    world.step(kDt);
  }
  state.counters["rtf"] = benchmark::Counter(kDt, benchmark::Counter::kIsIterationInvariantRate);
  state.counters["rays/s"] = benchmark::Counter(double(robots) * sensors * 3, benchmark::Counter::kIsIterationInvariantRate);
}
// Args: robots, sensors per robot (3 rays each).
BENCHMARK(Enki)->ArgNames({"robots", "sensors"})
    ->Args({1, 8})->Args({100, 8})->Args({1, 16})->Args({100, 16})
    ->UseRealTime()->Unit(benchmark::kMicrosecond);

// Deterministic rays spread over the maze: origins at cell centres, directions by golden angle.
struct Ray {
  Point2 origin;
  Vec2 dir;
};
std::vector<Ray> mazeRays() {
  std::vector<Ray> rays;
  for (int k = 0; k < 4096; ++k) {
    const int cell = (k * 37) % 256;
    const double a = 2.399963229728653 * k;
    rays.push_back({Point2((cell % 16 + 0.5) * 1.25, (cell / 16 + 0.5) * 1.25), unitVector(a)});
  }
  return rays;
}

// Box2D 2.4's b2World::RayCast over the maze walls (edges), closest hit within 6.5 m.
void RayCastBox2D(benchmark::State& state) {
  b2World world(b2Vec2(0, 0));
  b2BodyDef def;
  b2Body* ground = world.CreateBody(&def);
  Simulation sim(maze());
  for (const WallDef& w : sim.walls()) {
    b2EdgeShape e;
    e.SetTwoSided(b2Vec2(float(w.points[0].x()), float(w.points[0].y())),
                  b2Vec2(float(w.points[1].x()), float(w.points[1].y())));
    ground->CreateFixture(&e, 0.0f);
  }
  struct Closest : b2RayCastCallback {
    float fraction = 1;
    float ReportFixture(b2Fixture*, const b2Vec2&, const b2Vec2&, float f) override { return fraction = f; }
  };
  const std::vector<Ray> rays = mazeRays();
  std::size_t k = 0;
  for (auto _ : state) {
    const Ray& r = rays[k++ % rays.size()];
    Closest c;
    const b2Vec2 o(float(r.origin.x()), float(r.origin.y()));
    world.RayCast(&c, o, o + 6.5f * b2Vec2(float(r.dir.x()), float(r.dir.y())));
    benchmark::DoNotOptimize(c.fraction);
  }
  state.counters["rays/s"] = benchmark::Counter(1, benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(RayCastBox2D);

// Our uniform grid with DDA traversal over the same walls.
void RayCastGrid(benchmark::State& state) {
  Simulation sim(maze());
  const detail::RayCaster caster(sim.walls(), Point2(-1, -1), Point2(21, 21));
  const std::vector<Ray> rays = mazeRays();
  std::size_t k = 0;
  for (auto _ : state) {
    const Ray& r = rays[k++ % rays.size()];
    benchmark::DoNotOptimize(caster.cast(r.origin, r.dir, 6.5, -1));
  }
  state.counters["rays/s"] = benchmark::Counter(1, benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(RayCastGrid);

// The same rays as the axes of sonar cones of 5 rays (25 degrees wide, 22.5 degree specular
// cutoff), cast as the simulation casts them; rays/s counts all five.
void RayCastCone(benchmark::State& state) {
  Simulation sim(maze());
  const detail::RayCaster caster(sim.walls(), Point2(-1, -1), Point2(21, 21));
  const std::vector<Ray> rays = mazeRays();
  const double step = 25.0 * pi / 180.0 / 4.0, cosCutoff = std::cos(22.5 * pi / 180.0);
  struct Cone {
    std::array<double, 5> x, y;  // axis first, then outwards, as the simulation orders them
  };
  std::vector<Cone> cones;
  for (const Ray& r : rays) {
    const double a = std::atan2(r.dir.y(), r.dir.x());
    Cone c{};
    const double offsets[5] = {0.0, step, -step, 2 * step, -2 * step};
    for (int k = 0; k < 5; ++k) c.x[k] = std::cos(a + offsets[k]), c.y[k] = std::sin(a + offsets[k]);
    cones.push_back(c);
  }
  std::size_t k = 0;
  for (auto _ : state) {
    const std::size_t c = k++ % rays.size();
    benchmark::DoNotOptimize(caster.castCone(rays[c].origin, cones[c].x, cones[c].y, 6.5, -1, cosCutoff));
  }
  state.counters["rays/s"] = benchmark::Counter(5, benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(RayCastCone);

// Prints the usual console table, then one line per (robots, rays) pairing ours with Enki.
class PairingReporter : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    for (const Run& r : runs) {
      // One figure per benchmark: the run itself, or the median when repetitions are asked for.
      if (r.run_type == Run::RT_Aggregate && r.aggregate_name != "median") continue;
      auto rtf = r.counters.find("rtf");
      if (rtf != r.counters.end()) rtf_[r.run_name.str()] = rtf->second.value;
    }
  }
  void Finalize() override {
    ConsoleReporter::Finalize();
    const std::pair<const char*, const char*> pairs[] = {
        {"Ours/robots:1/sonars:8/rays:3/threads:1/real_time", "Enki/robots:1/sensors:8/real_time"},
        {"Ours/robots:100/sonars:8/rays:3/threads:1/real_time", "Enki/robots:100/sensors:8/real_time"},
        {"Ours/robots:1/sonars:16/rays:3/threads:1/real_time", "Enki/robots:1/sensors:16/real_time"},
        {"Ours/robots:100/sonars:16/rays:3/threads:1/real_time", "Enki/robots:100/sensors:16/real_time"},
    };
    std::printf("\nReal-time factor, same maze, same rays per robot per step (ours / Enki):\n");
    for (auto [ours, enki] : pairs) {
      auto a = rtf_.find(ours), b = rtf_.find(enki);
      if (a == rtf_.end() || b == rtf_.end()) continue;
      std::printf("  %-52s %10.0fx  vs Enki %10.0fx  ratio %6.2f\n", ours, a->second, b->second, a->second / b->second);
    }
  }

 private:
  std::map<std::string, double> rtf_;
};

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  PairingReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::Shutdown();
  return 0;
}
