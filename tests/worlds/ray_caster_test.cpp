// The ray caster (private to worlds/): a cone cast in one call, with its rays four or five at a
// time in SIMD lanes, reads exactly what casting each ray alone reads, with AVX2 and without.
#include "frob/worlds/registry.hpp"
#include "frob/worlds/simulation.hpp"
#include "random.hpp"
#include "ray_caster.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace frob::worlds::detail {
namespace {

// The maze's walls, pillars and a box, and robots scattered over it, a few sticking out of the grid.
struct Scene {
  std::vector<WallDef> walls;
  std::vector<Point2> centres;
  std::vector<double> radii;
};

Scene crowdedMaze() {
  Scene s;
  s.walls = Simulation(*loadReferenceWorld("maze")).walls();
  for (int k = 0; k < 12; ++k) s.walls.push_back(circleWall(Point2(0.9 + 1.6 * k, 0.4 + 1.55 * k), 0.1 + 0.02 * k));
  s.walls.push_back(rectangleWall(Point2(8.1, 8.2), Point2(9.3, 9.0)));
  Rng rng(3, 0, Stream::Sonar);
  for (int k = 0; k < 150; ++k) {
    s.centres.emplace_back(-1.2 + 22.4 * rng.uniform(), -1.2 + 22.4 * rng.uniform());
    s.radii.push_back(0.1 + 0.2 * rng.uniform());
  }
  return s;
}

// What the simulation reads for a cone: the nearest echoing first hit of any ray, else the range.
double perRay(const RayCaster& c, const Point2& o, const std::vector<Vec2>& dirs, double range, int self,
              double cosCutoff) {
  double nearest = range;
  for (const Vec2& d : dirs) {
    const RayHit h = c.cast(o, d, range, self);
    if (h.cosIncidence >= cosCutoff) nearest = std::min(nearest, h.distance);
  }
  return nearest;
}

TEST(RayCaster, AConeReadsWhatItsRaysReadOneByOneOnEveryInstructionSet) {
  const Scene s = crowdedMaze();
  RayCaster caster(s.walls, Point2(-1, -1), Point2(21, 21));
  caster.setRobots(s.centres, s.radii);
  Rng rng(9, 1, Stream::Sonar);
  const double cosCutoff = std::cos(22.5 * pi / 180);
  int echoes = 0, inside = 0;
  for (int k = 0; k < 20000; ++k) {
    // Origins mostly on robots' rims (as sonars are), some anywhere, a few outside the grid.
    const int self = k % 3 == 0 ? -1 : static_cast<int>(rng.next() % s.centres.size());
    const double a = 2 * pi * rng.uniform();
    Point2 o = self < 0 ? Point2(-2.0 + 24.0 * rng.uniform(), -2.0 + 24.0 * rng.uniform())
                        : s.centres[static_cast<std::size_t>(self)] + s.radii[static_cast<std::size_t>(self)] * unitVector(a);
    const int rays = 1 + k % 9;
    const double width = (rays == 1 ? 0.0 : 25.0) * pi / 180, range = k % 5 == 0 ? 2.0 : 6.5;
    std::vector<Vec2> dirs;
    for (int r = 0; r < rays; ++r) dirs.push_back(unitVector(a + (rays == 1 ? 0.0 : width * (r / (rays - 1.0) - 0.5))));
    const double expected = perRay(caster, o, dirs, range, self, cosCutoff);
    std::vector<double> xs, ys;
    for (const Vec2& d : dirs) xs.push_back(d.x()), ys.push_back(d.y());
    const bool before = useAvx2(true);
    const double withAvx2 = caster.castCone(o, xs, ys, range, self, cosCutoff);
    useAvx2(false);
    const double baseline = caster.castCone(o, xs, ys, range, self, cosCutoff);
    useAvx2(before);
    ASSERT_EQ(withAvx2, expected) << "cone " << k;
    ASSERT_EQ(baseline, expected) << "cone " << k;
    echoes += expected < range;
    inside += expected == 0.0;
  }
  EXPECT_GT(echoes, 5000);  // the test sees plenty of echoes,
  EXPECT_GT(inside, 10);    // and origins inside other robots
}

}  // namespace
}  // namespace frob::worlds::detail
