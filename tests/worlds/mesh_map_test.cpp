// Mesh maps: a model sliced at sonar height into thin walls.
#include "frob/worlds/maps.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace frob::worlds {
namespace {

// A 2 x 1 x 1 box from (0, 0, 0), z up, as an OBJ file in the test's temp folder.
std::filesystem::path writeBox(const std::string& name, bool yUp = false) {
  const auto path = std::filesystem::path(::testing::TempDir()) / name;
  std::ofstream out(path);
  for (double z : {0.0, 1.0})
    for (auto [x, y] : {std::pair{0.0, 0.0}, {2.0, 0.0}, {2.0, 1.0}, {0.0, 1.0}})
      out << "v " << x << ' ' << (yUp ? z : y) << ' ' << (yUp ? -y : z) << '\n';
  out << "f 1 2 3\nf 1 3 4\nf 5 8 7\nf 5 7 6\nf 1 5 6\nf 1 6 2\nf 2 6 7\nf 2 7 3\nf 3 7 8\nf 3 8 4\nf 4 8 5\nf 4 5 1\n";
  return path;
}

double perimeter(const std::vector<WallDef>& walls) {
  double p = 0;
  for (const WallDef& w : walls) p += (w.points[1] - w.points[0]).norm();
  return p;
}

TEST(MeshMap, SlicesABoxIntoItsOutline) {
  Result<std::vector<WallDef>> walls = wallsFromMesh(writeBox("box.obj"), {.height = 0.3, .origin = Point2(1, 1)});
  ASSERT_TRUE(walls.ok()) << walls.error();
  EXPECT_EQ(walls->size(), 8u);  // two triangles per side, each cut once
  EXPECT_NEAR(perimeter(*walls), 6.0, 1e-6);
  for (const WallDef& w : *walls)
    for (const Point2& p : w.points) {
      EXPECT_GE(p.x(), 1.0 - 1e-9);
      EXPECT_LE(p.x(), 3.0 + 1e-9);
    }
}

TEST(MeshMap, ScaleAndUpAxisAreApplied) {
  Result<std::vector<WallDef>> walls = wallsFromMesh(writeBox("box_y.obj", true), {.height = 0.6, .scale = 2.0, .yUp = true});
  ASSERT_TRUE(walls.ok()) << walls.error();
  EXPECT_NEAR(perimeter(*walls), 12.0, 1e-6);
}

TEST(MeshMap, NoGeometryAtSonarHeightIsAnError) {
  Result<std::vector<WallDef>> walls = wallsFromMesh(writeBox("low.obj"), {.height = 1.5});
  ASSERT_FALSE(walls.ok());
  EXPECT_EQ(walls.error(), "low.obj: no geometry at height 1.5 m (the mesh spans heights 0 to 1 m)");
}

TEST(MeshMap, BadFilesGiveMessages) {
  EXPECT_EQ(wallsFromMesh("/nonexistent/m.obj", {}).error(), "m.obj: no such mesh file");
  const auto junk = std::filesystem::path(::testing::TempDir()) / "junk.stl";
  std::ofstream(junk) << "\x01\x02 not a mesh";
  EXPECT_FALSE(wallsFromMesh(junk, {}).ok());
}

TEST(MeshMap, WorldFileNamesTheFieldWhenTheSliceIsEmpty) {
  writeBox("room.obj");
  Result<WorldDef> w = parseWorld("size = [4, 4]\n[mesh]\nfile = \"room.obj\"\nheight = 2.0\n", "m.toml", ::testing::TempDir());
  ASSERT_FALSE(w.ok());
  EXPECT_EQ(w.error(), "m.toml:3: mesh.file: room.obj: no geometry at height 2 m (the mesh spans heights 0 to 1 m)");
}

}  // namespace
}  // namespace frob::worlds
