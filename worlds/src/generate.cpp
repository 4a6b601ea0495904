#include "frob/worlds/generate.hpp"

#include "frob/worlds/free_space.hpp"
#include "generate_kit.hpp"

#include <algorithm>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <optional>

namespace frob::worlds {

namespace kit {

double mm(double v) { return std::round(v * 1000.0) / 1000.0; }

WorldDef base(const char* what, const Vec2& size, std::uint64_t seed, const Point2& start, double headingDeg) {
  WorldDef w{.description = what, .size = size, .seed = seed};
  w.robots.push_back({.name = "nomad", .start = {.position = start, .heading = headingDeg * pi / 180.0}});
  return w;
}

void knownSpread(WorldDef& w, double metres, double degrees) {
  for (RobotDef& r : w.robots) r.startSpread.knownPosition = metres, r.startSpread.knownHeading = degrees * pi / 180.0;
}

std::vector<WallDef> allWalls(const WorldDef& w) {
  std::vector<WallDef> all = w.walls;
  if (w.enclosed) {
    const Point2 a(0, 0), b(w.size.x(), 0), c = w.size, d(0, w.size.y());
    for (auto [p, q] : {std::pair{a, b}, {b, c}, {c, d}, {d, a}}) all.push_back(segmentWall(p, q));
  }
  return all;
}

double gapBetween(const WallDef& a, const WallDef& b) {
  if (a.shape == WallShape::Circle) return std::max(0.0, distanceToWall(a.points[0], b) - a.radius);
  double d = INFINITY;
  const auto edge = [&](const Point2& p, const Point2& q) {
    for (int i = 0; i <= 40; ++i) d = std::min(d, distanceToWall(p + (q - p) * (i / 40.0), b));
  };
  const auto& v = a.points;
  if (a.shape == WallShape::Rectangle) {
    const Point2 c1(v[1].x(), v[0].y()), c3(v[0].x(), v[1].y());
    edge(v[0], c1), edge(c1, v[1]), edge(v[1], c3), edge(c3, v[0]);
    if (distanceToWall(b.points[0], a) == 0) d = 0;  // b inside a
  } else {
    for (std::size_t i = 0; i + 1 < v.size(); ++i) edge(v[i], v[i + 1]);
    if (a.closed && v.size() > 2) edge(v.back(), v.front());
  }
  return d;
}

double gap(const WallDef& a, const WallDef& b) { return std::min(gapBetween(a, b), gapBetween(b, a)); }

}  // namespace kit

namespace {

using namespace kit;

constexpr double kTrapClearance = 1.5;  // round an obstacle field's L trap: more than a wall follower's reach

void snap(Point2& p) { p = {mm(p.x()), mm(p.y())}; }
void snap(WorldDef& w) {
  snap(w.size);
  for (Landmark& p : w.points) snap(p.position);
  for (RobotDef& r : w.robots) {
    snap(r.start.position);
    r.start.heading = mm(r.start.heading * 180.0 / pi) * pi / 180.0;
  }
  for (WallDef& wall : w.walls) {
    for (Point2& p : wall.points) snap(p);
    wall.radius = mm(wall.radius);
  }
  for (KeyEventDef& k : w.keys) k.time = mm(k.time);
  for (RobotDef& r : w.robots) r.drive.startDelay = mm(r.drive.startDelay), r.drive.maxSpeed = mm(r.drive.maxSpeed);
}

// A world of one of the first kinds: one robot, and the point "goal".
WorldDef base(const char* what, const Vec2& size, std::uint64_t seed, const Point2& start, double headingDeg, const Point2& goal) {
  WorldDef w = kit::base(what, size, seed, start, headingDeg);
  w.points.push_back({"goal", goal});
  return w;
}

// The promises of every kind: clearance round every start and named point, robots apart, and a
// way from the first robot's start to every point.
bool keepsPromises(const WorldDef& w) {
  const std::vector<WallDef> walls = allWalls(w);
  if (w.robots.empty()) return false;
  const WallIndex index(walls, w.size, 1.0);
  const FreeGrid grid(walls, w.size, kRadius, 0.05);
  const Point2 start = w.robots.front().start.position;
  const std::vector<bool> reachable = grid.reachable(grid.cellOf(start));
  for (std::size_t i = 0; i < w.robots.size(); ++i) {
    const Point2 p = w.robots[i].start.position;
    if (index.distance(p) < kRadius + kClearance || !reachable[grid.cellOf(p)]) return false;
    for (std::size_t j = 0; j < i; ++j) {
      if ((w.robots[j].start.position - p).norm() < 2 * (kRadius + kClearance)) return false;
    }
  }
  return std::all_of(w.points.begin(), w.points.end(),
                     [&](const Landmark& p) { return index.distance(p.position) >= kRadius + kClearance && reachable[grid.cellOf(p.position)]; });
}

WorldDef obstacles(Random& r, std::uint64_t seed) {
  WorldDef w = base("Generated obstacle field: blocks, pillars, spurs from the walls and a trap between the start and the goal", {15, 15}, seed,
                    {1.5, 1.5}, 45, {13.5, 13.5});
  knownSpread(w, 0.1, 10);
  const double apart = 2 * kRadius + 0.3;  // a wall follower passes between two obstacles without touching either
  std::vector<WallDef> placed;
  std::optional<WallDef> trapArea;  // the square an L spans: the trap stands alone, with nothing in it or near it
  if (r.next() % 2 == 0) {          // an L whose inside corner faces the start: the trap BUG must leave
    const Point2 c = Point2(r.uniform(5.5, 9.5), r.uniform(5.5, 9.5));
    const double s = r.uniform(1.2, 1.8);
    placed.push_back(polylineWall({c + Point2(-s, s), c + Point2(s, s), c + Point2(s, -s)}));
    trapArea = rectangleWall(Point2(c - Vec2(s, s)), Point2(c + Vec2(s, s)));
  }
  // A spur from the bottom wall (upright) or the left one, `along` from their corner.
  const auto spur = [](bool upright, double along, double reach, double thick) {
    return upright ? rectangleWall(Point2(along, 0), Point2(along + thick, reach)) : rectangleWall(Point2(0, along), Point2(reach, along + thick));
  };
  // Room for a wall follower between `o` and everything placed, and none near the trap.
  const auto standsApart = [&](const WallDef& o) {
    const auto clearOf = [&](const WallDef& p, double gap) { return gapBetween(o, p) > gap && gapBetween(p, o) > gap; };
    return std::all_of(placed.begin(), placed.end(), [&](const WallDef& p) { return clearOf(p, apart); }) &&
           (!trapArea || clearOf(*trapArea, kTrapClearance));
  };
  // Two spurs, from the left and the bottom wall beside the start, so that no blind drive along the
  // walls reaches the goal. Only there: a BUG that keeps the obstacle on its left and meets a spur
  // of a far wall on its way follows that wall away from the goal. They keep clear of the trap
  // (3.7 m from the walls at least) and of the way out towards the goal.
  for (const bool upright : {false, true}) {
    const double along = r.uniform(3.0, 3.6), reach = r.uniform(1.6, 2.1), thick = r.uniform(0.3, 0.6);
    placed.push_back(spur(upright, along, reach, thick));
  }
  const int count = 2 + r.integer(8, 14);
  for (int attempt = 0; static_cast<int>(placed.size()) < count && attempt < 500; ++attempt) {
    const Point2 c(r.uniform(2.0, 13.0), r.uniform(2.0, 13.0));
    WallDef o;
    if (r.next() % 3 == 0) {
      o = circleWall(c, r.uniform(0.2, 0.6));
    } else {
      const Vec2 half(r.uniform(0.25, 1.0), r.uniform(0.25, 1.0));
      o = rectangleWall(Point2(c - half), Point2(c + half));
    }
    // 2.5 m round the start: the way out between the spurs stays open.
    const bool clearOfEnds = distanceToWall(w.robots[0].start.position, o) > 2.5 && distanceToWall(w.points[0].position, o) > 1.0;
    if (clearOfEnds && standsApart(o)) placed.push_back(o);
  }
  // Two more spurs from those walls, further along, past the start's clear circle (a drive along a
  // wall could go round the first one's tip through that circle), and longer (one going round the
  // tips of both would drive among the obstacles). Drawn last, where they fit.
  for (const bool upright : {false, true}) {
    for (int attempt = 0; attempt < 200; ++attempt) {
      const double along = r.uniform(5.0, 12.5), reach = r.uniform(2.0, 3.2), thick = r.uniform(0.3, 0.6);
      if (const WallDef far = spur(upright, along, reach, thick); standsApart(far)) {
        placed.push_back(far);
        break;
      }
    }
  }
  w.walls = placed;
  return w;
}

WorldDef maze(Random& r, std::uint64_t seed) {
  const int cols = r.integer(5, 8), rows = r.integer(5, 8);
  constexpr double cell = 1.6;
  WorldDef w = base("Generated perfect maze of 1.6 m cells", {cols * cell, rows * cell}, seed, {cell / 2, cell / 2}, 0,
                    {(cols - 0.5) * cell, (rows - 0.5) * cell});
  // Depth-first carving: every cell joined to the others by exactly one way.
  std::vector<bool> seen(static_cast<std::size_t>(cols * rows), false), eastOpen(seen.size(), false), northOpen(seen.size(), false);
  std::vector<int> stack{0};
  seen[0] = true;
  while (!stack.empty()) {
    const int c = stack.back(), x = c % cols, y = c / cols;
    std::vector<int> next;
    if (x > 0 && !seen[c - 1]) next.push_back(c - 1);
    if (x + 1 < cols && !seen[c + 1]) next.push_back(c + 1);
    if (y > 0 && !seen[c - cols]) next.push_back(c - cols);
    if (y + 1 < rows && !seen[c + cols]) next.push_back(c + cols);
    if (next.empty()) {
      stack.pop_back();
      continue;
    }
    const int n = next[r.next() % next.size()];
    if (n == c + 1) eastOpen[c] = true;
    if (n == c - 1) eastOpen[n] = true;
    if (n == c + cols) northOpen[c] = true;
    if (n == c - cols) northOpen[n] = true;
    seen[n] = true;
    stack.push_back(n);
  }
  for (int y = 0; y < rows; ++y) {
    for (int x = 0; x < cols; ++x) {
      const int c = y * cols + x;
      if (x + 1 < cols && !eastOpen[c]) w.walls.push_back(segmentWall(Point2((x + 1) * cell, y * cell), Point2((x + 1) * cell, (y + 1) * cell)));
      if (y + 1 < rows && !northOpen[c]) w.walls.push_back(segmentWall(Point2(x * cell, (y + 1) * cell), Point2((x + 1) * cell, (y + 1) * cell)));
    }
  }
  return w;
}

WorldDef rooms(Random& r, std::uint64_t seed) {
  const double width = r.uniform(9, 12), height = r.uniform(7, 9);
  const double split = r.uniform(0.4, 0.6) * width, across = r.uniform(0.4, 0.6) * height;
  WorldDef w = base("Generated floor of rooms with doorways and furniture", {width, height}, seed, {1.0, 1.0}, 0, {width - 1.0, height - 1.0});
  // A wall down the middle and one across each half, each with a doorway of 1.2 to 1.6 m.
  const auto wallWithDoor = [&](const Point2& a, const Point2& b) {
    const double length = (b - a).norm(), door = r.uniform(1.2, 1.6), at = r.uniform(0.6, length - door - 0.6);
    const Vec2 u = (b - a) / length;
    w.walls.push_back(segmentWall(a, Point2(a + u * at)));
    w.walls.push_back(segmentWall(Point2(a + u * (at + door)), b));
  };
  wallWithDoor({split, 0}, {split, height});
  wallWithDoor({0, across}, {split, across});
  const double across2 = r.uniform(0.4, 0.6) * height;
  wallWithDoor({split, across2}, {width, across2});
  // Furniture: tables and pillars, more than the robot's diameter from each other and from walls.
  for (int attempt = 0, pieces = r.integer(4, 8); pieces > 0 && attempt < 300; ++attempt) {
    const Point2 c(r.uniform(0.8, width - 0.8), r.uniform(0.8, height - 0.8));
    const WallDef o = r.next() % 2 == 0 ? circleWall(c, r.uniform(0.15, 0.35))
                                        : rectangleWall(Point2(c - Vec2(0.4, 0.3)), Point2(c + Vec2(r.uniform(0.4, 0.8), 0.3)));
    bool clear = distanceToWall(w.robots[0].start.position, o) > 0.8 && distanceToWall(w.points[0].position, o) > 0.8;
    for (const WallDef& other : allWalls(w)) clear = clear && gapBetween(o, other) > 2 * kRadius + 0.1;
    if (clear) w.walls.push_back(o), --pieces;
  }
  return w;
}

WorldDef loop(Random& r, std::uint64_t seed) {
  const double width = r.uniform(10, 14), height = r.uniform(7, 10), corridor = r.uniform(1.2, 2.0);
  WorldDef w = base("Generated corridor loop round a block, with convex and concave corners", {width, height}, seed, {width / 2, corridor / 2}, 0,
                    {width / 2, height - corridor / 2});
  // The block, as a closed outline with a notch in its bottom side (its concave corners).
  const Point2 lo(corridor, corridor), hi(width - corridor, height - corridor);
  const double notchAt = r.uniform(lo.x() + 1.0, hi.x() - 2.5), notchWidth = r.uniform(0.8, 1.5), notchDepth = r.uniform(0.5, 1.2);
  w.walls.push_back(
      polylineWall({lo, Point2(notchAt, lo.y()), Point2(notchAt, lo.y() + notchDepth), Point2(notchAt + notchWidth, lo.y() + notchDepth),
                    Point2(notchAt + notchWidth, lo.y()), Point2(hi.x(), lo.y()), hi, Point2(lo.x(), hi.y())},
                   true));
  // Outer corners cut at 45 degrees on some sides: the corridor's convex corners become concave.
  if (r.next() % 2 == 0) w.walls.push_back(segmentWall({0, corridor * 0.6}, {corridor * 0.6, 0}));
  if (r.next() % 2 == 0) w.walls.push_back(segmentWall({width - corridor * 0.6, height}, {width, height - corridor * 0.6}));
  return w;
}

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3f", v);
  return buf;
}
std::string point(const Point2& p) { return "[" + number(p.x()) + ", " + number(p.y()) + "]"; }

}  // namespace

namespace {

constexpr WorldKind kKinds[] = {WorldKind::Obstacles, WorldKind::Maze,   WorldKind::Rooms,         WorldKind::Loop,         WorldKind::FurnishedRoom,
                                WorldKind::Outline,   WorldKind::Lounge, WorldKind::WarehouseKeys, WorldKind::WarehouseBox, WorldKind::Crossing};
constexpr const char* kNames[] = {"obstacles", "maze",   "rooms",          "loop",          "furnished_room",
                                  "outline",   "lounge", "warehouse_keys", "warehouse_box", "crossing"};
WorldDef (*const kMakers[])(Random&, std::uint64_t) = {obstacles, maze,   rooms,         loop,         furnishedRoom,
                                                       outline,   lounge, warehouseKeys, warehouseBox, crossing};

}  // namespace

std::optional<WorldKind> worldKind(std::string_view name) {
  for (WorldKind k : kKinds) {
    if (name == toString(k)) return k;
  }
  return std::nullopt;
}

const char* toString(WorldKind kind) { return kNames[static_cast<int>(kind)]; }

std::string worldKindNames() {
  std::string all;
  for (const char* name : kNames) all += (all.empty() ? "" : ", ") + std::string(name);
  return all;
}

Result<WorldDef> generateWorld(WorldKind kind, std::uint64_t seed) {
  // Each attempt its own stream; the first world that keeps the promises is the one.
  for (std::uint64_t attempt = 0; attempt < 100; ++attempt) {
    Random random(seed * 0x100000001b3ULL + attempt);
    WorldDef w = kMakers[static_cast<int>(kind)](random, seed);
    snap(w);
    if (keepsPromises(w) && checkWorld(w).ok()) return w;
  }
  return Status::failure(std::string("no ") + toString(kind) + " world keeping its promises was found for seed " + std::to_string(seed));
}

std::string toToml(const WorldDef& w) {
  std::string t = "# Made by frob world generate; the loader reads it back as it was made.\n";
  t += "description = \"" + w.description + "\"\nsize = " + point(w.size) + "\nenclosed = " + (w.enclosed ? "true" : "false") +
       "\nseed = " + std::to_string(w.seed) + "\n\n[points]\n";
  for (const Landmark& p : w.points) t += p.name + " = " + point(p.position) + "\n";
  for (const RobotDef& r : w.robots) {
    t += "\n[[robot]]\nname = \"" + r.name + "\"\nstart = " + point(r.start.position) + "\nheading_deg = " + number(r.start.heading * 180.0 / pi) +
         "\n";
    if (r.startSpread.knownPosition > 0 || r.startSpread.knownHeading > 0)
      t += "start_spread = { known_position = " + number(r.startSpread.knownPosition) +
           ", known_heading_deg = " + number(r.startSpread.knownHeading * 180.0 / pi) + " }\n";
    if (r.drive.startDelay > 0 || r.drive.maxSpeed != DriveDef{}.maxSpeed)
      t += "drive = { max_speed = " + number(r.drive.maxSpeed) + ", start_delay = " + number(r.drive.startDelay) + " }\n";
  }
  for (const KeyEventDef& k : w.keys) t += "\n[[key]]\ntime = " + number(k.time) + "\nkey = \"" + std::string(1, k.key) + "\"\n";
  for (const WallDef& wall : w.walls) {
    t += "\n[[wall]]\n";
    switch (wall.shape) {
      case WallShape::Segment:
        t += "from = " + point(wall.points[0]) + "\nto = " + point(wall.points[1]) + "\n";
        break;
      case WallShape::Rectangle:
        t += "rect = [" + point(wall.points[0]) + ", " + point(wall.points[1]) + "]\n";
        break;
      case WallShape::Circle:
        t += "circle = " + point(wall.points[0]) + "\nradius = " + number(wall.radius) + "\n";
        break;
      case WallShape::Polyline: {
        t += "polyline = [";
        for (std::size_t i = 0; i < wall.points.size(); ++i) t += (i ? ", " : "") + point(wall.points[i]);
        t += std::string("]\n") + (wall.closed ? "closed = true\n" : "");
        break;
      }
    }
  }
  return t;
}

}  // namespace frob::worlds
