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
#include <fstream>
#include <set>

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
    ASSERT_FALSE(world.robots.empty());
    ASSERT_FALSE(world.points.empty());
    const Point2 start = world.robots.front().start.position;
    for (const RobotDef& r : world.robots) {
      EXPECT_GE(nearestWall(withEnclosure(world), r.start.position), kRadius + 0.1) << "seed " << seed << ": " << r.name;
      EXPECT_TRUE(reachable(world, start, r.start.position)) << toString(GetParam()) << " seed " << seed << ": " << r.name;
    }
    for (const Landmark& p : world.points) {
      EXPECT_GE(nearestWall(withEnclosure(world), p.position), kRadius + 0.1) << "seed " << seed << ": " << p.name;
      EXPECT_TRUE(reachable(world, start, p.position)) << toString(GetParam()) << " seed " << seed << ": " << p.name;
    }
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
  ASSERT_EQ(back->points.size(), made.points.size());
  for (std::size_t i = 0; i < made.points.size(); ++i) EXPECT_EQ(back->points[i].position, made.points[i].position) << made.points[i].name;
  ASSERT_EQ(back->robots.size(), made.robots.size());
  for (std::size_t i = 0; i < made.robots.size(); ++i) {
    EXPECT_EQ(back->robots[i].start.position, made.robots[i].start.position) << i;
    EXPECT_NEAR(back->robots[i].start.heading, made.robots[i].start.heading, 1e-12) << i;
  }
  ASSERT_EQ(back->keys.size(), made.keys.size());
  for (std::size_t i = 0; i < made.keys.size(); ++i) EXPECT_EQ(back->keys[i].time, made.keys[i].time) << i;
  EXPECT_EQ(back->seed, made.seed);
  EXPECT_EQ(toToml(*back), toToml(made));
}

INSTANTIATE_TEST_SUITE_P(Generate, EveryKind,
                         ::testing::Values(WorldKind::Obstacles, WorldKind::Maze, WorldKind::Rooms, WorldKind::Loop, WorldKind::FurnishedRoom,
                                           WorldKind::Outline, WorldKind::Lounge, WorldKind::WarehouseKeys, WorldKind::WarehouseBox,
                                           WorldKind::Crossing),
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

// bug: no blind drive along the outer walls reaches the goal. The band within 1.3 m of them (the
// obstacles keep 1 m clear) is cut on both ways round, from the start's corner to the goal's, and
// again, nearly always, past the start's clear circle (2.5 m round it), where a drive could go
// round the tip of the spur beside the start: the spur further along is drawn last, where it fits
// beside the obstacles (in 200 fields it did not fit 5 times of 400).
TEST(Generate, AnObstacleFieldLeavesNoWayAlongTheWalls) {
  int open = 0;
  for (std::uint64_t seed = 1; seed <= 200; ++seed) {
    WorldDef band = generateWorld(WorldKind::Obstacles, seed).value();
    ASSERT_TRUE(reachable(band, band.robots[0].start.position, band.points[0].position)) << "seed " << seed;
    band.walls.push_back(rectangleWall(Point2(1.3, 1.3), Point2(band.size.x() - 1.3, band.size.y() - 1.3)));
    const Point2 goalCorner(band.size.x() - 0.6, band.size.y() - 0.6);
    EXPECT_FALSE(reachable(band, Point2(0.6, 0.6), goalCorner)) << "seed " << seed;
    open += reachable(band, Point2(4.6, 0.6), goalCorner);  // along the bottom wall
    open += reachable(band, Point2(0.6, 4.6), goalCorner);  // along the left wall
  }
  EXPECT_LE(open, 8);
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
  const std::pair<WorldKind, std::uint64_t> golden[] = {
      {WorldKind::Obstacles, 0xefdaa1b9469a55b2}, {WorldKind::Maze, 0x8d6d1211bd3c238a},          {WorldKind::Rooms, 0x6c928bc0cf02103b},
      {WorldKind::Loop, 0xddba8c29c890a141},      {WorldKind::FurnishedRoom, 0x055da3aee7223373}, {WorldKind::Outline, 0xd470583866fc7264},
      {WorldKind::Lounge, 0x5bbc189ffaf29cfb},    {WorldKind::WarehouseKeys, 0x388a10db183f71d2}, {WorldKind::WarehouseBox, 0xb236db9e97dc6cad},
      {WorldKind::Crossing, 0x86c3e8a50f63b372}};
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
  EXPECT_EQ(worldKind("warehouse_box"), WorldKind::WarehouseBox);
  EXPECT_EQ(worldKind("mazes"), std::nullopt);
  EXPECT_EQ(worldKindNames(), "obstacles, maze, rooms, loop, furnished_room, outline, lounge, warehouse_keys, warehouse_box, crossing");
}

// The assignments' families: each keeps what its handout promises, re-checked here independently.

// wander: every piece of furniture stands clear of the others and of the walls by 0.8 m (room to
// pass), or against the outer walls; nothing stands in the doorway.
TEST(Generate, AFurnishedRoomLeavesRoomToPassEverywhere) {
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    const WorldDef w = generateWorld(WorldKind::FurnishedRoom, seed).value();
    ASSERT_GE(w.walls.size(), 4u + 1u) << "seed " << seed;  // the house, two door posts, and furniture
    const std::vector<WallDef> all = withEnclosure(w);
    std::vector<std::vector<std::size_t>> pieces;  // furniture: walls that touch each other belong to one piece
    for (std::size_t i = 4; i < w.walls.size(); ++i) {
      const bool joins = !pieces.empty() && gap(w.walls[i], w.walls[pieces.back().front()], 0.5) < 0.03;
      if (joins)
        pieces.back().push_back(i);
      else
        pieces.push_back({i});
    }
    for (const auto& piece : pieces) {
      for (std::size_t j = 0; j < all.size(); ++j) {
        if (std::find(piece.begin(), piece.end(), j) != piece.end()) continue;
        double d = INFINITY;
        for (std::size_t i : piece) d = std::min(d, gap(w.walls[i], all[j], 1.0));
        const bool outerWall = j >= w.walls.size();
        EXPECT_TRUE(d > 0.8 - 0.03 || (outerWall && d < 0.03)) << "seed " << seed << ": wall " << piece.front() << " and " << j << ": " << d;
      }
    }
  }
}

// wall_follow: a closed outline with corners of both kinds (a left turn round the room is concave
// for a robot with the wall on its right, a right turn convex).
TEST(Generate, AnOutlineHasConcaveAndConvexCorners) {
  for (std::uint64_t seed = 1; seed <= 12; ++seed) {
    const WorldDef w = generateWorld(WorldKind::Outline, seed).value();
    ASSERT_EQ(w.walls.size(), 1u);
    const std::vector<Point2>& v = w.walls[0].points;
    ASSERT_TRUE(w.walls[0].closed);
    int left = 0, right = 0;
    for (std::size_t i = 0; i < v.size(); ++i) {
      const Vec2 a = v[(i + 1) % v.size()] - v[i], b = v[(i + 2) % v.size()] - v[(i + 1) % v.size()];
      (a.x() * b.y() - a.y() * b.x() > 0 ? left : right) += 1;
    }
    EXPECT_EQ(left - right, 4) << "seed " << seed;  // counter-clockwise, the way a right-wall follower goes round
    EXPECT_GE(right, 2) << "seed " << seed;
  }
}

// go_to_goal: the handout's waypoints, and something on the straight line of every leg between them.
TEST(Generate, ALoungeBlocksEveryLegBetweenTheWaypoints) {
  for (std::uint64_t seed = 1; seed <= 12; ++seed) {
    const WorldDef w = generateWorld(WorldKind::Lounge, seed).value();
    const Point2 wp[] = {*findPoint(w, "wp1"), *findPoint(w, "wp2"), *findPoint(w, "wp3"), *findPoint(w, "wp4")};
    EXPECT_EQ(wp[0], Point2(3.0, 2.5));
    for (int k = 0; k < 3; ++k) {
      double nearest = INFINITY;
      for (int i = 0; i <= 200; ++i) nearest = std::min(nearest, nearestWall(w.walls, wp[k] + (wp[k + 1] - wp[k]) * (i / 200.0)));
      EXPECT_LT(nearest, 0.03) << "seed " << seed << ": leg " << k + 1;
    }
  }
}

// go_to_goal: no fixed way is clear in every lounge. Pieces stand against the walls, and free ones
// well away from the legs' lines; in 40 lounges, a piece comes within the body's width (plus 0.1 m)
// of every point of a grid over the room but those near the waypoints and the start, so no line
// through the room and no way along its walls is kept clear.
TEST(Generate, ALoungeKeepsNoWayClearForAFixedRoute) {
  std::vector<WorldDef> lounges;
  for (std::uint64_t seed = 1; seed <= 40; ++seed) lounges.push_back(generateWorld(WorldKind::Lounge, seed).value());
  int againstAWall = 0, blocked = 0, points = 0;
  for (const WorldDef& w : lounges) {
    againstAWall += std::any_of(w.walls.begin(), w.walls.end(), [&](const WallDef& wall) {
      return wall.shape == WallShape::Rectangle &&
             (wall.points[0].x() == 0 || wall.points[0].y() == 0 || wall.points[1].x() == 12 || wall.points[1].y() == 10);
    });
  }
  EXPECT_EQ(againstAWall, 40);
  const Point2 keep[] = {{3.0, 2.5}, {3.5, 7.5}, {9.0, 7.0}, {8.5, 2.5}, {1.5, 1.5}};
  for (double x = 0.5; x < 12; x += 0.5) {
    for (double y = 0.5; y < 10; y += 0.5) {
      const Point2 p(x, y);
      // Round the start, 1.3 m from anywhere its known spread (0.25 m) may put it.
      if (std::any_of(std::begin(keep), std::end(keep), [&](const Point2& q) { return (q - p).norm() < (q == keep[4] ? 1.55 : 1.3); })) continue;
      ++points;
      blocked += std::any_of(lounges.begin(), lounges.end(), [&](const WorldDef& w) { return nearestWall(w.walls, p) < 2 * kRadius + 0.1; });
    }
  }
  EXPECT_EQ(blocked, points);
}

// parallel: other keys, then s, last, between 16 and 24 s; or a box across the patrol's way.
TEST(Generate, AWarehouseHasTheEventsItsChecksWaitFor) {
  for (std::uint64_t seed = 1; seed <= 12; ++seed) {
    const WorldDef keys = generateWorld(WorldKind::WarehouseKeys, seed).value();
    ASSERT_GE(keys.keys.size(), 2u);
    EXPECT_EQ(keys.keys.back().key, 's');
    EXPECT_GE(keys.keys.back().time, 16.0);
    EXPECT_LE(keys.keys.back().time, 24.0);
    for (std::size_t i = 0; i + 1 < keys.keys.size(); ++i) {
      EXPECT_NE(keys.keys[i].key, 's') << "seed " << seed;
      EXPECT_LT(keys.keys[i].time, keys.keys.back().time) << "seed " << seed;
    }
    // Other keys in a burst up to s: stopping at any key after a set time, or soon after another, fails.
    const double lead = keys.keys.back().time - keys.keys[keys.keys.size() - 2].time;
    EXPECT_GE(lead, 0.0) << "seed " << seed;
    EXPECT_LE(lead, 3.0) << "seed " << seed;
    const WorldDef box = generateWorld(WorldKind::WarehouseBox, seed).value();
    ASSERT_EQ(box.walls.size(), 3u) << "seed " << seed;  // the block, the shelf and the box
    const Point2 route[] = {{1.5, 1.5}, {6.5, 1.5}, {6.5, 4.5}, {1.5, 4.5}};
    double nearest = INFINITY;  // from the way of the robot's centre to the box: less than its radius, so it bumps
    for (int k = 0; k < 3; ++k) {
      for (int i = 0; i <= 200; ++i) nearest = std::min(nearest, distanceToWall(route[k] + (route[k + 1] - route[k]) * (i / 200.0), box.walls[2]));
    }
    EXPECT_LT(nearest, kRadius) << "seed " << seed;
  }
}

// multi_robot: 2 to 4 robots, each goal opposite its start through the centre, goals 2 m apart;
// starts 2 to 4 m from the centre, each robot with a start delay (0 to 4 s) and top speed (0.4 to
// 0.6 m/s) of its own, written to the world file, so that no timetable fits every crossing. Round
// pillars stand round the middle, 1.5 m apart, 1 m from the walls and 0.9 m from starts and goals.
TEST(Generate, ACrossingSendsEveryRobotThroughTheCentre) {
  for (std::uint64_t seed = 1; seed <= 12; ++seed) {
    const WorldDef w = generateWorld(WorldKind::Crossing, seed).value();
    ASSERT_GE(w.robots.size(), 2u);
    ASSERT_LE(w.robots.size(), 4u);
    std::vector<Point2> goals;
    for (const RobotDef& r : w.robots) {
      const std::optional<Point2> goal = findPoint(w, "goal_" + r.name);
      ASSERT_TRUE(goal) << r.name;
      EXPECT_LT((*goal + r.start.position - Point2(10, 10)).norm(), 1e-9) << "seed " << seed << ": " << r.name;
      for (const Point2& g : goals) EXPECT_GT((g - *goal).norm(), 2.0) << "seed " << seed;
      goals.push_back(*goal);
      EXPECT_GE((r.start.position - Point2(5, 5)).norm(), 2.0 - 1e-3);
      EXPECT_LE((r.start.position - Point2(5, 5)).norm(), 4.0 + 1e-3);
      EXPECT_GE(r.drive.startDelay, 0.0);
      EXPECT_LE(r.drive.startDelay, 4.0);
      EXPECT_GE(r.drive.maxSpeed, 0.4);
      EXPECT_LE(r.drive.maxSpeed, 0.6);
    }
    ASSERT_GE(w.walls.size(), 4u) << "seed " << seed;
    for (std::size_t i = 0; i < w.walls.size(); ++i) {
      const WallDef& p = w.walls[i];
      ASSERT_EQ(p.shape, WallShape::Circle) << "seed " << seed;
      EXPECT_GE(p.radius, 0.2);
      EXPECT_LE(p.radius, 0.4);
      EXPECT_GE(nearestWall(withEnclosure({.size = w.size}), p.points[0]) - p.radius, 1.0 - 1e-3) << "seed " << seed;
      for (std::size_t j = 0; j < i; ++j) EXPECT_GE((w.walls[j].points[0] - p.points[0]).norm() - w.walls[j].radius - p.radius, 1.5 - 1e-3);
      for (const RobotDef& r : w.robots) {
        EXPECT_GE(distanceToWall(r.start.position, p), 0.9 - 1e-3) << "seed " << seed << ": " << r.name;
        EXPECT_GE(distanceToWall(*findPoint(w, "goal_" + r.name), p), 0.9 - 1e-3) << "seed " << seed << ": " << r.name;
      }
    }
    const std::string file = ::testing::TempDir() + "crossing.toml";
    std::ofstream(file) << toToml(w);
    const Result<WorldDef> back = loadWorld(file);
    ASSERT_TRUE(back) << back.error();
    for (std::size_t i = 0; i < w.robots.size(); ++i) {
      EXPECT_EQ(back->robots[i].drive.startDelay, w.robots[i].drive.startDelay);
      EXPECT_EQ(back->robots[i].drive.maxSpeed, w.robots[i].drive.maxSpeed);
    }
  }
  std::set<double> delays;
  for (std::uint64_t seed = 1; seed <= 12; ++seed) {
    const WorldDef w = generateWorld(WorldKind::Crossing, seed).value();  // a named world: a range-for keeps no temporary alive
    for (const RobotDef& r : w.robots) delays.insert(r.drive.startDelay);
  }
  EXPECT_GT(*delays.rbegin() - *delays.begin(), 3.0);
}

// multi_robot: no roundabout stays clear. A body driving any circle of 1 to 3 m round the centre
// runs 5 cm or more into a pillar somewhere on it (sampled every 2 cm of radius, every degree), in
// every crossing; the pillars stand at drawn places, so no other fixed way is clear in most of them
// either (tests/assignments/blind_adversary_test.cpp drives such ways).
TEST(Generate, ACrossingBlocksEveryRoundaboutRoundTheCentre) {
  const Point2 centre(5, 5);
  std::set<double> places;
  for (std::uint64_t seed = 1; seed <= 12; ++seed) {
    const WorldDef w = generateWorld(WorldKind::Crossing, seed).value();
    for (const WallDef& p : w.walls) places.insert(p.points[0].x());
    for (double radius = 1.0; radius <= 3.0 + 1e-9; radius += 0.02) {
      double deepest = INFINITY;  // the nearest a point of the circle comes to a pillar's surface (negative inside it)
      for (int deg = 0; deg < 360; ++deg) {
        const Point2 at = centre + radius * Vec2(std::cos(deg * pi / 180), std::sin(deg * pi / 180));
        for (const WallDef& p : w.walls) deepest = std::min(deepest, (at - p.points[0]).norm() - p.radius);
      }
      EXPECT_LT(deepest, kRadius - 0.05 + 0.005) << "seed " << seed << ": the circle of " << radius << " m is clear";
    }
  }
  EXPECT_GT(places.size(), 12u * 4u - 2u);  // drawn: hardly two pillars in one place
}

}  // namespace
}  // namespace frob::worlds
