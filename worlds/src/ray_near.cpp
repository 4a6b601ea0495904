// Near sets: most sonar echoes in a maze are short, yet finding them by walking the grid costs
// several cells and their bookkeeping per ray. So the grid's box is also cut into finer cells, and
// each keeps a copy of every wall within nearRange_ of it. A ray from a point in the cell first tests that set: if its nearest hit there lies within
// nearRange_, the hit point is within nearRange_ of the cell, so its surface is in the set and
// no other surface is nearer; the hit is final. Otherwise the ray walks the grid as before, which
// tests the same surfaces again with the same arithmetic: the result never depends on the set
// (short of exact ties between two surfaces, as in ray_fan.cpp). Used only while the world has
// one robot: gathering the other robots near each cone cost more than the sets saved (measured).
#include "ray_caster.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace frob::worlds::detail {
namespace {

constexpr double kMaxNearCells = 1 << 16;  // bounds the time and memory of building the sets
constexpr std::size_t kMaxNearWalls = 1 << 19;  // copies over all sets; beyond, no near sets (about 50 MB)
constexpr double kSlack = 1e-6;  // metres added to the set's reach: origins rounded into the next cell

double pointBoxDist2(double px, double py, double lx, double ly, double hx, double hy) {
  const double dx = std::max({lx - px, 0.0, px - hx}), dy = std::max({ly - py, 0.0, py - hy});
  return dx * dx + dy * dy;
}

double pointSegDist2(double px, double py, double ax, double ay, double dx, double dy) {
  const double len2 = dx * dx + dy * dy;
  const double t = len2 > 0 ? std::clamp(((px - ax) * dx + (py - ay) * dy) / len2, 0.0, 1.0) : 0.0;
  const double ex = ax + t * dx - px, ey = ay + t * dy - py;
  return ex * ex + ey * ey;
}

// Whether segment a + v d, v in [0, 1], meets the box (Liang-Barsky clipping).
bool segMeetsBox(double ax, double ay, double dx, double dy, double lx, double ly, double hx, double hy) {
  double v0 = 0.0, v1 = 1.0;
  auto clip = [&](double p, double q) {  // keeps v with p v <= q
    if (p == 0.0) return q >= 0.0;
    const double v = q / p;
    if (p < 0) v0 = std::max(v0, v);
    else v1 = std::min(v1, v);
    return v0 <= v1;
  };
  return clip(-dx, ax - lx) && clip(dx, hx - ax) && clip(-dy, ay - ly) && clip(dy, hy - ay);
}

// The distance between a segment and a box that it does not meet is reached at a vertex of one of them.
double segBoxDist2(double ax, double ay, double dx, double dy, double lx, double ly, double hx, double hy) {
  if (segMeetsBox(ax, ay, dx, dy, lx, ly, hx, hy)) return 0.0;
  return std::min({pointBoxDist2(ax, ay, lx, ly, hx, hy), pointBoxDist2(ax + dx, ay + dy, lx, ly, hx, hy),
                   pointSegDist2(lx, ly, ax, ay, dx, dy), pointSegDist2(hx, ly, ax, ay, dx, dy),
                   pointSegDist2(lx, hy, ax, ay, dx, dy), pointSegDist2(hx, hy, ax, ay, dx, dy)});
}

}  // namespace

void RayCaster::buildNear(const std::vector<Seg>& segs, const std::vector<Circle>& circles) {
  // Measured in the 20 x 20 m maze (callgrind, one robot): reach 2 m and a quarter of a grid cell
  // beat 1, 1.5, 2.5, 3 and 4 m and halves or eighths; larger reaches hold too many walls.
  nearRange_ = 2.0;
  nearCell_ = std::max(cell_ / 4.0, std::sqrt((x1_ - x0_) * (y1_ - y0_) / kMaxNearCells) * 1.01);
  nearInv_ = 1.0 / nearCell_;
  nearNx_ = static_cast<int>(std::ceil((x1_ - x0_) * nearInv_ - 1e-9));
  nearNy_ = static_cast<int>(std::ceil((y1_ - y0_) * nearInv_ - 1e-9));
  const std::size_t cells = static_cast<std::size_t>(nearNx_) * static_cast<std::size_t>(nearNy_);
  const double reach = nearRange_ + kSlack, reach2 = reach * reach;
  // Each item is tried only on the cells under its box grown by the reach; count, then fill, so
  // that every set keeps the walls' order.
  auto range = [&](double lo, double hi, double origin, int n, int& c0, int& c1) {
    c0 = static_cast<int>(std::clamp(std::floor((lo - reach - origin) * nearInv_), 0.0, n - 1.0));
    c1 = static_cast<int>(std::clamp(std::floor((hi + reach - origin) * nearInv_), 0.0, n - 1.0));
  };
  auto bin = [&](const auto& items, auto near, std::vector<std::uint32_t>& start, auto& out) {
    start.assign(cells + 1, 0);
    auto forEachCell = [&](const auto& item, auto&& visit) {
      const auto [ax, ay, bx, by] = near(item, 0.0, 0.0, 0.0, 0.0, true);
      int i0, i1, j0, j1;
      range(ax, bx, x0_, nearNx_, i0, i1);
      range(ay, by, y0_, nearNy_, j0, j1);
      for (int j = j0; j <= j1; ++j)
        for (int i = i0; i <= i1; ++i) {
          const double lx = x0_ + i * nearCell_, ly = y0_ + j * nearCell_;
          if (near(item, lx, ly, lx + nearCell_, ly + nearCell_, false)[0] != 0.0)
            visit(static_cast<std::size_t>(j * nearNx_ + i));
        }
    };
    for (const auto& item : items) forEachCell(item, [&](std::size_t c) { ++start[c + 1]; });
    for (std::size_t c = 0; c < cells; ++c) start[c + 1] += start[c];
    out.resize(start[cells]);
    std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
    for (const auto& item : items) forEachCell(item, [&](std::size_t c) { out[fill[c]++] = item; });
  };
  // With `box`, the item's bounding box; else whether it comes within the reach of the cell (as [0] != 0).
  bin(segs, [&](const Seg& s, double lx, double ly, double hx, double hy, bool box) {
    if (box) return std::array{std::min(s.ax, s.ax + s.dx), std::min(s.ay, s.ay + s.dy),
                               std::max(s.ax, s.ax + s.dx), std::max(s.ay, s.ay + s.dy)};
    return std::array{segBoxDist2(s.ax, s.ay, s.dx, s.dy, lx, ly, hx, hy) <= reach2 ? 1.0 : 0.0, 0.0, 0.0, 0.0};
  }, nearSegStart_, nearSegs_);
  bin(circles, [&](const Circle& c, double lx, double ly, double hx, double hy, bool box) {
    if (box) return std::array{c.cx - c.r, c.cy - c.r, c.cx + c.r, c.cy + c.r};
    const double r = c.r + reach;
    return std::array{pointBoxDist2(c.cx, c.cy, lx, ly, hx, hy) <= r * r ? 1.0 : 0.0, 0.0, 0.0, 0.0};
  }, nearPillarStart_, nearPillars_);
  if (nearSegs_.size() > kMaxNearWalls) {  // a world dense with walls: rays walk the grid only
    nearRange_ = 0.0;
    nearSegs_ = {}, nearPillars_ = {};
    return;
  }
  nearBlockStart_.assign(cells + 1, 0);
  nearBlocks_.clear();
  for (std::size_t c = 0; c < cells; ++c) {
    for (std::uint32_t k = nearSegStart_[c]; k < nearSegStart_[c + 1]; ++k) {
      const std::uint32_t lane = (k - nearSegStart_[c]) % 4;
      if (lane == 0) {
        SegBlock b;
        for (double* a : {b.ax, b.ay, b.dx, b.dy, b.nx, b.ny}) std::fill(a, a + 4, NAN);
        nearBlocks_.push_back(b);
      }
      const Seg& s = nearSegs_[k];
      SegBlock& b = nearBlocks_.back();
      b.ax[lane] = s.ax, b.ay[lane] = s.ay, b.dx[lane] = s.dx, b.dy[lane] = s.dy, b.nx[lane] = s.nx, b.ny[lane] = s.ny;
    }
    nearBlockStart_[c + 1] = static_cast<std::uint32_t>(nearBlocks_.size());
  }
}

int RayCaster::nearCellOf(double ox, double oy) const {
  const int i = std::min(std::max(static_cast<int>((ox - x0_) * nearInv_), 0), nearNx_ - 1);
  const int j = std::min(std::max(static_cast<int>((oy - y0_) * nearInv_), 0), nearNy_ - 1);
  return j * nearNx_ + i;
}

}  // namespace frob::worlds::detail
