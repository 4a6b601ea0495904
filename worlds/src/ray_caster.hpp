#pragma once
// Private: fast ray casts for sonars. Static walls (segments and circles) live in a uniform grid
// walked by DDA (Amanatides & Woo); robots are circles re-binned into the same grid each step.
// Casting is read-only, so many threads may cast at once.

#include "frob/worlds/world_def.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

namespace frob::worlds::detail {

// The nearest surface a ray meets.
struct RayHit {
  double distance = INFINITY;  // along the ray, metres; INFINITY when nothing within range
  double cosIncidence = 1.0;   // |cos| of the angle between the ray and the surface normal
};

// The instruction sets cones are cast with, narrowest first. All give bit-identical results.
enum class Isa { Baseline, Avx2, Avx512 };
// For tests: casts with the widest set the CPU has up to `widest` (the widest of all by default);
// returns the one now in use.
Isa useIsa(Isa widest);

class RayCaster {
 public:
  // Builds the grid over [lo, hi] from the walls (rectangles become four segments).
  RayCaster(const std::vector<WallDef>& walls, const Point2& lo, const Point2& hi);
  // Replaces the moving circles (robots); circle i is skipped by casts from robot i.
  void setRobots(const std::vector<Point2>& centres, const std::vector<double>& radii);
  // The nearest hit of the ray from `origin` along unit `dir` within `range`, ignoring robot `self`.
  [[nodiscard]] RayHit cast(const Point2& origin, const Vec2& dir, double range, int self) const;
  // The sonar reading of a cone: rays from `origin` along the unit (dirX[k], dirY[k]), in order,
  // each cast only as far as the nearest echo so far; a hit echoes when its cosIncidence >=
  // `cosCutoff`. Returns the nearest echo, or `range` when none. Bit-identical to calling cast()
  // per ray, but the rays of a cone share the walk through the grid.
  [[nodiscard]] double castCone(const Point2& origin, std::span<const double> dirX, std::span<const double> dirY, double range, int self,
                                double cosCutoff) const;
  // Number of static segments (rectangles and polylines count their sides).
  [[nodiscard]] std::size_t segmentCount() const { return segmentCount_; }

 private:
  struct Seg {
    double ax, ay, dx, dy, nx, ny;  // start, direction (b - a), unit normal
  };
  struct Circle {
    double cx, cy, r;
  };
  struct Robot {
    double cx, cy, r;
    int index;  // into robots_, to skip the casting robot
  };
  // Per cell, the items a ray must test, stored by value so that a cell's walls are contiguous:
  // a ray reads one run of segments, then pillars and robots, without chasing indices.
  struct Span {
    std::uint32_t begin = 0, end = 0;
  };
  void cellRange(double x0, double y0, double x1, double y1, int& i0, int& j0, int& i1, int& j1) const;
  // Along one axis, the cells [c0, c1] of n, from `origin`, 1 / size `inv`, that [lo, hi] touches,
  // padded by a little and clamped to the grid.
  static void cellSpan(double lo, double hi, double origin, double inv, int n, int& c0, int& c1) {
    constexpr double eps = 1e-9;
    const double top = n - 1;
    // Truncation is floor here: anything below 0 clamps to cell 0 anyway (and NaN too).
    c0 = static_cast<int>(std::min(top, std::max(0.0, (lo - origin) * inv - eps)));
    c1 = static_cast<int>(std::min(top, std::max(0.0, (hi - origin) * inv + eps)));
  }
  void walk(int i, int j, double bx0, double bx1, double by0, double by1, double ox, double oy, double ux, double uy, double tmax, int self,
            RayHit& best) const;
  // Ray o + t u against one segment or circle: `best` becomes the hit when it is nearer.
  static void hitSegment(const Seg& s, double ox, double oy, double ux, double uy, RayHit& best);
  static void hitCircle(double cx, double cy, double r, double ox, double oy, double ux, double uy, RayHit& best);
  void testOutside(double ox, double oy, double ux, double uy, int self, RayHit& best) const;
  void testCell(int cell, double ox, double oy, double ux, double uy, int self, RayHit& best) const;
  // Most rays a fan casts at once: 8 with AVX-512, else 5 (four lanes and a lone fifth ray).
  static int fanWidth();
  // `rays` rays of one cone at once (ray_fan.cpp), 3 to fanWidth(), with four lanes 4 or 5 (the
  // caller pads 3 to 4): the nearest echo below `cap`, else `cap`.
  double castFan(int rays, double ox, double oy, const double* ux, const double* uy, double cap, int self, double cosCutoff) const;
  friend struct FanCaster;  // ray_fan.cpp: castFan's body, compiled for each instruction set

  std::size_t segmentCount_ = 0;
  std::vector<Robot> robots_;
  std::vector<int> outside_;                           // robots not fully inside the grid: tested by every ray
  std::vector<std::uint32_t> segStart_, pillarStart_;  // cell c: [start[c], start[c + 1])
  std::vector<Seg> cellSegs_;                          // segments per cell, in index order (a wall is copied into each cell it spans)
  std::vector<Circle> cellPillars_;
  // Robots per cell, rebuilt each step: only the cells robots touch are set and later cleared.
  std::vector<Span> robotSpan_;                                    // per cell
  std::vector<Robot> cellRobots_;                                  // per cell, in descending robot index
  std::vector<int> touched_;                                       // cells whose robotSpan_ is set
  double x0_ = 0, y0_ = 0, x1_ = 1, y1_ = 1, cell_ = 1, inv_ = 1;  // grid box [x0_, x1_] x [y0_, y1_]
  int nx_ = 1, ny_ = 1;
};

[[gnu::always_inline]] inline void RayCaster::hitSegment(const Seg& s, double ox, double oy, double ux, double uy, RayHit& best) {
  // Segment a + v d: t = tn / denom, v = vn / denom. Compared without dividing (the sign of denom
  // folded in) so that only an accepted hit costs a division.
  double denom = ux * s.dy - uy * s.dx;  // cross(u, d); 0 when parallel: an edge-on wall is never heard
  const double wx = s.ax - ox, wy = s.ay - oy;
  double tn = wx * s.dy - wy * s.dx;
  double vn = wx * uy - wy * ux;
  const double sign = std::copysign(1.0, denom);  // exact: flips signs only, and avoids a branch
  denom *= sign, tn *= sign, vn *= sign;
  if (!((tn >= 0.0) & (vn >= 0.0) & (vn <= denom) & (tn < best.distance * denom))) return;
  best = {tn / denom, std::abs(ux * s.nx + uy * s.ny)};
}

// A ray starting inside the circle reads 0.
[[gnu::always_inline]] inline void RayCaster::hitCircle(double cx, double cy, double r, double ox, double oy, double ux, double uy, RayHit& best) {
  const double px = ox - cx, py = oy - cy;
  const double b = px * ux + py * uy;
  const double c = px * px + py * py - r * r;
  if (c < 0) {
    best = {0.0, 1.0};
    return;
  }
  const double disc = b * b - c;
  if (disc < 0 || b > 0) return;  // misses, or the circle is behind the origin
  const double t = -b - std::sqrt(disc);
  if (t >= best.distance) return;
  const double nx = (px + t * ux) / r, ny = (py + t * uy) / r;
  best = {t, std::abs(nx * ux + ny * uy)};
}

}  // namespace frob::worlds::detail
