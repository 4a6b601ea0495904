// World generators: each kind keeps its promises for many seeds (checked here with brute-force
// distances and a flood fill of our own, not the generator's), writes a file that loads back to
// the same world, and the same kind and seed give the same world (golden hashes).
#include "frob/worlds/generate.hpp"

#include "frob/worlds/fnv.hpp"
#include "frob/worlds/world_file.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cinttypes>
#include <cmath>
#include <cstdio>

namespace frob::worlds {
namespace {

constexpr double kRadius = 0.23;

std::vector<WallDef> withEnclosure(const WorldDef& w) {
  std::vector<WallDef> all = w.walls;
  const Point2 a(0, 0), b(w.size.x(), 0), c = w.size, d(0, w.size.y());
  for (auto [p, q] : {std::pair{a, b}, {b, c}, {c, d}, {d, a}}) all.push_back(segmentWall(p, q));
  return all;
}

double nearestWall(const std::vector<WallDef>& walls, const Point2& p) {
  double d = INFINITY;
  for (const WallDef& w : walls) d = std::min(d, distanceToWall(p, w));
  return d;
}

// Whether the body can get from `a` to `b`: a flood fill over 10 cm cells whose centres keep the
// body clear of every wall (a coarser, independent check of the generator's 5 cm one).
bool reachable(const WorldDef& w, const Point2& a, const Point2& b) {
  const std::vector<WallDef> walls = withEnclosure(w);
  constexpr double cell = 0.1;
  const int nx = static_cast<int>(w.size.x() / cell), ny = static_cast<int>(w.size.y() / cell);
  const auto index = [&](const Point2& p) { return static_cast<int>(p.y() / cell) * nx + static_cast<int>(p.x() / cell); };
  std::vector<int> state(static_cast<std::size_t>(nx * ny), 0);  // 0 unknown, 1 free and seen, 2 blocked
  std::vector<int> stack{index(a)};
  state[index(a)] = 1;
  while (!stack.empty()) {
    const int c = stack.back();
    stack.pop_back();
    if (c == index(b)) return true;
    const int x = c % nx, y = c / nx;
    for (auto [dx, dy] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
      const int X = x + dx, Y = y + dy, n = Y * nx + X;
      if (X < 0 || Y < 0 || X >= nx || Y >= ny || state[n] != 0) continue;
      state[n] = nearestWall(walls, Point2((X + 0.5) * cell, (Y + 0.5) * cell)) >= kRadius ? 1 : 2;
      if (state[n] == 1) stack.push_back(n);
    }
  }
  return false;
}

// A wall's bounding box.
std::pair<Point2, Point2> boxOf(const WallDef& w) {
  Point2 lo = w.points[0], hi = lo;
  for (const Point2& p : w.points) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  return {lo - Vec2(w.radius, w.radius), hi + Vec2(w.radius, w.radius)};
}

// The gap between two walls: the least, over a 2 cm grid, of the sum of the distances to both. It
// is reached between them, so the grid covers their joint bounding box only; walls whose boxes are
// `enough` apart are at least that far apart and are not sampled.
double gap(const WallDef& a, const WallDef& b, double enough) {
  const auto [loA, hiA] = boxOf(a);
  const auto [loB, hiB] = boxOf(b);
  const Vec2 apart = (loB - hiA).cwiseMax(loA - hiB).cwiseMax(Vec2::Zero());
  if (apart.norm() > enough) return apart.norm();
  const Point2 lo = loA.cwiseMin(loB), hi = hiA.cwiseMax(hiB);
  double best = INFINITY;
  for (double x = lo.x(); x <= hi.x(); x += 0.02) {
    for (double y = lo.y(); y <= hi.y(); y += 0.02) best = std::min(best, distanceToWall({x, y}, a) + distanceToWall({x, y}, b));
  }
  return best;
}

class EveryKind : public ::testing::TestWithParam<WorldKind> {};

TEST_P(EveryKind, KeepsItsPromisesForManySeeds) {
  for (std::uint64_t seed = 1; seed <= 12; ++seed) {
    Result<WorldDef> w = generateWorld(GetParam(), seed);
    ASSERT_TRUE(w.ok()) << w.error();
    const WorldDef& world = w.value();
    EXPECT_EQ(world.seed, seed);
    const Point2 start = world.robots.at(0).start.position, goal = *findPoint(world, "goal");
    EXPECT_GE(nearestWall(withEnclosure(world), start), kRadius + 0.1) << "seed " << seed;
    EXPECT_GE(nearestWall(withEnclosure(world), goal), kRadius + 0.1) << "seed " << seed;
    EXPECT_TRUE(reachable(world, start, goal)) << toString(GetParam()) << " seed " << seed;
    EXPECT_TRUE(checkWorld(world).ok()) << checkWorld(world).error();
  }
}

TEST_P(EveryKind, WritesAFileThatLoadsBackToTheSameWorld) {
  const WorldDef made = generateWorld(GetParam(), 7).value();
  Result<WorldDef> back = parseWorld(toToml(made), "made.toml");
  ASSERT_TRUE(back.ok()) << back.error();
  ASSERT_EQ(back->walls.size(), made.walls.size());
  for (std::size_t i = 0; i < made.walls.size(); ++i) {
    EXPECT_EQ(back->walls[i].shape, made.walls[i].shape) << i;
    EXPECT_EQ(back->walls[i].points, made.walls[i].points) << i;  // exactly: coordinates are whole millimetres
    EXPECT_EQ(back->walls[i].radius, made.walls[i].radius) << i;
    EXPECT_EQ(back->walls[i].closed, made.walls[i].closed) << i;
  }
  EXPECT_EQ(back->points.at(0).position, made.points.at(0).position);
  EXPECT_EQ(back->robots.at(0).start.position, made.robots.at(0).start.position);
  EXPECT_EQ(back->seed, made.seed);
  EXPECT_EQ(toToml(*back), toToml(made));
}

INSTANTIATE_TEST_SUITE_P(Generate, EveryKind, ::testing::Values(WorldKind::Obstacles, WorldKind::Maze, WorldKind::Rooms, WorldKind::Loop),
                         [](const ::testing::TestParamInfo<WorldKind>& info) { return std::string(toString(info.param)); });

// Room for a wall follower (20 cm each side) between any two obstacles.
TEST(Generate, ObstaclesAreMoreThanTheRobotsDiameterApart) {
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    const WorldDef w = generateWorld(WorldKind::Obstacles, seed).value();
    ASSERT_GE(w.walls.size(), 8u);
    for (std::size_t i = 0; i < w.walls.size(); ++i) {
      for (std::size_t j = i + 1; j < w.walls.size(); ++j) {
        EXPECT_GT(gap(w.walls[i], w.walls[j], 1.0), 2 * kRadius + 0.3 - 0.03) << "seed " << seed << ": " << i << ", " << j;  // 2 cm grid
      }
    }
  }
}

// The L trap stands alone: nothing inside the square it spans, nothing within 1.5 m of it, so a robot
// following its walls meets no other obstacle.
TEST(Generate, TheTrapStandsAlone) {
  int traps = 0;
  for (std::uint64_t seed = 1; seed <= 8; ++seed) {
    const WorldDef w = generateWorld(WorldKind::Obstacles, seed).value();
    const auto trap = std::find_if(w.walls.begin(), w.walls.end(), [](const WallDef& wall) { return wall.shape == WallShape::Polyline; });
    if (trap == w.walls.end()) continue;
    ++traps;
    const std::vector<Point2>& l = trap->points;  // top-left, the corner, bottom-right
    const WallDef square = rectangleWall(Point2(l[0].x(), l[2].y()), l[1]);
    for (const WallDef& other : w.walls) {
      if (&other != &*trap) EXPECT_GT(gap(square, other, 2.0), 1.5 - 0.03) << "seed " << seed;  // 2 cm grid
    }
  }
  EXPECT_GE(traps, 2);  // seeds 1 to 8 hold traps to check
}

TEST(Generate, AMazeIsPerfect) {
  // A perfect maze of C x R cells keeps all but C R - 1 of its inner walls: one way between any two cells.
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    const WorldDef w = generateWorld(WorldKind::Maze, seed).value();
    const int cols = static_cast<int>(std::lround(w.size.x() / 1.6)), rows = static_cast<int>(std::lround(w.size.y() / 1.6));
    EXPECT_EQ(static_cast<int>(w.walls.size()), (cols - 1) * rows + cols * (rows - 1) - (cols * rows - 1)) << "seed " << seed;
  }
}

TEST(Generate, TheSameKindAndSeedGiveTheSameWorld) {
  // Golden hashes of the files, for this generator on every platform (it uses no library
  // randomness and writes millimetres). A change to a generator changes them: say so in its commit.
  const std::pair<WorldKind, std::uint64_t> golden[] = {{WorldKind::Obstacles, 0x507a6865ae68cffc},
                                                        {WorldKind::Maze, 0x8d6d1211bd3c238a},
                                                        {WorldKind::Rooms, 0x6c928bc0cf02103b},
                                                        {WorldKind::Loop, 0xddba8c29c890a141}};
  for (const auto& [kind, hash] : golden) {
    const std::string text = toToml(generateWorld(kind, 1).value());
    EXPECT_EQ(text, toToml(generateWorld(kind, 1).value()));
    const std::uint64_t actual = Fnv1a().add(std::string_view(text)).value();
    EXPECT_EQ(actual, hash) << toString(kind) << ": actual 0x" << std::hex << actual;
  }
  EXPECT_NE(toToml(generateWorld(WorldKind::Obstacles, 1).value()), toToml(generateWorld(WorldKind::Obstacles, 2).value()));
}

TEST(Generate, KindsByName) {
  EXPECT_EQ(worldKind("maze"), WorldKind::Maze);
  EXPECT_EQ(worldKind("mazes"), std::nullopt);
  EXPECT_EQ(worldKindNames(), "obstacles, maze, rooms, loop");
}

}  // namespace
}  // namespace frob::worlds
