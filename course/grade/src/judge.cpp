#include "frob/grade/judge.hpp"

#include "frob/run/format.hpp"
#include "frob/worlds/free_space.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iterator>
#include <optional>
#include <queue>

namespace frob::course {

using Kind = Criterion::Kind;
using worlds::WallDef;
using worlds::WallShape;

namespace {

std::string at(const Point2& p) { return format("(%.1f, %.1f)", p.x(), p.y()); }
std::string secondsText(double s) { return format("%.1f s", s); }

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

// A touch this soon after the robot last touched something is that collision going on: a robot
// still stopping bounces, or glances round a corner onto the next face (seconds).
constexpr double kSameCollision = 0.5;

// A touch that goes on while the robot drives counts again for every second of driving it lasts:
// pushing along an obstacle is many collisions, not one (seconds).
constexpr double kSlidePerCollision = 1.0;
// Below this the centre stands still: a robot pressed against what it stopped at slides nowhere (m/s).
constexpr double kStill = 0.02;
// A robot following an event may stand still this long in the `within` s before it: a step or two
// between driving and turning at a corner, not a stop (seconds).
constexpr double kStandingBefore = 0.25;
// How late a reported event may come when the rubric states no `within`: seen a step after it
// happened, a controller ends its task at once (seconds).
constexpr double kReportLatency = 1.0;

// The contacts that began a collision: touching spans and contacts (each in the step before it was
// sensed) merged where less than kSameCollision apart, the first contact of each; then, for each
// started kSlidePerCollision of driving while touching after the first, one more at that instant.
std::vector<std::pair<double, Point2>> collisionsOf(const Track& t, double dt) {
  std::vector<std::pair<double, double>> touches = t.touching;
  for (const auto& contact : t.contacts) touches.emplace_back(contact.first - dt, contact.first);
  std::sort(touches.begin(), touches.end());
  std::vector<std::pair<double, double>> merged;
  for (const auto& touch : touches) {
    if (!merged.empty() && touch.first < merged.back().second + kSameCollision - 1e-9) {
      merged.back().second = std::max(merged.back().second, touch.second);
    } else {
      merged.push_back(touch);
    }
  }
  std::vector<std::pair<double, Point2>> starts;
  std::vector<std::size_t> groups;  // the group each start began
  std::size_t group = 0;
  for (const auto& contact : t.contacts) {
    while (merged[group].second < contact.first - 1e-9) ++group;
    if (groups.empty() || groups.back() != group) starts.push_back(contact), groups.push_back(group);
  }
  for (const std::size_t g : groups) {
    double slid = 0.0;  // driving while touching, in this collision's touching spans
    for (const auto& [from, to] : t.touching) {
      if (from < merged[g].first - 1e-9 || to > merged[g].second + 1e-9) continue;
      for (auto k = static_cast<std::size_t>(std::max(1.0, std::ceil(from / dt - 1e-9))); k < t.path.size() && k * dt <= to + 1e-9; ++k) {
        if ((t.path[k] - t.path[k - 1]).norm() / dt < kStill) continue;
        slid += dt;
        if (slid > kSlidePerCollision + 1e-9) starts.emplace_back(static_cast<double>(k) * dt, t.path[k]), slid -= kSlidePerCollision;
      }
    }
  }
  std::stable_sort(starts.begin(), starts.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
  return starts;
}

double perimeter(const WallDef& w) {
  const auto& v = w.points;
  switch (w.shape) {
    case WallShape::Segment:
      return 2 * (v[1] - v[0]).norm();
    case WallShape::Rectangle:
      return 2 * ((v[1] - v[0]).x() + (v[1] - v[0]).y());
    case WallShape::Circle:
      return 2 * pi * w.radius;
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
  for (const worlds::Landmark& p : run.points) {
    if (p.name == name) return p.position;
  }
  return std::nullopt;
}

class Judge {
 public:
  Judge(const Criterion& c, const RunRecord& run) : c_(c), run_(run) {}

  // The first robot that fails gives the reason and the margin; when all pass, the robot nearest the edge.
  Verdict operator()() {
    if (c_.kind == Kind::RobotsApart) return robotsApart();
    std::optional<Margin> least;
    for (const Track& t : run_.robots) {
      if (t.path.empty()) continue;
      margin_.reset();
      std::string why = robot(t);
      const std::string who = run_.robots.size() > 1 ? t.name + " " : "";
      if (margin_) margin_->text = who + margin_->text;
      if (!why.empty()) return {false, who + why, margin_};
      if (margin_ && (!least || margin_->value < least->value)) least = margin_;
    }
    return {true, "", least};
  }

 private:
  double timeOf(std::size_t step) const { return static_cast<double>(step) * run_.dt; }
  bool late(std::size_t step) const { return c_.seconds > 0 && timeOf(step) > c_.seconds + 1e-9; }
  std::string allowed() const { return "allowed " + format("%g s", c_.seconds); }
  // Notes the robot's margin: `value` in `unit`, measured as `text`, decided at `when`.
  void measured(double value, const char* unit, std::string text, std::optional<double> when = std::nullopt) {
    margin_ = Margin{.value = value, .unit = unit, .text = std::move(text), .at = when};
  }
  // The margin of reaching `name`, first within reach at step `k`, or never (closest at step `near`).
  void reachMargin(const Track& t, const Point2& p, const std::string& name, std::optional<std::size_t> k, std::size_t from = 0) {
    if (k && c_.seconds > 0) {
      measured(c_.seconds - timeOf(*k), "s", format("reached %s at %.1f s of %g s", name.c_str(), timeOf(*k), c_.seconds), timeOf(*k));
      return;
    }
    const std::size_t near = closestTo(t.path, p, from);
    const double d = (t.path[near] - p).norm();
    measured(c_.distance - d, "m", format("closest %.2f m to %s; %.2f m needed", d, name.c_str(), c_.distance), timeOf(near));
  }

  // Why robot `t` fails the criterion; "" when it meets it.
  std::string robot(const Track& t) {
    switch (c_.kind) {
      case Kind::Goal:
        return goal(t);
      case Kind::Waypoints:
        return waypoints(t);
      case Kind::Stopped:
        return stopped(t);
      case Kind::Collisions:
        return collisions(t);
      case Kind::Clearance:
        return clearance(t);
      case Kind::WallDistance:
        return wallDistance(t);
      case Kind::Coverage:
        return coverage(t);
      case Kind::PathRatio:
      case Kind::Bug1Bound:
        return pathLength(t);
      case Kind::Returns:
        return returns(t);
      case Kind::RobotsApart:
        break;
    }
    return "";
  }

  // The event the criterion follows, as the simulator saw it: when it happened, or why it did not.
  struct Event {
    std::optional<double> at;
    std::string what, never;
  };
  Event event(const Track& t) const {
    const double end = timeOf(t.path.size() - 1);
    if (c_.afterKey != 0) {
      Event e{.what = format("the key %c was pressed", c_.afterKey), .never = format("the key %c was never pressed", c_.afterKey)};
      for (const worlds::KeyEventDef& k : run_.keys) {
        if (k.key == c_.afterKey && k.time <= end + 1e-9) return e.at = k.time, e;
      }
      return e;
    }
    if (c_.afterContact) {
      Event e{.what = "it touched something", .never = "it never touched anything"};
      if (!t.contacts.empty()) e.at = t.contacts.front().first;
      return e;
    }
    if (c_.afterDistance > 0) {
      Event e{.what = format("it had driven %.1f m", c_.afterDistance), .never = format("it never drove %.1f m", c_.afterDistance)};
      double driven = 0;
      for (std::size_t k = 1; k < t.path.size() && !e.at; ++k) {
        driven += (t.path[k] - t.path[k - 1]).norm();
        if (driven >= c_.afterDistance) e.at = timeOf(k);
      }
      return e;
    }
    return {.at = 0.0};
  }

  // How fast the fastest point of the body moves at step k (k >= 1): the centre's speed, plus the
  // rim's from turning on the spot (m/s).
  double bodySpeed(const Track& t, std::size_t k) const {
    const double turn = k < t.heading.size() ? std::abs(std::remainder(t.heading[k] - t.heading[k - 1], 2 * pi)) * t.radius : 0.0;
    return ((t.path[k] - t.path[k - 1]).norm() + turn) / run_.dt;
  }

  std::string stopped(const Track& t) {
    const Event e = event(t);
    if (!e.at) return e.never + ", so it had nothing to stop for";
    const std::size_t n = t.path.size();
    const bool follows = c_.afterKey != 0 || c_.afterContact;
    if (follows) {
      // Moving until the event: it stood still at most kStandingBefore of the `within` s before it.
      double stood = 0.0;
      for (std::size_t k = 1; k < n && timeOf(k) <= *e.at + 1e-9; ++k) {
        if (timeOf(k) > *e.at - c_.within + 1e-9 && bodySpeed(t, k) < c_.speed) stood += run_.dt;
      }
      if (stood > kStandingBefore + 1e-9) {
        measured(kStandingBefore - stood, "s", format("stood still %.2f s before %s; at most %.2f s", stood, e.what.c_str(), kStandingBefore), *e.at);
        return format("stood still for %.1f s of the %g s before %s (at %s); it must be moving until then", stood, c_.within, e.what.c_str(),
                      secondsText(*e.at).c_str());
      }
    }
    const std::size_t after = static_cast<std::size_t>(std::ceil((*e.at + c_.within) / run_.dt - 1e-9));
    const std::size_t from = follows ? std::min(after, n - 1) : n - 1;
    if (follows) {
      // The margin: how long before the deadline it last moved.
      std::size_t last = 0;
      for (std::size_t k = 1; k < n; ++k) {
        if (timeOf(k) > *e.at + 1e-9 && bodySpeed(t, k) >= c_.speed) last = k;
      }
      const double moving = last == 0 ? 0.0 : timeOf(last) - *e.at;
      measured(c_.within - moving, "s", format("moved until %.1f s after %s; %g s allowed", moving, e.what.c_str(), c_.within),
               last == 0 ? *e.at : timeOf(last));
    } else {
      const double speed = n > 1 ? bodySpeed(t, n - 1) : 0.0;
      measured(c_.speed - speed, "m/s", format("moving at %.2f m/s at the end; below %.2f m/s needed", speed, c_.speed), timeOf(n - 1));
    }
    for (std::size_t k = std::max<std::size_t>(from, 1); k < n; ++k) {
      const double speed = bodySpeed(t, k);
      if (speed < c_.speed) continue;
      if (k == n - 1 && from >= n - 1) return format("was still moving at %.2f m/s at the end; it should stop (below %.2f m/s)", speed, c_.speed);
      return format("was moving at %.2f m/s at %s, %.1f s after %s; it should stop within %g s (below %.2f m/s)", speed,
                    secondsText(timeOf(k)).c_str(), timeOf(k) - *e.at, e.what.c_str(), c_.within, c_.speed);
    }
    return "";
  }

  std::string returns(const Track& t) {
    if (!t.returned) return "its task never returned a value (reported by the controller)";
    if (*t.returned != c_.value) {
      return "its task returned " + (t.returned->empty() ? std::string("no value") : *t.returned) + ", not " + c_.value +
             " (reported by the controller)";
    }
    const Event e = event(t);
    if (!e.at) return "its task returned " + c_.value + ", but " + e.never;
    if (t.returnedAt + run_.dt < *e.at - 1e-9) {  // a step's grace: an event is seen in the frame after it
      measured(t.returnedAt - *e.at, "s", format("returned %.1f s before %s", *e.at - t.returnedAt, e.what.c_str()), t.returnedAt);
      return "its task returned " + c_.value + " at " + secondsText(t.returnedAt) + ", before " + e.what + " (at " + secondsText(*e.at) + ")";
    }
    if (c_.afterKey != 0 || c_.afterContact || c_.afterDistance > 0) {
      const double latency = c_.within > 0 ? c_.within : kReportLatency;
      measured(latency - (t.returnedAt - *e.at), "s", format("returned %.1f s after %s; at most %g s", t.returnedAt - *e.at, e.what.c_str(), latency),
               t.returnedAt);
      if (t.returnedAt > *e.at + latency + 1e-9) {
        return "its task returned " + c_.value + " at " + secondsText(t.returnedAt) + ", " + secondsText(t.returnedAt - *e.at) + " after " + e.what +
               format("; at most %g s later allowed", latency);
      }
    }
    return "";
  }

  std::string goal(const Track& t) {
    const std::string name = resolved(c_.point, t);
    const std::optional<Point2> g = pointNamed(run_, name);
    if (!g) return "the world has no point '" + name + "' to reach";
    const std::optional<std::size_t> k = firstWithin(t.path, *g, c_.distance);
    reachMargin(t, *g, name, k);
    if (!k) {
      const std::size_t near = closestTo(t.path, *g);
      return format("never came within %.2f m of %s (closest %.2f m, at %s)", c_.distance, name.c_str(), (t.path[near] - *g).norm(),
                    secondsText(timeOf(near)).c_str());
    }
    return late(*k) ? "reached " + name + " at " + secondsText(timeOf(*k)) + "; " + allowed() : "";
  }

  std::string waypoints(const Track& t) {
    std::size_t from = 0;
    std::string reached;
    std::optional<Margin> least;  // with a time bound the last waypoint's, else the one passed nearest the edge
    for (const std::string& given : c_.points) {
      const std::string name = resolved(given, t);
      const std::optional<Point2> p = pointNamed(run_, name);
      if (!p) return margin_.reset(), "the world has no point '" + name + "' to visit";
      const std::optional<std::size_t> k = firstWithin(t.path, *p, c_.distance, from);
      reachMargin(t, *p, name, k, from);
      if (!k) {
        const std::size_t near = closestTo(t.path, *p, from);
        return reached + format("never came within %.2f m of %s%s (closest %.2f m, at %s)", c_.distance, name.c_str(),
                                reached.empty() ? "" : " after that", (t.path[near] - *p).norm(), secondsText(timeOf(near)).c_str());
      }
      if (late(*k)) return reached + "reached " + name + " at " + secondsText(timeOf(*k)) + "; " + allowed();
      if (c_.seconds > 0 || !least || margin_->value < least->value) least = margin_;
      reached += "reached " + name + " at " + secondsText(timeOf(*k)) + ", ";
      from = *k;
    }
    margin_ = least;
    return "";
  }

  std::string collisions(const Track& t) {
    const std::vector<std::pair<double, Point2>> hits = collisionsOf(t, run_.dt);
    const auto many = [](std::size_t n) { return n == 0 ? std::string("no collision") : format("%zu collision%s", n, n == 1 ? "" : "s"); };
    measured(c_.count - static_cast<double>(hits.size()), "collisions", many(hits.size()) + format("; at most %d", c_.count),
             hits.size() > static_cast<std::size_t>(c_.count) ? std::optional(hits[static_cast<std::size_t>(c_.count)].first) : std::nullopt);
    if (static_cast<int>(hits.size()) <= c_.count) return c_.seconds > 0 ? touchingTime(t) : "";
    const auto& [when, where] = hits[static_cast<std::size_t>(c_.count)];
    const std::string what = obstacleAt(where, t.radius + 0.05).value_or("another robot");
    std::string why = format("touched %s at %s at %s", what.c_str(), secondsText(when).c_str(), at(where).c_str());
    if (c_.count > 0 || hits.size() > 1) why += format(" (%zu collisions; %d allowed)", hits.size(), c_.count);
    return why;
  }

  // Touching for longer than `seconds` in all: a path that pushes along a wall, not round it.
  std::string touchingTime(const Track& t) {
    double total = 0.0;
    const std::pair<double, double>* longest = nullptr;
    for (const auto& span : t.touching) {
      total += span.second - span.first;
      if (longest == nullptr || span.second - span.first > longest->second - longest->first) longest = &span;
    }
    if (total <= c_.seconds + 1e-9) return "";
    measured(c_.seconds - total, "s", format("pressed its bumpers %.1f s in all; at most %g s", total, c_.seconds), longest->first);
    return format("pressed its bumpers for %s in all, the longest touch from %s to %s; at most %s allowed", secondsText(total).c_str(),
                  secondsText(longest->first).c_str(), secondsText(longest->second).c_str(), secondsText(c_.seconds).c_str());
  }

  // What the robot at `p` touches within `reach`, the nearest, named by what it is: the world's
  // enclosing wall or a wall in it, a block (a box, a cupboard) or a round obstacle (a pillar, a table, a leg); none within reach: nothing.
  std::optional<std::string> obstacleAt(const Point2& p, double reach) const {
    std::optional<std::size_t> nearest;
    double best = reach;
    for (std::size_t w = 0; w < run_.walls.size(); ++w) {
      const double d = worlds::distanceToWall(p, run_.walls[w]);
      if (d <= best) best = d, nearest = w;
    }
    if (!nearest) return std::nullopt;
    if (*nearest >= run_.walls.size() - run_.enclosureWalls) return "the outer wall";
    switch (run_.walls[*nearest].shape) {
      case worlds::WallShape::Rectangle:
        return "a block";
      case worlds::WallShape::Circle:
        return "a round obstacle";
      default:
        return "a wall";
    }
  }

  std::string clearance(const Track& t) {
    const worlds::WallIndex walls(run_.walls, run_.size, t.radius + c_.distance + 1.0);
    std::size_t nearest = 0;
    double least = INFINITY;
    for (std::size_t k = 0; k < t.path.size(); ++k) {
      const double gap = walls.distance(t.path[k]) - t.radius;
      if (gap < least) least = gap, nearest = k;
    }
    measured(least - c_.distance, "m", format("came within %.2f m of a wall; at least %.2f m required", std::max(least, 0.0), c_.distance),
             timeOf(nearest));
    for (std::size_t k = 0; k < t.path.size(); ++k) {
      const double gap = walls.distance(t.path[k]) - t.radius;
      if (gap < c_.distance - 1e-9) {
        return format("came within %.2f m of %s at %s at %s; at least %.2f m required", std::max(gap, 0.0),
                      obstacleAt(t.path[k], t.radius + c_.distance).value_or("a wall").c_str(), secondsText(timeOf(k)).c_str(), at(t.path[k]).c_str(),
                      c_.distance);
      }
    }
    return "";
  }

  // The centre's distance to the nearest wall, or, with a side, to the nearest wall that side: the
  // least along rays from 60 to 120 degrees off the heading.
  double wallDistanceAt(const Track& t, std::size_t k, const worlds::WallIndex& walls) const {
    if (c_.side.empty() || k >= t.heading.size()) return walls.distance(t.path[k]);
    const double toSide = c_.side == "right" ? -pi / 2 : pi / 2;
    double d = INFINITY;
    for (int ray = -3; ray <= 3; ++ray) {
      const double a = t.heading[k] + toSide + ray * (pi / 18);
      for (const WallDef& w : run_.walls) d = std::min(d, worlds::rayToWall(t.path[k], Vec2(std::cos(a), std::sin(a)), w));
    }
    return std::min(d, run_.size.norm());  // no wall that side: as far as the world is wide
  }

  std::string wallDistance(const Track& t) {
    const worlds::WallIndex walls(run_.walls, run_.size, t.radius + c_.distance + c_.tolerance + 1.0);
    std::size_t counted = 0, within = 0, worst = 0;
    double worstOff = -1;
    for (std::size_t k = 0; k < t.path.size(); ++k) {
      if (timeOf(k) < c_.after - 1e-9) continue;
      const double off = std::abs(wallDistanceAt(t, k, walls) - t.radius - c_.distance);
      ++counted;
      if (off <= c_.tolerance + 1e-9) ++within;  // a value on the boundary is within it
      if (off > worstOff) worstOff = off, worst = k;
    }
    const double share = counted == 0 ? 0.0 : static_cast<double>(within) / static_cast<double>(counted);
    const std::string wall = c_.side.empty() ? "the wall" : "the wall on its " + c_.side;
    measured(100 * (share - c_.fraction), "points",
             format("kept %.2f ± %.2f m from %s %.0f%% of the time; %.0f%% required", c_.distance, c_.tolerance, wall.c_str(), 100 * share,
                    100 * c_.fraction),
             timeOf(worst));
    if (share >= c_.fraction) return "";
    return format("kept %.2f ± %.2f m from %s for %.0f%% of the time after %s; %.0f%% required (at worst %.2f m off the %.2f m wanted, at %s at %s)",
                  c_.distance, c_.tolerance, wall.c_str(), 100 * share, secondsText(c_.after).c_str(), 100 * c_.fraction, worstOff, c_.distance,
                  secondsText(timeOf(worst)).c_str(), at(t.path[worst]).c_str());
  }

  std::string coverage(const Track& t) {
    const worlds::FreeGrid grid(run_.walls, run_.size, t.radius, c_.cell);
    // With `away`, only the floor where the body keeps that far from every wall counts: the room's
    // middle, not the band a lap along its walls passes over.
    const worlds::FreeGrid open(run_.walls, run_.size, t.radius + c_.distance, c_.cell);
    const std::vector<bool> reachable = grid.reachable(grid.cellOf(t.path.front()));
    std::vector<bool> visited(reachable.size(), false);
    for (const Point2& p : t.path) visited[grid.cellOf(p)] = true;
    std::size_t free = 0, seen = 0;
    for (std::size_t c = 0; c < reachable.size(); ++c) {
      const bool counted = reachable[c] && open.free(static_cast<int>(c));
      free += counted;
      seen += counted && visited[c];
    }
    const double share = free == 0 ? 0.0 : static_cast<double>(seen) / static_cast<double>(free);
    const std::string floor =
        c_.distance > 0 ? format("the floor it could reach %.2f m or more from walls", c_.distance) : "the floor it could reach";
    measured(100 * (share - c_.fraction), "points", format("covered %.0f%% of %s; %.0f%% required", 100 * share, floor.c_str(), 100 * c_.fraction));
    if (share >= c_.fraction) return "";
    return format("covered %.0f%% of %s (%zu of %zu cells of %.2f m); %.0f%% required", 100 * share, floor.c_str(), seen, free, c_.cell,
                  100 * c_.fraction);
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
      const double shortest = worlds::FreeGrid(run_.walls, run_.size, t.radius, 0.05).shortestPath(t.path.front(), *g);
      measured(c_.ratio * shortest - travelled, "m", format("drove %.2f m to %s; at most %.2f m", travelled, name.c_str(), c_.ratio * shortest),
               timeOf(*k));
      if (travelled <= c_.ratio * shortest + 1e-9) return "";
      return format("drove %.2f m to %s; the shortest path is %.2f m and at most %.2f× that (%.2f m) is allowed", travelled, name.c_str(), shortest,
                    c_.ratio, c_.ratio * shortest);
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
    measured(bound - travelled, "m", format("drove %.2f m to %s; the BUG1 bound is %.2f m", travelled, name.c_str(), bound), timeOf(*k));
    if (travelled <= bound + 1e-9) return "";
    return format("drove %.2f m to %s; the BUG1 bound is %.2f m (%.2f m direct + 1.5 × %.2f m of perimeter of the %zu obstacles met)", travelled,
                  name.c_str(), bound, direct, perimeters, met);
  }

  // Box2D lets touching bodies overlap by up to a centimetre: closer than this over the distance required is too close.
  static constexpr double kOverlap = 0.01;

 public:
  // What the criterion measures of each robot at every step, as it measures it to judge.
  std::vector<Measured> measured() const {
    std::vector<Measured> out;
    for (std::size_t i = 0; i < run_.robots.size(); ++i) {
      const Track& t = run_.robots[i];
      Measured m{.unit = "m", .robot = i, .dt = run_.dt};
      switch (c_.kind) {
        case Kind::WallDistance: {
          const worlds::WallIndex walls(run_.walls, run_.size, t.radius + c_.distance + c_.tolerance + 1.0);
          m.name = "wall_distance", m.low = c_.distance - c_.tolerance, m.high = c_.distance + c_.tolerance, m.from = c_.after;
          for (std::size_t k = 0; k < t.path.size(); ++k) m.values.push_back(wallDistanceAt(t, k, walls) - t.radius);
          break;
        }
        case Kind::Clearance: {
          const worlds::WallIndex walls(run_.walls, run_.size, t.radius + c_.distance + 1.0);
          m.name = "clearance", m.low = c_.distance;
          for (const Point2& p : t.path) m.values.push_back(walls.distance(p) - t.radius);
          break;
        }
        case Kind::Goal: {
          const std::string name = resolved(c_.point, t);
          const std::optional<Point2> g = pointNamed(run_, name);
          if (!g) continue;
          m.name = name + "_distance", m.high = c_.distance, m.everyInstant = false;
          for (const Point2& p : t.path) m.values.push_back((p - *g).norm());
          break;
        }
        case Kind::Coverage: {
          const worlds::FreeGrid grid(run_.walls, run_.size, t.radius, c_.cell);
          const std::vector<bool> reachable = grid.reachable(grid.cellOf(t.path.front()));
          const auto free = static_cast<double>(std::count(reachable.begin(), reachable.end(), true));
          std::vector<bool> visited(reachable.size(), false);
          double seen = 0;
          m.name = "covered", m.unit = "%", m.low = 100 * c_.fraction, m.everyInstant = false;
          for (const Point2& p : t.path) {
            const std::size_t cell = grid.cellOf(p);
            if (reachable[cell] && !visited[cell]) visited[cell] = true, ++seen;
            m.values.push_back(free == 0 ? 0.0 : 100 * seen / free);
          }
          break;
        }
        case Kind::RobotsApart: {
          if (run_.robots.size() < 2) continue;
          m.name = "nearest_robot", m.low = c_.distance + kOverlap;
          for (std::size_t k = 0; k < t.path.size(); ++k) {
            double gap = INFINITY;
            for (const Track& o : run_.robots) {
              if (&o != &t && k < o.path.size()) gap = std::min(gap, (t.path[k] - o.path[k]).norm() - t.radius - o.radius);
            }
            m.values.push_back(gap);
          }
          break;
        }
        default:
          continue;
      }
      out.push_back(std::move(m));
    }
    return out;
  }

 private:
  Verdict robotsApart() {
    std::optional<Margin> least;
    for (std::size_t i = 0; i < run_.robots.size(); ++i) {
      for (std::size_t j = i + 1; j < run_.robots.size(); ++j) {
        const Track &a = run_.robots[i], &b = run_.robots[j];
        for (std::size_t k = 0; k < std::min(a.path.size(), b.path.size()); ++k) {
          const double gap = (a.path[k] - b.path[k]).norm() - a.radius - b.radius;
          if (!least || gap - c_.distance - kOverlap < least->value) {
            least = Margin{.value = gap - c_.distance - kOverlap,
                           .unit = "m",
                           .text = format("%s and %s came within %.2f m of each other; %.2f m required", a.name.c_str(), b.name.c_str(),
                                          std::max(gap, 0.0), c_.distance + kOverlap),
                           .at = timeOf(k)};
          }
        }
      }
    }
    for (std::size_t i = 0; i < run_.robots.size(); ++i) {
      for (std::size_t j = i + 1; j < run_.robots.size(); ++j) {
        const Track &a = run_.robots[i], &b = run_.robots[j];
        for (std::size_t k = 0; k < std::min(a.path.size(), b.path.size()); ++k) {
          const double gap = (a.path[k] - b.path[k]).norm() - a.radius - b.radius;
          if (gap < c_.distance + kOverlap) {
            return {false,
                    format("%s and %s %s at %s at %s", a.name.c_str(), b.name.c_str(),
                           c_.distance > 0 ? format("came within %.2f m of each other", std::max(gap, 0.0)).c_str() : "touched",
                           secondsText(timeOf(k)).c_str(), at((a.path[k] + b.path[k]) / 2).c_str()),
                    least};
          }
        }
      }
    }
    return {true, "", least};
  }

  const Criterion& c_;
  const RunRecord& run_;
  std::optional<Margin> margin_;  // the robot being judged's
};

}  // namespace

std::string Margin::amount() const {
  const double by = std::abs(value);
  if (unit == "s") return format("%.1f s", by);
  if (unit == "points") return format("%.0f percentage point%s", by, std::lround(by) == 1 ? "" : "s");
  if (unit == "collisions") return format("%.0f collision%s", by, std::lround(by) == 1 ? "" : "s");
  return format("%.2f %s", by, unit.c_str());
}

std::string Margin::said(bool passed) const { return std::string(passed ? "passed by " : "failed by ") + amount() + " (" + text + ")"; }

Verdict judge(const Criterion& criterion, const RunRecord& run) { return Judge(criterion, run)(); }

std::vector<Check> checksFor(const Rubric& rubric, const std::string& world) {
  std::error_code ec;
  const std::filesystem::path file = std::filesystem::weakly_canonical(world, ec);
  const auto runsThere = [&](const Check& c) {
    return std::any_of(c.worlds.begin(), c.worlds.end(),
                       [&](const WorldRef& w) { return w.file.empty() ? w.name == world : std::filesystem::weakly_canonical(w.file, ec) == file; });
  };
  std::vector<Check> there;
  std::copy_if(rubric.checks.begin(), rubric.checks.end(), std::back_inserter(there), runsThere);
  return there.empty() ? rubric.checks : there;
}

std::vector<Measured> measuredAlong(const std::vector<Check>& checks, const RunRecord& record) {
  std::vector<Measured> all;
  for (const Check& check : checks) {
    for (const Criterion& c : check.criteria) {
      for (Measured& m : Judge(c, record).measured()) {
        const bool known = std::any_of(all.begin(), all.end(), [&](const Measured& a) { return a.robot == m.robot && a.name == m.name; });
        if (!known) all.push_back(std::move(m));
      }
    }
  }
  return all;
}

std::vector<CriterionVerdict> judgeChecks(const std::vector<Check>& checks, const RunRecord& record) {
  std::string failure;
  for (const Track& t : record.robots) {
    if (failure.empty() && !t.failure.empty()) failure = "the controller failed: " + t.failure;
  }
  const double ran = record.robots.empty() ? 0.0 : static_cast<double>(record.robots.front().path.size() - 1) * record.dt;
  std::vector<CriterionVerdict> verdicts;
  for (const Check& check : checks) {
    const double seconds = std::min(check.seconds, ran);
    const RunRecord judged = record.upTo(seconds);
    for (const Criterion& c : check.criteria) {
      Verdict v = failure.empty() ? judge(c, judged) : Verdict{.reason = failure};
      verdicts.push_back({.check = check.name,
                          .criterion = std::string(toString(c.kind)),
                          .seconds = seconds,
                          .passed = v.passed,
                          .reason = std::move(v.reason),
                          .margin = std::move(v.margin)});
    }
  }
  return verdicts;
}

}  // namespace frob::course
