// The world-file loader: a full world reads back as written, and every kind of bad input gives a
// message naming file, line and field instead of a crash.
#include "frob/worlds/world_file.hpp"

#include "frob/worlds/registry.hpp"

#include <gtest/gtest.h>

#include <string>

namespace frob::worlds {
namespace {

using namespace frob::literals;

TEST(WorldFile, ReadsEveryPartOfAWorld) {
  Result<WorldDef> w = parseWorld(R"(
    description = "test room"
    size = [8, 6.5]
    enclosed = false
    seed = 99
    [sonar]
    noise = 0.05
    [[wall]]
    from = [1, 1]
    to = [1, 5]
    [[wall]]
    polyline = [[2, 1], [3, 1], [3, 2]]
    closed = true
    [[wall]]
    rect = [[6, 5], [5, 4]]
    [[wall]]
    circle = [7, 1]
    radius = 0.5
    [points]
    goal = [7.5, 6]
    [[robot]]
    name = "a"
    start = [2, 4]
    heading_deg = 90
    sonar = { count = 4, rays = 3 }
    odometry = { translation = 0.1 }
    drive = { max_speed = 1.5, slip = 0.05, slip_time = 1.5 }
    start_spread = { position = 0.1, heading_deg = 3 }
    [[robot]]
    start = [4, 2]
    sonar = { angles_deg = [0, 180], noise = 0 }
    [[key]]
    time = 2.5
    key = "q"
    robot = 1
  )",
                                  "room.toml");
  ASSERT_TRUE(w.ok()) << w.error();
  EXPECT_EQ(w->description, "test room");
  EXPECT_EQ(w->size, Vec2(8, 6.5));
  EXPECT_FALSE(w->enclosed);
  EXPECT_EQ(w->seed, 99u);
  ASSERT_EQ(w->walls.size(), 4u);
  EXPECT_EQ(w->walls[0].shape, WallShape::Segment);
  EXPECT_EQ(w->walls[1].shape, WallShape::Polyline);
  EXPECT_TRUE(w->walls[1].closed);
  EXPECT_EQ(w->walls[2].points[0], Point2(5, 4));  // corners normalised to min, max
  EXPECT_EQ(w->walls[3].radius, 0.5);
  EXPECT_EQ(findPoint(*w, "goal"), Point2(7.5, 6));
  ASSERT_EQ(w->robots.size(), 2u);
  EXPECT_EQ(w->robots[0].name, "a");
  EXPECT_DOUBLE_EQ(w->robots[0].start.heading, 90_deg);
  EXPECT_EQ(w->robots[0].sonar.count, 4);
  EXPECT_EQ(w->robots[0].sonar.rays, 3);
  EXPECT_EQ(w->robots[0].sonar.noise, 0.05);  // from the world-wide [sonar] defaults
  EXPECT_EQ(w->robots[0].odometry.translation, 0.1);
  EXPECT_EQ(w->robots[0].drive.maxSpeed, 1.5);
  EXPECT_EQ(w->robots[0].drive.slip, 0.05);
  EXPECT_EQ(w->robots[0].drive.slipTime, 1.5);
  EXPECT_EQ(w->robots[0].startSpread.position, 0.1);
  EXPECT_DOUBLE_EQ(w->robots[0].startSpread.heading, 3_deg);
  EXPECT_EQ(w->robots[1].sonar.noise, 0.0);  // overridden
  EXPECT_EQ(sonarAngles(w->robots[1].sonar).size(), 2u);
  ASSERT_EQ(w->keys.size(), 1u);
  EXPECT_EQ(w->keys[0].key, 'q');
  EXPECT_EQ(w->keys[0].robot, 1);
}

TEST(WorldFile, DefaultsAreANomad200) {
  Result<WorldDef> w = parseWorld("size = [4, 4]\n[[robot]]\nstart = [2, 2]\n", "x.toml");
  ASSERT_TRUE(w.ok()) << w.error();
  const RobotSpec spec = robotSpec(w->robots[0]);
  EXPECT_EQ(spec.radius, 0.23);
  ASSERT_EQ(spec.sonarAngles.size(), 16u);
  EXPECT_EQ(spec.sonarAngles[0], 0.0);
  EXPECT_NEAR(spec.sonarAngles[4], 90_deg, 1e-12);
  EXPECT_EQ(spec.sonarMinRange, 0.15);
  EXPECT_EQ(spec.sonarMaxRange, 6.5);
  EXPECT_TRUE(w->enclosed);
  // Its wheels slip, it starts near its start, its odometry drifts: a replayed path goes astray.
  const RobotDef& r = w->robots[0];
  EXPECT_EQ(r.drive.slip, 0.03);
  EXPECT_EQ(r.drive.slipTime, 2.0);
  EXPECT_EQ(r.startSpread.position, 0.02);
  EXPECT_DOUBLE_EQ(r.startSpread.heading, 0.5_deg);
  EXPECT_EQ(r.odometry.translation, 0.005);
  EXPECT_EQ(r.odometry.heading, 0.001);
  EXPECT_EQ(r.odometry.turn, 0.002);
}

// One bad world and the exact message it must give.
struct BadWorld {
  const char* what;
  const char* toml;
  const char* message;
};

class WorldFileErrors : public ::testing::TestWithParam<BadWorld> {};

TEST_P(WorldFileErrors, NameFileLineAndField) {
  Result<WorldDef> w = parseWorld(GetParam().toml, "maze.toml");
  ASSERT_FALSE(w.ok()) << GetParam().what;
  EXPECT_EQ(w.error(), GetParam().message) << GetParam().what;
}

INSTANTIATE_TEST_SUITE_P(
    Cases, WorldFileErrors,
    ::testing::Values(
        BadWorld{"missing size", "seed = 1\n", "maze.toml:1: size: missing (expected [width, height] in metres)"},
        BadWorld{"unknown top-level key", "size = [4, 4]\nsead = 3\n",
                 "maze.toml:2: sead: unknown key (expected one of description, size, enclosed, seed, wall, points, "
                 "robot, key, bitmap, mesh, sonar, odometry, drive, start_spread)"},
        BadWorld{"wrong type of point", "size = [4, 4]\n[[wall]]\nfrom = [1, 1]\nto = [2, 2]\n[[wall]]\nfrom = 3\nto = [1, 1]\n",
                 "maze.toml:6: wall[1].from: expected [x, y]"},
        BadWorld{"string for a number", "size = [4, 4]\n[[robot]]\nstart = [2, 2]\nradius = \"big\"\n",
                 "maze.toml:4: robot[0].radius: expected a number"},
        BadWorld{"negative size", "size = [-4, 4]\n", "maze.toml:1: size: width and height must be positive"},
        BadWorld{"nan", "size = [nan, 4]\n", "maze.toml:1: size: expected a finite number"},
        BadWorld{"typo in a robot", "size = [4, 4]\n[[robot]]\nstart = [2, 2]\nhaeding_deg = 3\n",
                 "maze.toml:4: robot[0].haeding_deg: unknown key (expected one of name, start, heading_deg, radius, "
                 "density, bumpers, sonar, odometry, drive, start_spread)"},
        BadWorld{"typo in a sonar", "size = [4, 4]\n[[robot]]\nstart = [2, 2]\n[robot.sonar]\ncone = 3\n",
                 "maze.toml:5: robot[0].sonar.cone: unknown key (expected one of count, angles_deg, cone_deg, rays, "
                 "min_range, max_range, specular_cutoff_deg, noise)"},
        BadWorld{"robot inside a wall", "size = [4, 4]\n[[wall]]\nrect = [[1, 1], [3, 3]]\n[[robot]]\nstart = [2, 2]\n",
                 "maze.toml:5: robot[0].start: the robot (radius 0.23 m, start_spread.position 0.02 m) may touch wall[0]; move it away "
                 "or set start_spread.position = 0"},
        BadWorld{"robot across a thin wall", "size = [4, 4]\n[[wall]]\nfrom = [2, 0]\nto = [2, 4]\n[[robot]]\nstart = [2.1, 2]\n",
                 "maze.toml:6: robot[0].start: the robot (radius 0.23 m, start_spread.position 0.02 m) may touch wall[0]; move it away "
                 "or set start_spread.position = 0"},
        BadWorld{"robot within its start spread of a wall", "size = [4, 4]\n[[wall]]\nfrom = [2, 0]\nto = [2, 4]\n[[robot]]\nstart = [2.24, 2]\n",
                 "maze.toml:6: robot[0].start: the robot (radius 0.23 m, start_spread.position 0.02 m) may touch wall[0]; move it away "
                 "or set start_spread.position = 0"},
        BadWorld{"slip out of range", "size = [4, 4]\n[[robot]]\nstart = [2, 2]\ndrive = { slip = 0.7 }\n",
                 "maze.toml:3: robot[0].drive.slip: must lie in [0, 0.5]"},
        BadWorld{"typo in a start spread", "size = [4, 4]\n[start_spread]\nheading = 1\n[[robot]]\nstart = [2, 2]\n",
                 "maze.toml:3: start_spread.heading: unknown key (expected one of position, heading_deg, known_position, known_heading_deg)"},
        BadWorld{"robot outside", "size = [4, 4]\n[[robot]]\nstart = [5, 2]\n",
                 "maze.toml:3: robot[0].start: the robot (radius 0.23 m, start_spread.position 0.02 m) may reach outside the world"},
        BadWorld{"robots overlap", "size = [4, 4]\n[[robot]]\nstart = [2, 2]\n[[robot]]\nstart = [2.2, 2]\n",
                 "maze.toml:5: robot[1].start: the robot (radius 0.23 m, start_spread.position 0.02 m) may overlap robot[0]"},
        BadWorld{"two wall shapes", "size = [4, 4]\n[[wall]]\nfrom = [1, 1]\nto = [2, 2]\ncircle = [1, 1]\n",
                 "maze.toml:2: wall[0]: give exactly one of from/to, polyline, rect, circle"},
        BadWorld{"segment without to", "size = [4, 4]\n[[wall]]\nfrom = [1, 1]\n", "maze.toml:2: wall[0].to: missing (a segment needs from and to)"},
        BadWorld{"zero-length wall", "size = [4, 4]\n[[wall]]\nfrom = [1, 1]\nto = [1, 1]\n",
                 "maze.toml:2: wall[0].to: the wall has (almost) zero length"},
        BadWorld{"wall outside", "size = [4, 4]\n[[wall]]\nfrom = [1, 1]\nto = [9, 1]\n",
                 "maze.toml:2: wall[0].points: (9, 1) lies outside the world [0, 4] x [0, 4]"},
        BadWorld{"circle without radius", "size = [4, 4]\n[[wall]]\ncircle = [1, 1]\n",
                 "maze.toml:2: wall[0].radius: missing (a circle needs a radius)"},
        BadWorld{"negative radius", "size = [4, 4]\n[[wall]]\ncircle = [1, 1]\nradius = -1\n", "maze.toml:4: wall[0].radius: must be positive"},
        BadWorld{"wall is not a table", "size = [4, 4]\nwall = [1, 2]\n", "maze.toml:2: wall[0]: expected a table"},
        BadWorld{"sonar count out of range", "size = [4, 4]\n[[robot]]\nstart = [2, 2]\nsonar = { count = 1000 }\n",
                 "maze.toml:4: robot[0].sonar.count: must lie in [0, 64]"},
        BadWorld{"max below min range", "size = [4, 4]\n[[robot]]\nstart = [2, 2]\nsonar = { min_range = 2, max_range = 1 }\n",
                 "maze.toml:3: robot[0].sonar.max_range: must exceed min_range and be at most 100 m"},
        BadWorld{"angles contradict count", "size = [4, 4]\n[[robot]]\nstart = [2, 2]\nsonar = { count = 3, angles_deg = [0] }\n",
                 "maze.toml:4: robot[0].sonar.angles_deg: has 1 angles but count is 3"},
        BadWorld{"negative odometry noise", "size = [4, 4]\n[odometry]\nturn = -1\n[[robot]]\nstart = [2, 2]\n",
                 "maze.toml:5: robot[0].odometry.turn: must lie in [0, 10]"},
        BadWorld{"point outside", "size = [4, 4]\n[points]\ngoal = [5, 5]\n", "maze.toml:3: points.goal: lies outside the world"},
        BadWorld{"long key", "size = [4, 4]\n[[key]]\ntime = 1\nkey = \"go\"\n", "maze.toml:4: key[0].key: expected exactly one character"},
        BadWorld{"key for no robot", "size = [4, 4]\n[[key]]\ntime = 1\nkey = \"g\"\nrobot = 3\n",
                 "maze.toml:2: key[0].robot: no robot with index 3"},
        BadWorld{"negative seed", "size = [4, 4]\nseed = -2\n", "maze.toml:2: seed: expected a non-negative integer"},
        BadWorld{"missing bitmap", "size = [4, 4]\n[bitmap]\nfile = \"nowhere.png\"\n", "maze.toml:3: bitmap.file: nowhere.png: no such bitmap file"},
        BadWorld{"missing mesh", "size = [4, 4]\n[mesh]\nfile = \"nowhere.obj\"\n", "maze.toml:3: mesh.file: nowhere.obj: no such mesh file"},
        BadWorld{"mesh up axis", "size = [4, 4]\n[mesh]\nfile = \"x.obj\"\nup = \"w\"\n", "maze.toml:4: mesh.up: expected \"z\" or \"y\""}));

TEST(WorldFile, SyntaxErrorsSayWhatTomlSaid) {
  Result<WorldDef> w = parseWorld("size = [4, 4\n", "maze.toml");
  ASSERT_FALSE(w.ok());
  EXPECT_TRUE(w.error().starts_with("maze.toml:")) << w.error();
  EXPECT_NE(w.error().find("syntax error"), std::string::npos) << w.error();
}

TEST(WorldFile, LoadWorldNamesAMissingFile) {
  Result<WorldDef> w = loadWorld("/nonexistent/dir/world.toml");
  ASSERT_FALSE(w.ok());
  EXPECT_EQ(w.error(), "/nonexistent/dir/world.toml: cannot open the world file");
}

TEST(WorldFile, MapPathsResolveRelativeToTheWorldFile) {
  // The office world names "office.png" without a folder: it must load from any working directory.
  Result<WorldDef> w = loadWorld(worldDataDir() / "office.toml");
  ASSERT_TRUE(w.ok()) << w.error();
  EXPECT_GT(w->walls.size(), 10u);
  // The same text parsed against another folder cannot find the bitmap, and says so.
  Result<WorldDef> elsewhere = parseWorld("size = [20, 15]\n[bitmap]\nfile = \"office.png\"\n", "o.toml", "/tmp/none");
  ASSERT_FALSE(elsewhere.ok());
  EXPECT_EQ(elsewhere.error(), "o.toml:3: bitmap.file: office.png: no such bitmap file");
}

}  // namespace
}  // namespace frob::worlds
