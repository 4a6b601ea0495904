#pragma once
/// Where a robot's body fits among a world's walls: nearest-wall distances, a grid of the cells where
/// the body fits, what is reachable from where, and the shortest way. The world generators check
/// their worlds with it; the grader and the diagnosis judge runs with it.

#include "frob/worlds/world_def.hpp"

#include <algorithm>
#include <cmath>
#include <queue>
#include <vector>

namespace frob::worlds {

// Nearest-wall distances, found among the walls whose box lies within `reach` of a bucket.
class WallIndex {
 public:
  WallIndex(const std::vector<WallDef>& walls, const Vec2& size, double reach) : walls_(walls), reach_(reach) {
    cell_ = std::max(reach, 0.5);
    nx_ = std::max(1, static_cast<int>(std::ceil(size.x() / cell_)));
    ny_ = std::max(1, static_cast<int>(std::ceil(size.y() / cell_)));
    buckets_.resize(static_cast<std::size_t>(nx_) * ny_);
    for (std::size_t w = 0; w < walls.size(); ++w) {
      Point2 lo = walls[w].points[0], hi = lo;
      for (const Point2& p : walls[w].points) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
      const double r = walls[w].radius + reach;
      for (int y = clampY(lo.y() - r); y <= clampY(hi.y() + r); ++y) {
        for (int x = clampX(lo.x() - r); x <= clampX(hi.x() + r); ++x) buckets_[y * nx_ + x].push_back(w);
      }
    }
  }
  // Distance from `p` to the nearest wall's surface, at most `reach`.
  double distance(const Point2& p) const {
    double d = reach_;
    for (std::size_t w : buckets_[clampY(p.y()) * nx_ + clampX(p.x())]) d = std::min(d, distanceToWall(p, walls_[w]));
    return d;
  }

 private:
  int clampX(double x) const { return std::clamp(static_cast<int>(std::floor(x / cell_)), 0, nx_ - 1); }
  int clampY(double y) const { return std::clamp(static_cast<int>(std::floor(y / cell_)), 0, ny_ - 1); }
  const std::vector<WallDef>& walls_;
  double reach_, cell_ = 1.0;
  int nx_ = 1, ny_ = 1;
  std::vector<std::vector<std::size_t>> buckets_;
};

// A grid over the world of cells where a robot's centre fits (its body clear of every wall).
class FreeGrid {
 public:
  FreeGrid(const std::vector<WallDef>& walls, const Vec2& size, double radius, double cell)
      : cell_(cell), radius_(radius), index_(walls, size, radius + cell) {
    nx_ = std::max(1, static_cast<int>(std::floor(size.x() / cell)));
    ny_ = std::max(1, static_cast<int>(std::floor(size.y() / cell)));
    free_.resize(static_cast<std::size_t>(nx_) * ny_);
    for (int y = 0; y < ny_; ++y) {
      for (int x = 0; x < nx_; ++x) free_[y * nx_ + x] = index_.distance(centre(x, y)) >= radius;
    }
  }
  [[nodiscard]] int size() const { return nx_ * ny_; }
  [[nodiscard]] Point2 centre(int x, int y) const { return {(x + 0.5) * cell_, (y + 0.5) * cell_}; }
  [[nodiscard]] Point2 centre(int c) const { return centre(c % nx_, c / nx_); }
  [[nodiscard]] bool free(int c) const { return free_[c]; }
  // The cell holding `p`, or the nearest free cell when that one is not free (a start grazing a wall).
  [[nodiscard]] int cellOf(const Point2& p) const {
    const int x = std::clamp(static_cast<int>(p.x() / cell_), 0, nx_ - 1), y = std::clamp(static_cast<int>(p.y() / cell_), 0, ny_ - 1);
    int best = y * nx_ + x;
    for (int r = 1; !free_[best] && r < 4; ++r) {
      for (int dy = -r; dy <= r; ++dy) {
        for (int dx = -r; dx <= r; ++dx) {
          const int cx = x + dx, cy = y + dy;
          if (cx >= 0 && cy >= 0 && cx < nx_ && cy < ny_ && free_[cy * nx_ + cx] && !free_[best]) best = cy * nx_ + cx;
        }
      }
    }
    return best;
  }
  // The free cells reachable from `from` through free side neighbours.
  [[nodiscard]] std::vector<bool> reachable(int from) const {
    std::vector<bool> seen(free_.size(), false);
    std::vector<int> stack{from};
    seen[from] = free_[from];
    while (!stack.empty()) {
      const int c = stack.back();
      stack.pop_back();
      if (!free_[c]) continue;
      for (int n : neighbours4(c)) {
        if (!seen[n] && free_[n]) seen[n] = true, stack.push_back(n);
      }
    }
    return seen;
  }
  // Length of the shortest path for the body from `a` to `b`; infinity when there is none. A* on
  // the grid finds the way, then each corner that the body can cut in a straight line is cut, so
  // the length is within a few centimetres of the true shortest path.
  [[nodiscard]] double shortestPath(const Point2& a, const Point2& b) const {
    const int from = cellOf(a), to = cellOf(b);
    std::vector<double> cost(free_.size(), INFINITY);
    std::vector<int> parent(free_.size(), -1);
    using Entry = std::pair<double, int>;  // estimated total, cell
    std::priority_queue<Entry, std::vector<Entry>, std::greater<>> open;
    cost[from] = 0;
    open.push({(centre(from) - centre(to)).norm(), from});
    while (!open.empty()) {
      const auto [estimate, c] = open.top();
      open.pop();
      if (c == to) break;
      if (estimate > cost[c] + (centre(c) - centre(to)).norm() + 1e-9) continue;  // a stale entry
      const int x = c % nx_, y = c / nx_;
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
          const int cx = x + dx, cy = y + dy;
          if ((dx == 0 && dy == 0) || cx < 0 || cy < 0 || cx >= nx_ || cy >= ny_) continue;
          const int n = cy * nx_ + cx;
          // A diagonal step needs both cells beside it free, so the body does not cut a corner.
          if (!free_[n] || (dx != 0 && dy != 0 && (!free_[y * nx_ + cx] || !free_[cy * nx_ + x]))) continue;
          const double step = (dx != 0 && dy != 0) ? cell_ * std::sqrt(2.0) : cell_;
          if (cost[c] + step < cost[n]) {
            cost[n] = cost[c] + step;
            parent[n] = c;
            open.push({cost[n] + (centre(n) - centre(to)).norm(), n});
          }
        }
      }
    }
    if (!std::isfinite(cost[to])) return INFINITY;
    std::vector<Point2> way{b};
    for (int c = to; c != -1; c = parent[c]) way.push_back(centre(c));
    way.push_back(a);
    // From each anchor, straight on to the furthest point of the way in sight.
    double length = 0;
    for (std::size_t anchor = way.size() - 1; anchor > 0;) {
      std::size_t next = anchor - 1;
      while (next > 0 && clear(way[anchor], way[next - 1])) --next;
      length += (way[anchor] - way[next]).norm();
      anchor = next;
    }
    return length;
  }

 private:
  std::vector<int> neighbours4(int c) const {
    const int x = c % nx_, y = c / nx_;
    std::vector<int> out;
    if (x > 0) out.push_back(c - 1);
    if (x + 1 < nx_) out.push_back(c + 1);
    if (y > 0) out.push_back(c - nx_);
    if (y + 1 < ny_) out.push_back(c + nx_);
    return out;
  }
  // Whether the body can drive straight from `p` to `q` clear of every wall (sampled every 2 cm).
  bool clear(const Point2& p, const Point2& q) const {
    const int samples = static_cast<int>(std::ceil((q - p).norm() / 0.02));
    for (int i = 0; i <= samples; ++i) {
      if (index_.distance(p + (q - p) * (static_cast<double>(i) / std::max(samples, 1))) < radius_ - 1e-9) return false;
    }
    return true;
  }

  double cell_, radius_;
  WallIndex index_;
  int nx_ = 1, ny_ = 1;
  std::vector<bool> free_;
};

}  // namespace frob::worlds
