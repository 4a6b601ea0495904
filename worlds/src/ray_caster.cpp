#include "ray_caster.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace frob::worlds::detail {
namespace {

constexpr int kMaxCells = 1 << 16;  // keeps the grid small enough to rebuild cheaply
// A band of a fan's sweep costs about as much as testing this many segments (a lone robot's step
// over cells of 1 to 12 m in the maze, the hall of blocks and the large map: 17.5 ns a band, 1.1
// ns a segment tested).
constexpr double kBandCost = 16.0;
// Fitting a grid sweeps sample cones from kSampleSide x kSampleSide origins, kSampleDirections each.
constexpr int kSampleSide = 16, kSampleDirections = 8;

}  // namespace

Spread spreadOf(std::span<const double> dirX, std::span<const double> dirY) {
  Spread s;
  for (std::size_t k = 0; k < dirX.size(); ++k) s.cos = std::min(s.cos, dirX[0] * dirX[k] + dirY[0] * dirY[k]);
  s.sin = std::sqrt(std::max(0.0, 1.0 - s.cos * s.cos));
  return s;
}

RayCaster::RayCaster(const std::vector<WallDef>& walls, const Point2& lo, const Point2& hi, const Sensing& sensing) {
  std::vector<Seg> segs;
  std::vector<Circle> circles;
  auto addSeg = [&](const Point2& a, const Point2& b) {
    const Vec2 d = b - a;
    const Vec2 n = Vec2(-d.y(), d.x()).normalized();
    segs.push_back({a.x(), a.y(), d.x(), d.y(), n.x(), n.y()});
  };
  for (const WallDef& w : walls) {
    forEachEdge(
        w, addSeg, [&](const Point2& lo, const Point2& hi) { forEachSide(lo, hi, addSeg); },
        [&](const Point2& c, double radius) {
          circles.push_back({c.x(), c.y(), radius});
        });
  }
  segmentCount_ = segs.size();

  // Cells about as wide as the mean spacing of walls: a fan is swept a cell's length at a time, so
  // smaller cells test fewer walls in more bands, and a band costs as much as some 16 segment tests.
  // Where walls are few and far between (blocks in a hall), a cone is cheapest swept in one band:
  // with sensors to sweep for, that grid is built too, and kept when its sample sweeps cost less.
  // Never under a metre (cells of 0.77 m swept 10,000 short walls a metre apart 17% slower than
  // cells of 1 m), nor so small that the grid outgrows kMaxCells.
  const double w = std::max(hi.x() - lo.x(), 1e-3), h = std::max(hi.y() - lo.y(), 1e-3);
  const double spacing = std::sqrt(w * h / (static_cast<double>(segs.size() + circles.size()) + 1.0));
  const double smallest = std::max(1.0, std::sqrt(w * h / kMaxCells) * 1.01);
  const double bySpacing = std::max(smallest, std::min(0.75 * spacing, 8.0)), oneBand = std::max(smallest, sensing.range * 1.01);
  if (sensing.cell > 0 || sensing.range <= 0) {
    build(segs, circles, lo, hi, sensing.cell > 0 ? std::max(smallest, sensing.cell) : bySpacing);
    return;
  }
  build(segs, circles, lo, hi, oneBand);
  const double oneBandCost = sweepCost(sensing, lo, hi);
  build(segs, circles, lo, hi, bySpacing);
  if (oneBandCost < sweepCost(sensing, lo, hi)) build(segs, circles, lo, hi, oneBand);
}

void RayCaster::build(const std::vector<Seg>& segs, const std::vector<Circle>& circles, const Point2& lo, const Point2& hi, double cell) {
  x0_ = lo.x(), y0_ = lo.y();
  cell_ = cell;
  inv_ = 1.0 / cell_;
  nx_ = std::max(1, static_cast<int>(std::ceil(std::max(hi.x() - lo.x(), 1e-3) * inv_)));
  ny_ = std::max(1, static_cast<int>(std::ceil(std::max(hi.y() - lo.y(), 1e-3) * inv_)));

  // Copy each item into every cell its bounding box touches (count, then fill), keeping index order.
  const std::size_t cells = static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_);
  auto forEachCell = [&](double ax, double ay, double bx, double by, auto&& visit) {
    int i0, j0, i1, j1;
    cellRange(ax, ay, bx, by, i0, j0, i1, j1);
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i) visit(static_cast<std::size_t>(j * nx_ + i));
  };
  auto bin = [&](const auto& items, auto bounds, std::vector<std::uint32_t>& start, auto& out) {
    start.assign(cells + 1, 0);
    for (const auto& item : items) {
      const auto [ax, ay, bx, by] = bounds(item);
      forEachCell(ax, ay, bx, by, [&](std::size_t c) { ++start[c + 1]; });
    }
    for (std::size_t c = 0; c < cells; ++c) start[c + 1] += start[c];
    out.resize(start[cells]);
    std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
    for (const auto& item : items) {
      const auto [ax, ay, bx, by] = bounds(item);
      forEachCell(ax, ay, bx, by, [&](std::size_t c) { out[fill[c]++] = item; });
    }
  };
  bin(
      segs,
      [](const Seg& s) {
        return std::array{std::min(s.ax, s.ax + s.dx), std::min(s.ay, s.ay + s.dy), std::max(s.ax, s.ax + s.dx), std::max(s.ay, s.ay + s.dy)};
      },
      segStart_, cellSegs_);
  bin(
      circles,
      [](const Circle& c) {
        return std::array{c.cx - c.r, c.cy - c.r, c.cx + c.r, c.cy + c.r};
      },
      pillarStart_, cellPillars_);
  x1_ = x0_ + nx_ * cell_, y1_ = y0_ + ny_ * cell_;
}

double RayCaster::sweepCost(const Sensing& sensing, const Point2& lo, const Point2& hi) const {
  // Each sample is a cone swept as a fan is, as far as its axis meets a wall (where most of its
  // rays end), band by band over the cells its edges and axis bound.
  const Neighbours none;
  const double half = sensing.cone / 2;
  double cost = 0.0;
  for (int a = 0; a < kSampleSide; ++a) {
    for (int b = 0; b < kSampleSide; ++b) {
      const Point2 o = lo + Vec2((a + 0.5) / kSampleSide * (hi.x() - lo.x()), (b + 0.5) / kSampleSide * (hi.y() - lo.y()));
      for (int k = 0; k < kSampleDirections; ++k) {
        const double axis = (k + 0.25) * 2 * pi / kSampleDirections;
        const double end = std::min(sensing.range, cast(o, unitVector(axis), sensing.range, none).distance);
        double uxLo = INFINITY, uxHi = -INFINITY, uyLo = INFINITY, uyHi = -INFINITY;
        for (const double angle : {axis - half, axis, axis + half}) {
          const Vec2 u = unitVector(angle);
          uxLo = std::min(uxLo, u.x()), uxHi = std::max(uxHi, u.x()), uyLo = std::min(uyLo, u.y()), uyHi = std::max(uyHi, u.y());
        }
        CellBox before;
        for (double d0 = 0.0; d0 < end;) {
          const double d1 = std::min(d0 + cell_, end);
          const CellBox now = bandBox(o.x(), o.y(), uxLo, uxHi, uyLo, uyHi, d0, d1);
          cost += kBandCost;
          forEachNewRun(now, before,
                        [&](int first, int last) { cost += segStart_[last] - segStart_[first] + pillarStart_[last] - pillarStart_[first]; });
          before = now, d0 = d1;
        }
      }
    }
  }
  return cost;
}

void RayCaster::cellRange(double ax, double ay, double bx, double by, int& i0, int& j0, int& i1, int& j1) const {
  cellSpan(ax, bx, x0_, inv_, nx_, i0, i1);
  cellSpan(ay, by, y0_, inv_, ny_, j0, j1);
}

void RayCaster::setRobots(const std::vector<Point2>& centres, const std::vector<double>& radii, double reach) {
  robots_.clear();
  if (centres.size() <= 1) return;  // a robot never hears itself: nothing to bin
  // Cells about as wide as the reach, so that a gather reads two or three a side; at most 64 a side.
  const double side = std::max(reach, std::max(x1_ - x0_, y1_ - y0_) / 64.0);
  robotInv_ = 1.0 / side;
  robotNx_ = std::max(1, static_cast<int>(std::ceil((x1_ - x0_) * robotInv_)));
  robotNy_ = std::max(1, static_cast<int>(std::ceil((y1_ - y0_) * robotInv_)));
  auto cellOf = [&](const Point2& c) {
    int i, j, unused;
    cellSpan(c.x(), c.x(), x0_, robotInv_, robotNx_, i, unused);
    cellSpan(c.y(), c.y(), y0_, robotInv_, robotNy_, j, unused);
    return static_cast<std::size_t>(j * robotNx_ + i);
  };
  // Count per cell, then place in index order.
  robotStart_.assign(static_cast<std::size_t>(robotNx_) * static_cast<std::size_t>(robotNy_) + 1, 0);
  robotRadius_ = 0;
  for (std::size_t k = 0; k < centres.size(); ++k) {
    ++robotStart_[cellOf(centres[k]) + 1];
    robotRadius_ = std::max(robotRadius_, radii[k]);
  }
  for (std::size_t c = 1; c < robotStart_.size(); ++c) robotStart_[c] += robotStart_[c - 1];
  robots_.resize(centres.size());
  std::vector<std::uint32_t> fill(robotStart_.begin(), robotStart_.end() - 1);
  for (std::size_t k = 0; k < centres.size(); ++k)
    robots_[fill[cellOf(centres[k])]++] = {centres[k].x(), centres[k].y(), radii[k], static_cast<int>(k)};
}

void RayCaster::gather(const Point2& centre, double rim, double range, int self, Neighbours& out) const {
  out.count = 0;
  if (robots_.empty()) {  // no rings
    out.ringStart.assign(1, 0);
    return;
  }
  const std::size_t rings = static_cast<std::size_t>(std::ceil(range * inv_)) + 1;
  out.ringStart.assign(rings + 1, 0);
  // A ray from within `rim` of the centre, shorter than the range, meets only robots whose centres
  // lie within rim + range + their radius; a millimetre's margin outweighs any rounding.
  const double cx = centre.x(), cy = centre.y(), reach = rim + range, far = reach + robotRadius_ + 1e-3;
  int i0, i1, j0, j1;
  cellSpan(cx - far, cx + far, x0_, robotInv_, robotNx_, i0, i1);
  cellSpan(cy - far, cy + far, y0_, robotInv_, robotNy_, j0, j1);
  std::size_t candidates = 0;
  for (int j = j0; j <= j1; ++j) candidates += robotStart_[j * robotNx_ + i1 + 1] - robotStart_[j * robotNx_ + i0];
  if (out.found.size() < candidates) out.found.resize(candidates);  // grown, never shrunk: no filling anew each time
  // Every candidate is written, and kept by counting it: no branch to mispredict.
  std::size_t kept = 0;
  for (int j = j0; j <= j1; ++j) {
    for (std::uint32_t k = robotStart_[j * robotNx_ + i0], end = robotStart_[j * robotNx_ + i1 + 1]; k < end; ++k) {
      const Robot& c = robots_[k];
      const double dx = c.cx - cx, dy = c.cy - cy, squared = dx * dx + dy * dy, within = reach + c.r + 1e-3;
      const bool keep = c.index != self && squared <= within * within;  // false for NaN
      // No sensor meets this robot nearer than `lower` (a micrometre less, against rounding).
      const double lower = std::sqrt(squared) - c.r - rim - 1e-6;
      const auto ring = static_cast<std::size_t>(std::min(static_cast<double>(rings - 1), std::max(0.0, lower * inv_)));
      Neighbours::Found& found = out.found[kept];  // field by field: a braced temporary copied whole stalls
      found.ring = static_cast<std::uint32_t>(ring), found.x = c.cx, found.y = c.cy, found.r = c.r;
      kept += keep;
      out.ringStart[ring + 1] += keep;
    }
  }
  // Placed by ring (counted above), keeping the order found within each.
  for (std::size_t k = 1; k <= rings; ++k) out.ringStart[k] += out.ringStart[k - 1];
  out.next.assign(out.ringStart.begin(), out.ringStart.end() - 1);
  out.count = kept;
  for (std::vector<double>* v : {&out.x, &out.y, &out.r}) {
    v->resize(kept + 8);
    std::fill(v->begin() + static_cast<std::ptrdiff_t>(kept), v->end(), NAN);
  }
  for (const Neighbours::Found& f : std::span(out.found).first(kept)) {
    const std::uint32_t slot = out.next[f.ring]++;
    out.x[slot] = f.x, out.y[slot] = f.y, out.r[slot] = f.r;
  }
}

[[gnu::always_inline]] inline void RayCaster::testCell(int cell, double ox, double oy, double ux, double uy, RayHit& best) const {
  for (std::uint32_t k = segStart_[cell], end = segStart_[cell + 1]; k < end; ++k) hitSegment(cellSegs_[k], ox, oy, ux, uy, best);
  for (std::uint32_t k = pillarStart_[cell], end = pillarStart_[cell + 1]; k < end; ++k) {
    const Circle& c = cellPillars_[k];
    hitCircle(c.cx, c.cy, c.r, ox, oy, ux, uy, best);
  }
}

[[gnu::always_inline]] inline void RayCaster::walk(int i, int j, double bx0, double bx1, double by0, double by1, double ox, double oy, double ux,
                                                   double uy, double tmax, RayHit& best) const {
  // Walk the cells the ray crosses, nearest first; stop once the best hit lies within the cell.
  // bx0/bx1 (by0/by1): the offsets from the origin to cell i's (j's) lower and upper sides.
  const double ix = 1.0 / ux, iy = 1.0 / uy;  // +-inf along an axis; the steps handle it
  const int si = ux > 0 ? 1 : -1, sj = uy > 0 ? 1 : -1;
  const double dtx = cell_ * std::abs(ix), dty = cell_ * std::abs(iy);
  double tx = ux > 0 ? bx1 * ix : ux < 0 ? bx0 * ix : INFINITY;
  double ty = uy > 0 ? by1 * iy : uy < 0 ? by0 * iy : INFINITY;
  for (;;) {
    testCell(j * nx_ + i, ox, oy, ux, uy, best);
    const double exit = std::min(tx, ty);
    if (best.distance <= exit || exit >= tmax) break;
    if (tx < ty) {
      i += si, tx += dtx;
      if (static_cast<unsigned>(i) >= static_cast<unsigned>(nx_)) break;
    } else {
      j += sj, ty += dty;
      if (static_cast<unsigned>(j) >= static_cast<unsigned>(ny_)) break;
    }
  }
}

RayHit RayCaster::cast(const Point2& origin, const Vec2& dir, double range, const Neighbours& near) const {
  const double ox = origin.x(), oy = origin.y(), ux = dir.x(), uy = dir.y();
  RayHit best{range, 1.0};
  for (std::size_t k = 0; k < near.count; ++k) hitCircle(near.x[k], near.y[k], near.r[k], ox, oy, ux, uy, best);

  // Clip [0, range] to the grid's box (slab method), unless the ray starts inside it (the usual case).
  const double x1 = x1_, y1 = y1_;
  double tmin = 0.0, tmax = range;
  if (!inside(ox, oy)) [[unlikely]] {
    const double ix = 1.0 / ux, iy = 1.0 / uy;
    if (ux != 0.0) {
      const double a = (x0_ - ox) * ix, b = (x1 - ox) * ix;
      tmin = std::max(tmin, std::min(a, b)), tmax = std::min(tmax, std::max(a, b));
    } else if (ox < x0_ || ox > x1) {
      tmax = -1.0;
    }
    if (uy != 0.0) {
      const double a = (y0_ - oy) * iy, b = (y1 - oy) * iy;
      tmin = std::max(tmin, std::min(a, b)), tmax = std::min(tmax, std::max(a, b));
    } else if (oy < y0_ || oy > y1) {
      tmax = -1.0;
    }
  }
  if (tmin <= tmax) {
    const double px = (ox + tmin * ux - x0_) * inv_, py = (oy + tmin * uy - y0_) * inv_;  // >= 0 up to rounding
    const int i = std::min(std::max(static_cast<int>(px), 0), nx_ - 1);
    const int j = std::min(std::max(static_cast<int>(py), 0), ny_ - 1);
    walk(i, j, x0_ + i * cell_ - ox, x0_ + (i + 1) * cell_ - ox, y0_ + j * cell_ - oy, y0_ + (j + 1) * cell_ - oy, ox, oy, ux, uy, tmax, best);
  }
  if (best.distance >= range) best.distance = INFINITY;
  return best;
}

double RayCaster::castCone(const Point2& origin, std::span<const double> dirX, std::span<const double> dirY, const Spread& spread, double range,
                           double cosCutoff, const Neighbours& near) const {
  double reading;
  castCones({&origin, 1}, dirX, dirY, spread, range, cosCutoff, near, {&reading, 1});
  return reading;
}

}  // namespace frob::worlds::detail
