// The registry of reference worlds; their golden-hash determinism tests are in determinism_test.cpp.
#include "frob/worlds/registry.hpp"

#include <gtest/gtest.h>

#include <string>

namespace frob::worlds {
namespace {

TEST(Registry, EveryReferenceWorldLoadsAndHasARobot) {
  ASSERT_GE(referenceWorlds().size(), 7u);
  for (const WorldEntry& e : referenceWorlds()) {
    EXPECT_TRUE(worldPath(e).is_absolute()) << e.name;
    Result<WorldDef> w = loadWorld(worldPath(e));
    ASSERT_TRUE(w.ok()) << e.name << ": " << w.error();
    EXPECT_FALSE(w->robots.empty()) << e.name;
    EXPECT_EQ(w->description, e.description) << e.name;  // the file and the registry agree
  }
}

TEST(Registry, FindsWorldsByName) {
  ASSERT_NE(findWorld("maze"), nullptr);
  EXPECT_EQ(findWorld("maze")->file, "maze.toml");
  EXPECT_EQ(findWorld("no such world"), nullptr);
  EXPECT_EQ(loadReferenceWorld("nowhere").error(), "no reference world called 'nowhere'");
  EXPECT_TRUE(loadReferenceWorld("empty").ok());
}

TEST(Registry, TheReferenceWorldsHaveWhatTheySay) {
  const WorldDef maze = *loadReferenceWorld("maze");
  EXPECT_GE(maze.walls.size(), 180u);
  EXPECT_LE(maze.walls.size(), 260u);
  EXPECT_EQ(maze.size, Vec2(20, 20));
  EXPECT_TRUE(findPoint(*loadReferenceWorld("obstacles"), "goal").has_value());
  EXPECT_GE(loadReferenceWorld("arena")->robots.size(), 4u);
  EXPECT_GT(loadReferenceWorld("mesh")->walls.size(), 10u);
  const WorldDef office = *loadReferenceWorld("office");
  EXPECT_GT(office.walls.size(), 10u);
  EXPECT_LT(office.walls.size(), 100u);  // merged into few rectangles, not one per pixel
}

}  // namespace
}  // namespace frob::worlds
