// Benchmarks of the simulator (issue 5): real-time factor (simulated seconds per wall second) in
// the 20 x 20 m reference maze, our ray caster against Box2D's own, and Enki side by side with
// the same number of rays per robot per step, Enki set up as its users would for speed (issue 17).
// Run by hand for figures:
//   build/tests/bench/worlds_bench --benchmark_min_time=2 --benchmark_repetitions=5
// At the end a table pairs each of our runs with the Enki runs of the same rays and robots, says
// what each side computes, and gives the fair ratio as the headline.
#include "cpu_figures.hpp"
#include "frob/worlds/generate.hpp"
#include "frob/worlds/registry.hpp"
#include "frob/worlds/simulation.hpp"
#include "ray_caster.hpp"  // private header of worlds/, for the ray-cast micro benchmark

#include <enki/robots/e-puck/EPuck.h>

#include <benchmark/benchmark.h>
#include <box2d/box2d.h>
#include <enki/PhysicalEngine.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

namespace {

using namespace frob;
using namespace frob::worlds;

constexpr double kDt = 0.01;  // 100 Hz
// Steps run before timing starts, in ours and in Enki alike: Enki's first steps with the maze as one
// object cost over ten times its later ones (16 ms against about 1 ms at 100 robots), so a short
// timed run measured mostly them; after 100 steps (1 s) a step costs about what it costs later.
constexpr int kWarmUpSteps = 100;

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
  const int robots = static_cast<int>(state.range(0)), sonars = static_cast<int>(state.range(1)), rays = static_cast<int>(state.range(2)),
            threads = static_cast<int>(state.range(3));
  Simulation sim(mazeWith(robots, sonars, rays), {.dt = kDt, .threads = threads});
  std::vector<Wheels> wheels(sim.robotCount());
  auto step = [&] {
    sim.sense();
    for (std::size_t i = 0; i < wheels.size(); ++i) wheels[i] = wander(sim.frame(i));
    sim.step(wheels);
  };
  for (int k = 0; k < kWarmUpSteps; ++k) step();
  for (auto _ : state) step();
  state.counters["rtf"] = benchmark::Counter(kDt, benchmark::Counter::kIsIterationInvariantRate);
  state.counters["rays/s"] = benchmark::Counter(double(robots) * sonars * rays, benchmark::Counter::kIsIterationInvariantRate);
}
// Args: robots, sonars, rays per sonar, threads.
BENCHMARK(Ours)
    ->ArgNames({"robots", "sonars", "rays", "threads"})
    ->Args({1, 16, 5, 1})  // the target: >= 2000x real time
    ->Args({100, 16, 5, 1})
    ->Args({100, 16, 5, 2})  // the target: >= 30x real time on both cores
    ->Args({1, 8, 3, 1})     // as many rays as an Enki e-puck (8 IR sensors x 3 rays)
    ->Args({100, 8, 3, 1})
    ->Args({1, 16, 3, 1})  // as many rays as an e-puck given 16 long-range sensors
    ->Args({100, 16, 3, 1})
    ->UseRealTime()
    ->Unit(benchmark::kMicrosecond);
// A fixed number of steps from the same start, so that instruction counts (valgrind --tool=callgrind,
// which counts independent of load) compare between builds:
//   valgrind --tool=callgrind build/tests/bench/worlds_bench --benchmark_filter=OursFixedSteps
BENCHMARK(Ours)
    ->Name("OursFixedSteps")
    ->ArgNames({"robots", "sonars", "rays", "threads"})
    ->Args({1, 16, 5, 1})
    ->Args({100, 16, 5, 1})
    ->Iterations(300)
    ->UseRealTime()
    ->Unit(benchmark::kMicrosecond);

// A robot standing still in the maze, as one is once its task has returned (half the steps of a
// graded class came after it): no robot moved, so its cones are not cast again.
void AtRest(benchmark::State& state) {
  Simulation sim(mazeWith(1, 16, 5), {.dt = kDt});
  const std::vector<Wheels> still(1);
  auto step = [&] {
    sim.sense();
    sim.step(still);
  };
  for (int k = 0; k < kWarmUpSteps; ++k) step();
  for (auto _ : state) step();
  state.counters["rtf"] = benchmark::Counter(kDt, benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(AtRest)->UseRealTime()->Unit(benchmark::kMicrosecond);

// A 100 x 100 m hall with a 10 x 10 grid of 2 x 2 m blocks, and `robots` robots between them.
WorldDef hallWith(int robots) {
  WorldDef w = maze();
  const RobotDef proto = w.robots.at(0);
  w.size = {100, 100};
  w.walls.clear();
  for (int i = 0; i < 10; ++i) {
    for (int j = 0; j < 10; ++j) w.walls.push_back(rectangleWall(Point2(9 + 10 * i, 9 + 10 * j), Point2(11 + 10 * i, 11 + 10 * j)));
  }
  w.robots.clear();
  for (int k = 0; k < robots; ++k) {  // a 32 x 32 grid of 3 m cells, clear of the blocks
    RobotDef r = proto;
    r.start = {.position = Point2(1.5 + 3.0 * (k % 32) + 0.3, 1.5 + 3.0 * (k / 32) + 0.3), .heading = 0.7 * k};
    w.robots.push_back(r);
  }
  return w;
}

// How the cost grows with the robot count (the Nomad's 16 sonars of 5 rays each), on both cores,
// and on one, where CPU time is the whole work of a step (with two, it is the main thread's only).
void Scale(benchmark::State& state) {
  Simulation sim(hallWith(static_cast<int>(state.range(0))), {.dt = kDt, .threads = static_cast<int>(state.range(1))});
  std::vector<Wheels> wheels(sim.robotCount());
  auto step = [&] {
    sim.sense();
    for (std::size_t i = 0; i < wheels.size(); ++i) wheels[i] = wander(sim.frame(i));
    sim.step(wheels);
  };
  for (int k = 0; k < kWarmUpSteps; ++k) step();
  for (auto _ : state) step();
  state.counters["rtf"] = benchmark::Counter(kDt, benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(Scale)->ArgNames({"robots", "threads"})->ArgsProduct({{1, 10, 100, 1000}, {2, 1}})->UseRealTime();  // target: 1000 on 2 at >= 5x

// A large map: 10,000 short walls, one every metre of a 100 x 100 m floor (a cluttered building
// floor plan has as many), and one robot among them.
WorldDef largeMap() {
  WorldDef w = hallWith(1);
  w.walls.clear();
  for (int i = 0; i < 100; ++i) {
    for (int j = 0; j < 100; ++j) w.walls.push_back(segmentWall(Point2(i + 0.3, j + 0.1), Point2(i + 0.7, j + 0.1)));
  }
  w.robots[0].start.position = Point2(50.5, 50.55);
  return w;
}

void LargeMap(benchmark::State& state) {
  const WorldDef w = largeMap();
  Simulation sim(w, {.dt = kDt});
  std::vector<Wheels> wheels(1);
  for (int k = 0; k < kWarmUpSteps; ++k) {
    sim.sense();
    sim.step(wheels);
  }
  for (auto _ : state) {
    sim.sense();
    wheels[0] = wander(sim.frame(0));
    sim.step(wheels);
  }
  state.counters["walls"] = static_cast<double>(w.walls.size());
  state.counters["rtf"] = benchmark::Counter(kDt, benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(LargeMap);  // target: >= 2000x with ~10,000 walls

// Building a simulation, which fits the ray caster's grid to the walls and the sonars: the maze,
// the hall with 1000 robots, the large map.
void Construct(benchmark::State& state) {
  const WorldDef w = state.range(0) == 0 ? maze() : state.range(0) == 1 ? hallWith(1000) : largeMap();
  for (auto _ : state) benchmark::DoNotOptimize(Simulation(w, {.dt = kDt}));
}
BENCHMARK(Construct)->ArgName("world")->DenseRange(0, 2)->Unit(benchmark::kMillisecond);

// Generating a hidden world of each kind, its promises checked (target: <= 50 ms); a new seed each time.
void GenerateWorld(benchmark::State& state) {
  const auto kind = static_cast<frob::worlds::WorldKind>(state.range(0));
  std::uint64_t seed = 1;
  for (auto _ : state) benchmark::DoNotOptimize(frob::worlds::generateWorld(kind, seed++));
  state.SetLabel(frob::worlds::toString(kind));
}
BENCHMARK(GenerateWorld)->ArgName("kind")->DenseRange(0, static_cast<int>(frob::worlds::WorldKind::Crossing))->Unit(benchmark::kMillisecond);

// Enki, the same maze in centimetres, configured as its users would for speed.
//
// What the e-pucks sense (range(1)):
//   0  EPuck(CAPABILITY_BASIC_SENSORS): in Enki's header that value (0x1) also passes the test for
//      CAPABILITY_SCANNER_TURRET (0x3), so the 64-pixel scanner turret runs too. Kept to show what
//      the earlier figures measured; not a fair pairing.
//   1  the 8 infrared sensors only (3 rays each, 12 cm): CAPABILITY_NONE, then the EPuck's own 8
//      IRSensor members added by hand.
//   2  16 infrared sensors of 3 rays reaching 6.5 m, as far as our sonars.
// How the walls are given (range(2)):
//   0  one static object per wall: Enki loops over all pairs of objects every step, so 225 walls cost
//      hundreds of microseconds a step with no robot at all;
//   1  one static object whose hull has one part per wall: the same rectangles, so the same ray
//      distances (EnkiLayoutsReadTheSame checks that), and one object to pair with each robot,
//      though its bounding circle spans the maze, so every sensor tests every part.
// The pairings take whichever layout is faster for the robots and sensors in question.
enum EnkiSensing { kTurretAndIr = 0, kIrOnly = 1, kLongRange16 = 2 };
enum EnkiWalls { kSeparate = 0, kOneObject = 1 };

// Wall `wall` of the maze as a 2 cm thick rectangle, 1 cm longer at each end (corners meet), in
// world centimetres, counter-clockwise as Enki wants its polygons.
Enki::Polygon wallRectangle(const WallDef& wall) {
  const Point2 a = wall.points[0] * 100, b = wall.points[1] * 100;
  const Vec2 t = (b - a).normalized(), n(-t.y(), t.x());
  Enki::Polygon p;
  for (const Point2& c : {Point2(a - t - n), Point2(b + t - n), Point2(b + t + n), Point2(a - t + n)}) p.push_back(Enki::Point(c.x(), c.y()));
  return p;
}

void addMaze(Enki::World& world, EnkiWalls walls) {
  Enki::PhysicalObject::Hull all;
  for (const WallDef& wall : maze().walls) {
    const Enki::PhysicalObject::Part part(wallRectangle(wall), 10.0);
    if (walls == kOneObject) {
      all.push_back(part);
      continue;
    }
    auto* o = new Enki::PhysicalObject;                        // the world owns and deletes it
    o->setCustomHull(Enki::PhysicalObject::Hull(part), -1.0);  // negative mass: static
    world.addObject(o);
  }
  if (walls == kOneObject) {
    auto* o = new Enki::PhysicalObject;
    o->setCustomHull(all, -1.0);
    world.addObject(o);
  }
}

// An Enki world with `robots` e-pucks in the cells our robots start in, sensing as `sensing` says.
struct EnkiMaze {
  std::vector<std::unique_ptr<Enki::IRSensor>> extra;  // declared first: outlives the world and its robots
  Enki::World world;
  std::vector<Enki::EPuck*> pucks;

  EnkiMaze(int robots, EnkiSensing sensing, EnkiWalls walls) : world(maze().size.x() * 100, maze().size.y() * 100) {
    world.setRandomSeed(1);
    addMaze(world, walls);
    for (const RobotDef& r : mazeWith(robots, 0, 1).robots) {
      auto* e = new Enki::EPuck(sensing == kTurretAndIr ? Enki::EPuck::CAPABILITY_BASIC_SENSORS : Enki::EPuck::CAPABILITY_NONE);
      e->pos = Enki::Point(r.start.position.x() * 100, r.start.position.y() * 100);
      e->angle = r.start.heading;
      if (sensing == kIrOnly) {
        for (Enki::IRSensor* ir : {&e->infraredSensor0, &e->infraredSensor1, &e->infraredSensor2, &e->infraredSensor3, &e->infraredSensor4,
                                   &e->infraredSensor5, &e->infraredSensor6, &e->infraredSensor7})
          e->addLocalInteraction(ir);
      }
      if (sensing == kLongRange16) {
        for (int k = 0; k < 16; ++k) {
          const double a = 2 * pi * k / 16;
          extra.push_back(
              std::make_unique<Enki::IRSensor>(e, Enki::Vector(3.7 * std::cos(a), 3.7 * std::sin(a)), 2.5, a, 650.0, 3731.0, 0.3, 0.7, 0.0));
          e->addLocalInteraction(extra.back().get());
        }
      }
      world.addObject(e);
      pucks.push_back(e);
    }
  }
  // The front sensor of robot i: infrared sensor 0 of the e-puck, or the first long-range one.
  const Enki::IRSensor& front(std::size_t i) const { return extra.empty() ? pucks[i]->infraredSensor0 : *extra[i * 16]; }
};

// One iteration is one 10 ms step: the same wander rule as ours, on the front sensor.
void Enki(benchmark::State& state) {
  const auto sensing = static_cast<EnkiSensing>(state.range(1));
  EnkiMaze m(static_cast<int>(state.range(0)), sensing, static_cast<EnkiWalls>(state.range(2)));
  const double near = sensing == kLongRange16 ? 60.0 : 5.0;  // cm
  auto step = [&] {
    for (std::size_t i = 0; i < m.pucks.size(); ++i) {
      const bool clear = m.front(i).getDist() > near;
      m.pucks[i]->leftSpeed = clear ? 10.0 : -5.0;
      m.pucks[i]->rightSpeed = clear ? 10.5 : 5.0;
    }
    m.world.step(kDt);
  };
  for (int k = 0; k < kWarmUpSteps; ++k) step();
  for (auto _ : state) step();
  state.counters["rtf"] = benchmark::Counter(kDt, benchmark::Counter::kIsIterationInvariantRate);
}
// Args: robots, sensing, walls (see above). One object saves Enki the pairs of walls but puts every
// part in range of every robot; measured after the warm-up it was the faster layout in every pairing.
BENCHMARK(Enki)
    ->ArgNames({"robots", "sensing", "walls"})
    ->Args({1, kTurretAndIr, kSeparate})
    ->Args({100, kTurretAndIr, kSeparate})  // the earlier, unfair setup
    ->Args({1, kIrOnly, kSeparate})
    ->Args({100, kIrOnly, kSeparate})
    ->Args({1, kIrOnly, kOneObject})
    ->Args({100, kIrOnly, kOneObject})
    ->Args({1, kLongRange16, kSeparate})
    ->Args({100, kLongRange16, kSeparate})
    ->Args({1, kLongRange16, kOneObject})
    ->Args({100, kLongRange16, kOneObject})
    ->UseRealTime()
    ->Unit(benchmark::kMicrosecond);

// The two wall layouts give the same ray distances: 100 e-pucks with 16 long-range sensors stand
// still for one step in each, and every ray of every sensor is compared. Fails (and so fails the
// smoke test) if any differs by more than 1e-9 cm (the parts are shifted to their centroid and
// back, which may round), or if too few rays hit a wall for the comparison to mean anything.
void EnkiLayoutsReadTheSame(benchmark::State& state) {
  double worst = 0;
  int hits = 0, rays = 0;
  for (auto _ : state) {
    EnkiMaze separate(100, kLongRange16, kSeparate), one(100, kLongRange16, kOneObject);
    separate.world.step(kDt);
    one.world.step(kDt);
    worst = 0, hits = 0, rays = 0;
    for (std::size_t s = 0; s < one.extra.size(); ++s) {
      for (unsigned k = 0; k < one.extra[s]->getRayCount(); ++k) {
        const double a = separate.extra[s]->getRayDist(k), b = one.extra[s]->getRayDist(k);
        worst = std::max(worst, std::abs(a - b));
        hits += b < 650.0;
        ++rays;
      }
    }
  }
  if (worst > 1e-9 || hits < rays / 2) state.SkipWithError("Enki's two wall layouts read different ray distances");
  state.counters["rays"] = rays;
  state.counters["hits"] = hits;
  state.counters["worst_cm"] = worst;
}
BENCHMARK(EnkiLayoutsReadTheSame)->Iterations(1)->Unit(benchmark::kMillisecond);

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
    e.SetTwoSided(b2Vec2(float(w.points[0].x()), float(w.points[0].y())), b2Vec2(float(w.points[1].x()), float(w.points[1].y())));
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

const worlds::detail::Neighbours noRobots;  // the ray micro benchmarks cast among walls only

// Our uniform grid with DDA traversal over the same walls.
void RayCastGrid(benchmark::State& state) {
  Simulation sim(maze());
  const worlds::detail::RayCaster caster(sim.walls(), Point2(-1, -1), Point2(21, 21));
  const std::vector<Ray> rays = mazeRays();
  std::size_t k = 0;
  for (auto _ : state) {
    const Ray& r = rays[k++ % rays.size()];
    benchmark::DoNotOptimize(caster.cast(r.origin, r.dir, 6.5, noRobots));
  }
  state.counters["rays/s"] = benchmark::Counter(1, benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(RayCastGrid);

// The same rays as the axes of sonar cones of 5 rays (25 degrees wide, 22.5 degree specular
// cutoff), cast as the simulation casts them; rays/s counts all five.
void RayCastCone(benchmark::State& state) {
  Simulation sim(maze());
  const worlds::detail::RayCaster caster(sim.walls(), Point2(-1, -1), Point2(21, 21));
  const std::vector<Ray> rays = mazeRays();
  const double step = 25.0 * pi / 180.0 / 4.0, cosCutoff = std::cos(22.5 * pi / 180.0);
  struct Cone {
    std::array<double, 5> x, y;  // axis first, then outwards, as the simulation orders them
  };
  std::vector<Cone> cones;
  std::vector<worlds::detail::Spread> spreads;
  for (const Ray& r : rays) {
    const double a = std::atan2(r.dir.y(), r.dir.x());
    Cone c{};
    const double offsets[5] = {0.0, step, -step, 2 * step, -2 * step};
    for (int k = 0; k < 5; ++k) c.x[k] = std::cos(a + offsets[k]), c.y[k] = std::sin(a + offsets[k]);
    cones.push_back(c);
    spreads.push_back(worlds::detail::spreadOf(c.x, c.y));
  }
  std::size_t k = 0;
  for (auto _ : state) {
    const std::size_t c = k++ % rays.size();
    benchmark::DoNotOptimize(caster.castCone(rays[c].origin, cones[c].x, cones[c].y, spreads[c], 6.5, cosCutoff, noRobots));
  }
  state.counters["rays/s"] = benchmark::Counter(5, benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(RayCastCone);

// Prints the usual console table, then every pairing of ours with Enki and what each side computes.
// The pairings use CPU time: every run here is single-threaded, and on a shared machine the wall
// clock also counts the time a process waited for a core.
class PairingReporter : public bench::CpuFiguresReporter {
 public:
  void Finalize() override {
    ConsoleReporter::Finalize();
    struct Pairing {
      int robots;
      const char *ours, *enki, *what;
    };
    // Enki names without the walls argument: both layouts are looked up, and the faster one is fair.
    const Pairing pairs[] = {
        {1, "Ours/robots:1/sonars:8/rays:3/threads:1", "Enki/robots:1/sensing:1", "8 x 3 rays; Enki's 8 IR sensors only"},
        {100, "Ours/robots:100/sonars:8/rays:3/threads:1", "Enki/robots:100/sensing:1", "8 x 3 rays; Enki's 8 IR sensors only"},
        {1, "Ours/robots:1/sonars:16/rays:3/threads:1", "Enki/robots:1/sensing:2", "16 x 3 rays to 6.5 m"},
        {100, "Ours/robots:100/sonars:16/rays:3/threads:1", "Enki/robots:100/sensing:2", "16 x 3 rays to 6.5 m"},
        {1, "Ours/robots:1/sonars:8/rays:3/threads:1", "Enki/robots:1/sensing:0", "unfair (earlier): Enki's turret too"},
        {100, "Ours/robots:100/sonars:8/rays:3/threads:1", "Enki/robots:100/sensing:0", "unfair (earlier): Enki's turret too"},
    };
    std::printf(
        "\nReal-time factors (CPU time) in the same 20 x 20 m maze, one 10 ms step per iteration, one thread each.\n"
        "  ours: Box2D 2.4 (robots against walls and each other), per sonar a cone of rays with a specular\n"
        "        cutoff and noise (6.5 m), odometry with noise, bumpers, a wander rule per robot.\n"
        "  Enki: its own physics over all pairs of objects, per IR sensor 3 rays (12 cm, or 6.5 m for the\n"
        "        16-sensor e-pucks) through a response function with noise, the same wander rule; the maze\n"
        "        as 225 wall objects or as one object of 225 parts (the same ray distances).\n");
    std::printf("  %-7s %-38s %9s %12s %12s %8s\n", "robots", "rays per robot", "ours", "Enki walls", "Enki 1 obj", "ratio");
    auto find = [&](const std::string& name) {
      const double s = seconds(name + "/real_time");
      return s > 0 ? kDt / s : -1.0;
    };
    double headline = -1;
    for (const Pairing& p : pairs) {
      const double ours = find(p.ours), separate = find(std::string(p.enki) + "/walls:0"), one = find(std::string(p.enki) + "/walls:1");
      const double enki = std::max(separate, one);  // the faster layout
      if (ours < 0 || enki <= 0) continue;
      std::printf("  %-7d %-38s %8.1fx %11.2fx %11.2fx %8.2f\n", p.robots, p.what, ours, separate, one, ours / enki);
      if (&p == &pairs[1]) headline = ours / enki;
    }
    std::printf("  (ratio: ours against Enki's faster layout; a layout not run shows as -1)\n");
    if (headline > 0) std::printf("Headline (fair): 100 robots, 8 x 3 rays each, against Enki's faster layout: ours %.1fx as fast\n", headline);
  }
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
