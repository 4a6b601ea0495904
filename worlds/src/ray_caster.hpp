#pragma once
// Private: fast ray casts for sonars. Static walls (segments and circles) live in a uniform grid
// walked by DDA (Amanatides & Woo); robots are circles re-binned into the same grid each step.
// Casting is read-only, so many threads may cast at once.

#include "frob/worlds/world_def.hpp"

#include <cstdint>
#include <vector>

namespace frob::worlds::detail {

// The nearest surface a ray meets.
struct RayHit {
  double distance = INFINITY;  // along the ray, metres; INFINITY when nothing within range
  double cosIncidence = 1.0;   // |cos| of the angle between the ray and the surface normal
};

class RayCaster {
 public:
  // Builds the grid over [lo, hi] from the walls (rectangles become four segments).
  RayCaster(const std::vector<WallDef>& walls, const Point2& lo, const Point2& hi);
  // Replaces the moving circles (robots); circle i is skipped by casts from robot i.
  void setRobots(const std::vector<Point2>& centres, const std::vector<double>& radii);
  // The nearest hit of the ray from `origin` along unit `dir` within `range`, ignoring robot `self`.
  [[nodiscard]] RayHit cast(const Point2& origin, const Vec2& dir, double range, int self) const;
  // Number of static segments (rectangles and polylines count their sides).
  [[nodiscard]] std::size_t segmentCount() const { return segs_.size(); }

 private:
  struct Seg {
    double ax, ay, dx, dy, nx, ny;  // start, direction (b - a), unit normal
  };
  struct Circle {
    double cx, cy, r;
  };
  // Compressed lists: cell c holds items[start[c] .. start[c+1]).
  struct Bins {
    std::vector<std::uint32_t> start, items;
  };
  void cellRange(double x0, double y0, double x1, double y1, int& i0, int& j0, int& i1, int& j1) const;
  void testCell(int cell, double ox, double oy, double ux, double uy, int self, RayHit& best) const;

  std::vector<Seg> segs_;
  std::vector<Circle> circles_;   // static pillars
  std::vector<Circle> robots_;
  std::vector<int> outside_;      // robots not fully inside the grid: tested by every ray
  Bins static_;                   // item: segment index, or pillar index with the top bit set
  // Robots per cell as linked lists, so that re-binning costs only the cells robots touch.
  struct Link {
    int robot, next;
  };
  std::vector<int> head_;         // per cell: first link, or -1
  std::vector<Link> links_;
  std::vector<int> touched_;      // cells whose head_ is set
  double x0_ = 0, y0_ = 0, cell_ = 1, inv_ = 1;
  int nx_ = 1, ny_ = 1;
};

}  // namespace frob::worlds::detail
