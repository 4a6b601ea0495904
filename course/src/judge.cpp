#include "frob/course/judge.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <queue>

namespace frob::course {

using Kind = Criterion::Kind;
using worlds::WallDef;
using worlds::WallShape;

namespace {

template <class... A>
std::string format(const char* f, A... args) {
  char buf[256];
  std::snprintf(buf, sizeof buf, f, args...);
  return buf;
}
std::string at(const Point2& p) { return format("(%.1f, %.1f)", p.x(), p.y()); }
std::string secondsText(double s) { return format("%.1f s", s); }

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
    for (std::size_t w : buckets_[clampY(p.y()) * nx_ + clampX(p.x())]) d = std::min(d, worlds::distanceToWall(p, walls_[w]));
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
  FreeGrid(const RunRecord& run, double radius, double cell) : cell_(cell), radius_(radius), index_(run.walls, run.size, radius + cell) {
    nx_ = std::max(1, static_cast<int>(std::floor(run.size.x() / cell)));
    ny_ = std::max(1, static_cast<int>(std::floor(run.size.y() / cell)));
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

// Length of `path` from its start to step `end` (exclusive of later steps).
double lengthUpTo(const std::vector<Point2>& path, std::size_t end) {
  double d = 0;
  for (std::size_t k = 1; k <= end && k < path.size(); ++k) d += (path[k] - path[k - 1]).norm();
  return d;
}

// The first step at which `path` comes within `within` of `p`, from step `from` on.
std::optional<std::size_t> firstWithin(const std::vector<Point2>& path, const Point2& p, double within, std::size_t from = 0) {
  for (std::size_t k = from; k < path.size(); ++k) {
    if ((path[k] - p).norm() <= within) return k;
  }
  return std::nullopt;
}

// The step of `path` closest to `p`.
std::size_t closestTo(const std::vector<Point2>& path, const Point2& p, std::size_t from = 0) {
  std::size_t best = from;
  for (std::size_t k = from; k < path.size(); ++k) {
    if ((path[k] - p).squaredNorm() < (path[best] - p).squaredNorm()) best = k;
  }
  return best;
}

double perimeter(const WallDef& w) {
  const auto& v = w.points;
  switch (w.shape) {
    case WallShape::Segment: return 2 * (v[1] - v[0]).norm();
    case WallShape::Rectangle: return 2 * ((v[1] - v[0]).x() + (v[1] - v[0]).y());
    case WallShape::Circle: return 2 * pi * w.radius;
    case WallShape::Polyline: {
      double d = 0;
      for (std::size_t i = 0; i + 1 < v.size(); ++i) d += (v[i + 1] - v[i]).norm();
      return w.closed ? d + (v.back() - v.front()).norm() : 2 * d;  // an open wall is walked round both sides
    }
  }
  return 0;
}

// A point's name with "{robot}" replaced by the robot's name.
std::string resolved(std::string name, const Track& t) {
  if (const std::size_t i = name.find("{robot}"); i != std::string::npos) name.replace(i, 7, t.name);
  return name;
}

// The named point `name`, if the world has it.
std::optional<Point2> pointNamed(const RunRecord& run, const std::string& name) {
  for (const worlds::NamedPoint& p : run.points) {
    if (p.name == name) return p.position;
  }
  return std::nullopt;
}

class Judge {
 public:
  Judge(const Criterion& c, const RunRecord& run) : c_(c), run_(run) {}

  Verdict operator()() {
    if (c_.kind == Kind::RobotsApart) return robotsApart();
    for (const Track& t : run_.robots) {
      if (t.path.empty()) continue;
      std::string why = robot(t);
      if (!why.empty()) return {false, (run_.robots.size() > 1 ? t.name + " " : "") + why};
    }
    return {true, ""};
  }

 private:
  double timeOf(std::size_t step) const { return static_cast<double>(step) * run_.dt; }
  bool late(std::size_t step) const { return c_.seconds > 0 && timeOf(step) > c_.seconds + 1e-9; }
  std::string allowed() const { return "allowed " + format("%g s", c_.seconds); }

  // Why robot `t` fails the criterion; "" when it meets it.
  std::string robot(const Track& t) {
    switch (c_.kind) {
      case Kind::Goal: return goal(t);
      case Kind::Waypoints: return waypoints(t);
      case Kind::Stopped: {
        const std::size_t n = t.path.size();
        const double speed = n < 2 ? 0.0 : (t.path[n - 1] - t.path[n - 2]).norm() / run_.dt;
        return speed < c_.speed ? "" : format("was still moving at %.2f m/s at the end; it should stop (below %.2f m/s)", speed, c_.speed);
      }
      case Kind::Collisions: return collisions(t);
      case Kind::Clearance: return clearance(t);
      case Kind::WallDistance: return wallDistance(t);
      case Kind::Coverage: return coverage(t);
      case Kind::PathRatio:
      case Kind::Bug1Bound: return pathLength(t);
      case Kind::Returns:
        if (!t.returned) return "its task never returned a value (reported by the controller)";
        return *t.returned == c_.value ? "" : "its task returned " + *t.returned + ", not " + c_.value + " (reported by the controller)";
      case Kind::RobotsApart: break;
    }
    return "";
  }

  std::string goal(const Track& t) {
    const std::string name = resolved(c_.point, t);
    const std::optional<Point2> g = pointNamed(run_, name);
    if (!g) return "the world has no point '" + name + "' to reach";
    const std::optional<std::size_t> k = firstWithin(t.path, *g, c_.distance);
    if (!k) {
      const std::size_t near = closestTo(t.path, *g);
      return format("never came within %.2f m of %s (closest %.2f m, at %s)", c_.distance, name.c_str(),
                    (t.path[near] - *g).norm(), secondsText(timeOf(near)).c_str());
    }
    return late(*k) ? "reached " + name + " at " + secondsText(timeOf(*k)) + "; " + allowed() : "";
  }

  std::string waypoints(const Track& t) {
    std::size_t from = 0;
    std::string reached;
    for (const std::string& given : c_.points) {
      const std::string name = resolved(given, t);
      const std::optional<Point2> p = pointNamed(run_, name);
      if (!p) return "the world has no point '" + name + "' to visit";
      const std::optional<std::size_t> k = firstWithin(t.path, *p, c_.distance, from);
      if (!k) {
        const std::size_t near = closestTo(t.path, *p, from);
        return reached + format("never came within %.2f m of %s after that (closest %.2f m, at %s)", c_.distance, name.c_str(),
                                (t.path[near] - *p).norm(), secondsText(timeOf(near)).c_str());
      }
      if (late(*k)) return reached + "reached " + name + " at " + secondsText(timeOf(*k)) + "; " + allowed();
      reached += "reached " + name + " at " + secondsText(timeOf(*k)) + ", ";
      from = *k;
    }
    return "";
  }

  std::string collisions(const Track& t) {
    if (static_cast<int>(t.contacts.size()) <= c_.count) return "";
    const auto& [when, where] = t.contacts[static_cast<std::size_t>(c_.count)];
    const WallIndex walls(run_.walls, run_.size, 1.0);
    const char* what = walls.distance(where) <= t.radius + 0.05 ? "a wall" : "another robot";
    std::string why = format("touched %s at %s at %s", what, secondsText(when).c_str(), at(where).c_str());
    if (c_.count > 0 || t.contacts.size() > 1) why += format(" (%zu contacts; %d allowed)", t.contacts.size(), c_.count);
    return why;
  }

  std::string clearance(const Track& t) {
    const WallIndex walls(run_.walls, run_.size, t.radius + c_.distance + 1.0);
    for (std::size_t k = 0; k < t.path.size(); ++k) {
      const double gap = walls.distance(t.path[k]) - t.radius;
      if (gap < c_.distance - 1e-9) {
        return format("came within %.2f m of a wall at %s at %s; at least %.2f m required", std::max(gap, 0.0),
                      secondsText(timeOf(k)).c_str(), at(t.path[k]).c_str(), c_.distance);
      }
    }
    return "";
  }

  std::string wallDistance(const Track& t) {
    const WallIndex walls(run_.walls, run_.size, t.radius + c_.distance + c_.tolerance + 1.0);
    std::size_t counted = 0, within = 0, worst = 0;
    double worstOff = -1;
    for (std::size_t k = 0; k < t.path.size(); ++k) {
      if (timeOf(k) < c_.after - 1e-9) continue;
      const double off = std::abs(walls.distance(t.path[k]) - t.radius - c_.distance);
      ++counted;
      if (off <= c_.tolerance + 1e-9) ++within;  // a value on the boundary is within it
      if (off > worstOff) worstOff = off, worst = k;
    }
    const double share = counted == 0 ? 0.0 : static_cast<double>(within) / static_cast<double>(counted);
    if (share >= c_.fraction) return "";
    return format("kept %.2f ± %.2f m from the wall for %.0f%% of the time after %s; %.0f%% required (furthest off: %.2f m at %s at %s)",
                  c_.distance, c_.tolerance, 100 * share, secondsText(c_.after).c_str(), 100 * c_.fraction, worstOff,
                  secondsText(timeOf(worst)).c_str(), at(t.path[worst]).c_str());
  }

  std::string coverage(const Track& t) {
    const FreeGrid grid(run_, t.radius, c_.cell);
    const std::vector<bool> reachable = grid.reachable(grid.cellOf(t.path.front()));
    std::vector<bool> visited(reachable.size(), false);
    for (const Point2& p : t.path) visited[grid.cellOf(p)] = true;
    std::size_t free = 0, seen = 0;
    for (std::size_t c = 0; c < reachable.size(); ++c) {
      free += reachable[c];
      seen += reachable[c] && visited[c];
    }
    const double share = free == 0 ? 0.0 : static_cast<double>(seen) / static_cast<double>(free);
    if (share >= c_.fraction) return "";
    return format("covered %.0f%% of the floor it could reach (%zu of %zu cells of %.2f m); %.0f%% required", 100 * share, seen, free,
                  c_.cell, 100 * c_.fraction);
  }

  std::string pathLength(const Track& t) {
    const std::string name = resolved(c_.point, t);
    const std::optional<Point2> g = pointNamed(run_, name);
    if (!g) return "the world has no point '" + name + "'";
    const double within = std::max(c_.distance, t.radius);
    const std::optional<std::size_t> k = firstWithin(t.path, *g, within);
    if (!k) return format("never came within %.2f m of %s, so its path cannot be measured", within, name.c_str());
    const double travelled = lengthUpTo(t.path, *k);
    const double direct = (*g - t.path.front()).norm();
    if (c_.kind == Kind::PathRatio) {
      const double shortest = FreeGrid(run_, t.radius, 0.05).shortestPath(t.path.front(), *g);
      if (travelled <= c_.ratio * shortest + 1e-9) return "";
      return format("drove %.2f m to %s; the shortest path is %.2f m and at most %.2f× that (%.2f m) is allowed", travelled,
                    name.c_str(), shortest, c_.ratio, c_.ratio * shortest);
    }
    // BUG1: the obstacles met are the walls (not the enclosure) the body came within 0.3 m of.
    const std::size_t inner = run_.walls.size() - run_.enclosureWalls;
    double perimeters = 0;
    std::size_t met = 0;
    for (std::size_t w = 0; w < inner; ++w) {
      const bool near = std::any_of(t.path.begin(), t.path.begin() + static_cast<std::ptrdiff_t>(*k + 1),
                                    [&](const Point2& p) { return worlds::distanceToWall(p, run_.walls[w]) <= t.radius + 0.3; });
      if (near) perimeters += perimeter(run_.walls[w]), ++met;
    }
    const double bound = direct + 1.5 * perimeters;
    if (travelled <= bound + 1e-9) return "";
    return format("drove %.2f m to %s; the BUG1 bound is %.2f m (%.2f m direct + 1.5 × %.2f m of perimeter of the %zu obstacles met)",
                  travelled, name.c_str(), bound, direct, perimeters, met);
  }

  Verdict robotsApart() {
    for (std::size_t i = 0; i < run_.robots.size(); ++i) {
      for (std::size_t j = i + 1; j < run_.robots.size(); ++j) {
        const Track &a = run_.robots[i], &b = run_.robots[j];
        for (std::size_t k = 0; k < std::min(a.path.size(), b.path.size()); ++k) {
          const double gap = (a.path[k] - b.path[k]).norm() - a.radius - b.radius;
          if (gap < c_.distance + 0.01) {  // Box2D lets touching bodies overlap by up to a centimetre
            return {false, format("%s and %s %s at %s at %s", a.name.c_str(), b.name.c_str(),
                                  c_.distance > 0 ? format("came within %.2f m of each other", std::max(gap, 0.0)).c_str() : "touched",
                                  secondsText(timeOf(k)).c_str(), at((a.path[k] + b.path[k]) / 2).c_str())};
          }
        }
      }
    }
    return {true, ""};
  }

  const Criterion& c_;
  const RunRecord& run_;
};

}  // namespace

Verdict judge(const Criterion& criterion, const RunRecord& run) { return Judge(criterion, run)(); }

}  // namespace frob::course
