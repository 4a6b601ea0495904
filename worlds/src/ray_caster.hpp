#pragma once
// Private: fast ray casts for sonars. Static walls (segments and circles) live in a uniform grid
// walked by DDA (Amanatides & Woo). Robots are circles, binned by centre each step into a coarser
// grid of their own; a sensing robot gathers its neighbours once, in rings by distance, and each
// cone tests a ring only once its sweep reaches it, and of it only the robots inside its wedge.
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

// The robots a robot's sensors could hear, gathered once for all its cones: centres and radii by
// ring, where ring k holds the robots no sensor can meet nearer than k cell lengths; then eight
// entries of padding, so that lanes may load eight from any entry.
struct Neighbours {
  std::vector<double> x, y, r;
  std::vector<std::uint32_t> ringStart = {0};  // ring k: [ringStart[k], ringStart[k + 1]); no rings at first
  std::size_t count = 0;                       // robots; the rest is padding
  // Scratch for gather(): the robots as found (the first `count`), with their rings, and the next
  // free slot per ring.
  struct Found {
    std::uint32_t ring;
    double x, y, r;
  };
  std::vector<Found> found;
  std::vector<std::uint32_t> next;
};

// How far a cone's rays stray from its first ray: the cosine and sine of the widest angle between them.
struct Spread {
  double cos = 1.0, sin = 0.0;
};
// The spread of the rays along unit (dirX[k], dirY[k]).
[[nodiscard]] Spread spreadOf(std::span<const double> dirX, std::span<const double> dirY);

// How sensors will sweep the walls, which sizes the grid's cells: the farthest any reads and its
// widest cone (radians). Without it (range 0), cells follow the walls' spacing alone. `cell`, when
// set, is the cell size to use instead (for tests).
struct Sensing {
  double range = 0.0, cone = 0.0, cell = 0.0;
};

class RayCaster {
 public:
  // Builds the grid over [lo, hi] from the walls (rectangles become four segments), its cells
  // sized for the cheapest sweeps of `sensing`'s cones.
  RayCaster(const std::vector<WallDef>& walls, const Point2& lo, const Point2& hi, const Sensing& sensing = {});
  // Replaces the moving circles (robots). `reach`: the farthest any sensor hears from its robot's
  // centre, which sizes the robots' grid.
  void setRobots(const std::vector<Point2>& centres, const std::vector<double>& radii, double reach);
  // Into `out`, the robots other than `self` that a sensor at most `rim` from `centre` could hear
  // within `range`.
  void gather(const Point2& centre, double rim, double range, int self, Neighbours& out) const;
  // The nearest hit of the ray from `origin` along unit `dir` within `range`, among the walls and
  // the robots `near`.
  [[nodiscard]] RayHit cast(const Point2& origin, const Vec2& dir, double range, const Neighbours& near) const;
  // The sonar reading of a cone: rays from `origin` along the unit (dirX[k], dirY[k]), in order,
  // at most `spread` from the first (spreadOf() these rays, or wider; the same rays turned give the
  // same spread), each cast only as far as the nearest echo so far; a hit echoes when its
  // cosIncidence >= `cosCutoff`. Returns the nearest echo, or `range` when none. Bit-identical to
  // calling cast() per ray, but the rays of a cone share the walk through the grid.
  [[nodiscard]] double castCone(const Point2& origin, std::span<const double> dirX, std::span<const double> dirY, const Spread& spread, double range,
                                double cosCutoff, const Neighbours& near) const;
  // castCone() for each of a robot's cones, alike but for their origins: cone j's rays are
  // dirX/dirY[j * n, (j + 1) * n) for n = dirX.size() / origins.size(); its reading goes to readings[j].
  void castCones(std::span<const Point2> origins, std::span<const double> dirX, std::span<const double> dirY, const Spread& spread, double range,
                 double cosCutoff, const Neighbours& near, std::span<double> readings) const;
  // Number of static segments (rectangles and polylines count their sides).
  [[nodiscard]] std::size_t segmentCount() const { return segmentCount_; }
  // The side of the grid's cells, metres.
  [[nodiscard]] double cellSize() const { return cell_; }

 private:
  struct Seg {
    double ax, ay, dx, dy, nx, ny;  // start, direction (b - a), unit normal
  };
  struct Circle {
    double cx, cy, r;
  };
  struct Robot {
    double cx, cy, r;
    int index;  // as given to setRobots(), to skip the sensing robot
  };
  // Cells [i0, i1] x [j0, j1]; empty at first.
  struct CellBox {
    int i0 = 1, j0 = 1, i1 = 0, j1 = 0;
  };
  // Bins the walls into a grid of cells of side `cell` over [lo, hi].
  void build(const std::vector<Seg>& segs, const std::vector<Circle>& circles, const Point2& lo, const Point2& hi, double cell);
  // What sweeping sample cones of `sensing` from a lattice of origins over [lo, hi] costs with this
  // grid, in segment tests: each band counts as kBandCost of them.
  [[nodiscard]] double sweepCost(const Sensing& sensing, const Point2& lo, const Point2& hi) const;
  [[nodiscard]] bool inside(double x, double y) const { return x >= x0_ && x <= x1_ && y >= y0_ && y <= y1_; }
  // The cells under the pieces over [d0, d1] of rays from (ox, oy) whose directions lie in
  // [uxLo, uxHi] x [uyLo, uyHi]: a piece's end ox + d ux is monotone in ux for d >= 0 (rounding
  // too), so the ends of the extremes bound all.
  [[gnu::always_inline]] CellBox bandBox(double ox, double oy, double uxLo, double uxHi, double uyLo, double uyHi, double d0, double d1) const {
    CellBox b;
    cellSpan(std::min(ox + d0 * uxLo, ox + d1 * uxLo), std::max(ox + d0 * uxHi, ox + d1 * uxHi), x0_, inv_, nx_, b.i0, b.i1);
    cellSpan(std::min(oy + d0 * uyLo, oy + d1 * uyLo), std::max(oy + d0 * uyHi, oy + d1 * uyHi), y0_, inv_, ny_, b.j0, b.j1);
    return b;
  }
  // Calls visit(begin, end) for each run of cells [begin, end) of one row that lie in `now` but not
  // in `before`: row by row, the whole row, or the parts left and right of `before`'s. A row's
  // cells are one run of the cell arrays, so a band costs a loop per row rather than per cell.
  template <class Visit>
  [[gnu::always_inline]] void forEachNewRun(const CellBox& now, const CellBox& before, Visit&& visit) const {
    for (int j = now.j0; j <= now.j1; ++j) {
      const int row = j * nx_;
      if (j < before.j0 || j > before.j1) {
        visit(row + now.i0, row + now.i1 + 1);
      } else {
        if (now.i0 < before.i0) visit(row + now.i0, row + std::min(now.i1 + 1, before.i0));
        if (now.i1 > before.i1) visit(row + std::max(now.i0, before.i1 + 1), row + now.i1 + 1);
      }
    }
  }
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
  void walk(int i, int j, double bx0, double bx1, double by0, double by1, double ox, double oy, double ux, double uy, double tmax,
            RayHit& best) const;
  // Ray o + t u against one segment or circle: `best` becomes the hit when it is nearer.
  static void hitSegment(const Seg& s, double ox, double oy, double ux, double uy, RayHit& best);
  static void hitCircle(double cx, double cy, double r, double ox, double oy, double ux, double uy, RayHit& best);
  void testCell(int cell, double ox, double oy, double ux, double uy, RayHit& best) const;
  // How a fan culls robots: its cone's rays lie within angle h of ray (ax, ay); a circle (q from the
  // origin, radius r) can meet one only if it comes within r of that wedge, so only if
  // |cross| cos h - max(along, 0) sin h <= r and along >= -r (for h under 90 degrees), along and
  // cross measured on (ax, ay). An origin inside the circle passes both. `margin` widens every
  // bound against rounding; `behind` is it, or infinite when h is 90 degrees or more.
  struct Wedge {
    double ax, ay, cosH, sinH, margin, behind;
  };
  friend struct FanCaster;  // ray_fan.cpp: castCones's body, compiled for each instruction set

  std::size_t segmentCount_ = 0;
  // Per cell, the walls a ray must test, stored by value so that a cell's walls are contiguous: a
  // ray reads one run of segments, then of pillars, without chasing indices.
  std::vector<std::uint32_t> segStart_, pillarStart_;  // cell c: [start[c], start[c + 1])
  std::vector<Seg> cellSegs_;                          // segments per cell, in index order (a wall is copied into each cell it spans)
  std::vector<Circle> cellPillars_;
  double x0_ = 0, y0_ = 0, x1_ = 1, y1_ = 1, cell_ = 1, inv_ = 1;  // grid box [x0_, x1_] x [y0_, y1_]
  int nx_ = 1, ny_ = 1;
  // The robots, by the cell of the robots' grid (over the same box) that holds their centre; a
  // centre outside the box counts in the nearest cell, so a gather that reaches it still finds it.
  std::vector<std::uint32_t> robotStart_;  // cell c: [robotStart_[c], robotStart_[c + 1])
  std::vector<Robot> robots_;              // by cell, then index
  double robotInv_ = 1, robotRadius_ = 0;  // 1 / the robots' cell size; the largest robot radius
  int robotNx_ = 1, robotNy_ = 1;
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
