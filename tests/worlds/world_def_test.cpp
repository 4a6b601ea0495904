// Worlds built in code with designated initializers, and their checks.
#include "frob/worlds/world_def.hpp"

#include <gtest/gtest.h>

namespace frob::worlds {
namespace {

using namespace frob::literals;

TEST(WorldDef, BuildsInCodeWithDesignatedInitializers) {
  const WorldDef w{
      .description = "made in code",
      .size = {5.0, 5.0},
      .walls = {segmentWall({1, 1}, {1, 4}), rectangleWall({3, 3}, {4, 4}), circleWall({4, 1}, 0.3), polylineWall({{2, 1}, {2, 2}, {2.5, 2}}, true)},
      .points = {{.name = "goal", .position = {4.5, 4.5}}},
      .robots = {{.start = {.position = {0.5, 0.5}, .heading = 90_deg}, .sonar = {.count = 8}}},
  };
  EXPECT_TRUE(checkWorld(w).ok()) << checkWorld(w).error();
  EXPECT_EQ(robotSpec(w.robots[0]).sonarAngles.size(), 8u);
  EXPECT_EQ(findPoint(w, "goal"), Point2(4.5, 4.5));
  EXPECT_EQ(findPoint(w, "start"), std::nullopt);
}

// A ray meets the first surface of a wall ahead of it, of any shape, and misses what is behind or beside it.
TEST(WorldDef, ARayMeetsTheFirstSurfaceAhead) {
  const Point2 o(0, 0);
  const Vec2 east(1, 0);
  EXPECT_DOUBLE_EQ(rayToWall(o, east, segmentWall({2, -1}, {2, 1})), 2.0);
  EXPECT_EQ(rayToWall(o, east, segmentWall({-2, -1}, {-2, 1})), INFINITY);  // behind
  EXPECT_EQ(rayToWall(o, east, segmentWall({2, 0.5}, {2, 1})), INFINITY);   // beside
  EXPECT_DOUBLE_EQ(rayToWall(o, east, rectangleWall({3, -1}, {5, 1})), 3.0);
  EXPECT_DOUBLE_EQ(rayToWall(o, east, polylineWall({{4, 2}, {4, -2}, {1.5, -2}}, true)), 2.75);  // the closing edge, nearest
  EXPECT_DOUBLE_EQ(rayToWall(o, east, circleWall({5, 0}, 1)), 4.0);
  EXPECT_EQ(rayToWall(o, east, circleWall({5, 2}, 1)), INFINITY);
  EXPECT_EQ(rayToWall(o, east, circleWall({0, 0.5}, 1)), 0.0);  // from inside
}

TEST(WorldDef, ChecksNameTheFieldWithoutAFile) {
  WorldDef w{.size = {5.0, 5.0}, .walls = {circleWall({2, 2}, 1.0)}, .robots = {{.start = {.position = {2.5, 2.5}}}}};
  EXPECT_EQ(checkWorld(w).error(),
            "world: robot[0].start: the robot (radius 0.23 m, start_spread.position 0.02 m) may touch wall[0]; move it away or set "
            "start_spread.position = 0");
  w.robots[0].start.position = {4.5, 4.5};
  EXPECT_TRUE(checkWorld(w).ok()) << checkWorld(w).error();
  w.robots[0].sonar.rays = 0;
  EXPECT_EQ(checkWorld(w).error(), "world: robot[0].sonar.rays: must lie in [1, 64]");
  w.robots[0].sonar.rays = 5;
  w.walls.push_back(polylineWall({{1, 1}}));
  EXPECT_EQ(checkWorld(w).error(), "world: wall[1].points: expected 2 or more points, got 1");
  w.walls.pop_back();
  w.size = {0, 5};
  EXPECT_EQ(checkWorld(w).error(), "world: size: width and height must lie in (0, 1000] m, got [0, 5]");
}

}  // namespace
}  // namespace frob::worlds
