// The ray caster (private to worlds/): a cone cast in one call, with its rays four or five at a
// time in SIMD lanes and only the robots it may meet tested, reads what a brute-force cast of every
// ray against every wall and robot reads, and the same bits with AVX-512, AVX2 and neither.
#include "ray_caster.hpp"

#include "frob/worlds/registry.hpp"
#include "frob/worlds/simulation.hpp"
#include "random.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
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

// The reference, independent of the caster: every ray against every wall and robot, no grid.
struct Hit {
  double distance = INFINITY;
  double cosIncidence = 1.0;
};

// Ray o + t d (unit d) against segment [a, b]: t from solving o + t d = a + v (b - a) by Cramer's rule.
void againstSegment(const Point2& o, const Vec2& d, const Point2& a, const Point2& b, Hit& best) {
  const Vec2 e = b - a, w = a - o;
  const double det = d.x() * e.y() - d.y() * e.x();
  if (det == 0.0) return;  // parallel: an edge-on wall is never heard
  const double t = (w.x() * e.y() - w.y() * e.x()) / det, v = (w.x() * d.y() - w.y() * d.x()) / det;
  if (t < 0.0 || v < 0.0 || v > 1.0 || t >= best.distance) return;
  const Vec2 n = Vec2(-e.y(), e.x()).normalized();
  best = {t, std::abs(d.dot(n))};
}

// Against a solid circle: an origin inside reads 0; else the nearer root of |o + t d - c| = r.
void againstCircle(const Point2& o, const Vec2& d, const Point2& c, double r, Hit& best) {
  const Vec2 p = o - c;
  if (p.squaredNorm() < r * r) {
    best = {0.0, 1.0};
    return;
  }
  const double b = p.dot(d), disc = b * b - (p.squaredNorm() - r * r);
  if (disc < 0 || b > 0) return;
  const double t = -b - std::sqrt(disc);
  if (t >= best.distance) return;
  best = {t, std::abs(d.dot((p + t * d) / r))};
}

Hit bruteForce(const Scene& s, const Point2& o, const Vec2& d, double range, int self) {
  Hit best{.distance = range};
  for (const WallDef& w : s.walls) {
    const std::vector<Point2>& v = w.points;
    switch (w.shape) {
      case WallShape::Segment:
        againstSegment(o, d, v[0], v[1], best);
        break;
      case WallShape::Polyline:
        for (std::size_t i = 0; i + 1 < v.size(); ++i) againstSegment(o, d, v[i], v[i + 1], best);
        if (w.closed) againstSegment(o, d, v.back(), v.front(), best);
        break;
      case WallShape::Rectangle: {
        const Point2 c[4] = {v[0], Point2(v[1].x(), v[0].y()), v[1], Point2(v[0].x(), v[1].y())};
        for (int k = 0; k < 4; ++k) againstSegment(o, d, c[k], c[(k + 1) % 4], best);
        break;
      }
      case WallShape::Circle:
        againstCircle(o, d, v[0], w.radius, best);
        break;
    }
  }
  for (std::size_t k = 0; k < s.centres.size(); ++k)
    if (static_cast<int>(k) != self) againstCircle(o, d, s.centres[k], s.radii[k], best);
  return best;
}

// What a sonar reads for a cone: the nearest echoing first hit of any ray, else the range. `ambiguous`
// is set when some ray's incidence is so near the cutoff that rounding could decide whether it echoes.
double coneByBruteForce(const Scene& s, const Point2& o, const std::vector<Vec2>& dirs, double range, int self, double cosCutoff, bool& ambiguous) {
  double nearest = range;
  for (const Vec2& d : dirs) {
    const Hit h = bruteForce(s, o, d, range, self);
    ambiguous |= h.distance < range && std::abs(h.cosIncidence - cosCutoff) < 1e-9;
    if (h.cosIncidence >= cosCutoff) nearest = std::min(nearest, h.distance);
  }
  return nearest;
}

// Whatever the grid's cells: the maze's own (about a metre), half a sonar's range, or as long, so that
// a cone is swept in one band.
class RayCasterOnGrid : public ::testing::TestWithParam<double> {};
INSTANTIATE_TEST_SUITE_P(Cells, RayCasterOnGrid, ::testing::Values(0.0, 3.3, 6.6));

// A tenth as many cones under the sanitizers, whose build leaves this test's own code unoptimised.
constexpr int kCones = __has_feature(address_sanitizer) ? 2000 : 20000;

TEST_P(RayCasterOnGrid, AConeReadsWhatABruteForceCastReadsOnEveryInstructionSet) {
  const Scene s = crowdedMaze();
  RayCaster caster(s.walls, Point2(-1, -1), Point2(21, 21), {.cell = GetParam()});
  if (GetParam() > 0) ASSERT_EQ(caster.cellSize(), GetParam());
  caster.setRobots(s.centres, s.radii, 6.5);
  Neighbours near;
  Rng rng(9, 1, Stream::Sonar);
  const double cosCutoff = std::cos(22.5 * pi / 180);
  int echoes = 0, inside = 0, skipped = 0, wide = 0, crowded = 0;
  for (int k = 0; k < kCones; ++k) {
    // Origins mostly on robots' rims (as sonars are), some anywhere, a few outside the grid.
    const int self = k % 3 == 0 ? -1 : static_cast<int>(rng.next() % s.centres.size());
    const double a = 2 * pi * rng.uniform();
    Point2 o = self < 0 ? Point2(-2.0 + 24.0 * rng.uniform(), -2.0 + 24.0 * rng.uniform())
                        : s.centres[static_cast<std::size_t>(self)] + s.radii[static_cast<std::size_t>(self)] * unitVector(a);
    const int rays = 1 + k % 9;
    // Mostly a sonar's 25 degrees; some cones as wide as a right angle or wider, where no robot is culled.
    const double width = (rays == 1 ? 0.0 : k % 7 == 0 ? 200.0 : k % 11 == 0 ? 90.0 : 25.0) * pi / 180, range = k % 5 == 0 ? 2.0 : 6.5;
    std::vector<Vec2> dirs;
    for (int r = 0; r < rays; ++r) dirs.push_back(unitVector(a + (rays == 1 ? 0.0 : width * (r / (rays - 1.0) - 0.5))));
    bool ambiguous = false;
    const double expected = coneByBruteForce(s, o, dirs, range, self, cosCutoff, ambiguous);
    std::vector<double> xs, ys;
    for (const Vec2& d : dirs) xs.push_back(d.x()), ys.push_back(d.y());
    // As the simulation gathers: around the sensing robot's centre, for sensors on its rim.
    if (self < 0)
      caster.gather(o, 0.0, range, self, near);
    else
      caster.gather(s.centres[static_cast<std::size_t>(self)], s.radii[static_cast<std::size_t>(self)], range, self, near);
    crowded += near.count > 8;  // ray_fan.cpp's kCrowd: tested without a branch on each segment's hit
    useIsa(Isa::Baseline);
    const double baseline = caster.castCone(o, xs, ys, spreadOf(xs, ys), range, cosCutoff, near);
    for (const Isa isa : {Isa::Avx2, Isa::Avx512}) {
      if (useIsa(isa) != isa) continue;  // the CPU lacks it
      ASSERT_EQ(caster.castCone(o, xs, ys, spreadOf(xs, ys), range, cosCutoff, near), baseline)
          << "cone " << k << ": instruction set " << static_cast<int>(isa) << " and plain x86-64 must agree bit for bit";
      ++wide;
    }
    useIsa(Isa::Avx512);
    skipped += ambiguous;
    if (ambiguous) continue;
    // The grid walk and the brute force round differently: 1e-12 m is far above that, far below any real miss.
    ASSERT_NEAR(baseline, expected, 1e-12) << "cone " << k;
    echoes += expected < range;
    inside += expected == 0.0;
  }
  EXPECT_LT(skipped, 10);                    // almost every cone is checked,
  EXPECT_GT(echoes, kCones / 4);             // the test sees plenty of echoes,
  EXPECT_GT(inside, kCones / 2000);          // and origins inside other robots,
  EXPECT_GT(crowded, kCones / 4);            // among many robots
  EXPECT_GT(kCones - crowded, kCones / 20);  // and among few
  std::printf("cones compared with a wider instruction set: %d; cast among more than eight robots: %d\n", wide, crowded);
}

// A hall of 2 m blocks 10 m apart, walled round, as the scale benchmark's.
std::vector<WallDef> hallOfBlocks() {
  std::vector<WallDef> walls;
  for (int i = 0; i < 10; ++i)
    for (int j = 0; j < 10; ++j) walls.push_back(rectangleWall(Point2(9 + 10 * i, 9 + 10 * j), Point2(11 + 10 * i, 11 + 10 * j)));
  for (auto [a, b] : {std::pair{Point2(0, 0), Point2(100, 0)},
                      {Point2(100, 0), Point2(100, 100)},
                      {Point2(100, 100), Point2(0, 100)},
                      {Point2(0, 100), Point2(0, 0)}})
    walls.push_back(segmentWall(a, b));
  return walls;
}

TEST(RayCaster, SizesItsCellsForTheWallsAndTheSonars) {
  const Sensing sonar{.range = 6.5, .cone = 25.0 * pi / 180};
  // Among walls a metre or so apart, cells follow their spacing, with or without sonars to fit.
  const std::vector<WallDef> maze = crowdedMaze().walls;
  const double bySpacing = RayCaster(maze, Point2(-1, -1), Point2(21, 21)).cellSize();
  EXPECT_GT(bySpacing, 1.0);
  EXPECT_LT(bySpacing, 1.5);
  EXPECT_EQ(RayCaster(maze, Point2(-1, -1), Point2(21, 21), sonar).cellSize(), bySpacing);
  // Among blocks 10 m apart, a cone costs least swept in one band: cells longer than its range.
  const std::vector<WallDef> hall = hallOfBlocks();
  EXPECT_LT(RayCaster(hall, Point2(-1, -1), Point2(101, 101)).cellSize(), 6.5);
  EXPECT_GE(RayCaster(hall, Point2(-1, -1), Point2(101, 101), sonar).cellSize(), 6.5);
}

}  // namespace
}  // namespace frob::worlds::detail
