// The assignments' families of hidden worlds: each keeps what its handout promises (the layout a
// controller may rely on) and draws the rest (furniture, corners, keys, boxes, starts).
#include "generate_kit.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

namespace frob::worlds::kit {

namespace {

using Piece = std::vector<WallDef>;  // one piece of furniture: its walls, placed together

constexpr double kPassage = 0.8;      // between furniture and anything else: room for the body and a margin
constexpr double kBlockDepth = 0.05;  // how far into a pillar a body on a way blocked by it runs, at least

// The nearest gap between `piece` and any of `walls`.
double gapTo(const Piece& piece, const std::vector<WallDef>& walls) {
  double d = INFINITY;
  for (const WallDef& a : piece) {
    for (const WallDef& b : walls) d = std::min(d, gap(a, b));
  }
  return d;
}

// Every gap between `piece` and the walls of `w` wide enough to pass, or closed where it stands
// against the outer walls (a counter along a wall).
bool standsClear(const Piece& piece, const WorldDef& w) {
  const std::vector<WallDef> walls = allWalls(w);
  for (const WallDef& a : piece) {
    for (std::size_t i = 0; i < walls.size(); ++i) {
      const double g = gap(a, walls[i]);
      if (g < kPassage && !(g < 1e-9 && i >= w.walls.size())) return false;
    }
  }
  return true;
}

double distanceTo(const Point2& p, const Piece& piece) {
  double d = INFINITY;
  for (const WallDef& w : piece) d = std::min(d, distanceToWall(p, w));
  return d;
}

// The nearest the segment a-b comes to `piece` (0 when it crosses it), sampled every 2 cm.
double segmentDistance(const Point2& a, const Point2& b, const Piece& piece) {
  const int n = std::max(1, static_cast<int>((b - a).norm() / 0.02));
  double d = INFINITY;
  for (int i = 0; i <= n; ++i) d = std::min(d, distanceTo(a + (b - a) * (static_cast<double>(i) / n), piece));
  return d;
}

// A table from `lo` to `hi` with round legs at its corners that stand free of `walls` (so that the
// sonars, which hear only surfaces they face, hear it from every side).
Piece tableWithLegs(const Point2& lo, const Point2& hi, const std::vector<WallDef>& walls) {
  Piece p{rectangleWall(lo, hi)};
  for (const Point2& c : {lo, Point2(hi.x(), lo.y()), hi, Point2(lo.x(), hi.y())}) {
    const bool againstAWall = std::any_of(walls.begin(), walls.end(), [&](const WallDef& w) { return distanceToWall(c, w) < 1e-9; });
    if (!againstAWall) p.push_back(circleWall(c, 0.1));
  }
  return p;
}

void add(WorldDef& w, const Piece& piece) { w.walls.insert(w.walls.end(), piece.begin(), piece.end()); }

// A shape of furniture round `c`: a round table or pillar, or a block with legs.
Piece furniture(Random& r, const Point2& c, const std::vector<WallDef>& walls) {
  if (r.coin()) return {circleWall(c, r.uniform(0.3, 0.55))};
  const Vec2 half(r.uniform(0.3, 0.8), r.uniform(0.3, 0.8));
  return tableWithLegs(Point2(c - half), Point2(c + half), walls);
}

}  // namespace

WorldDef furnishedRoom(Random& r, std::uint64_t seed) {
  const double width = r.uniform(5.5, 7.5), depth = r.uniform(4.5, 6.5), hall = 2.0, door = r.uniform(1.0, 1.2);
  const double doorAt = r.uniform(1.5, width - 1.5 - door), doorMid = doorAt + door / 2;
  WorldDef w = base("Generated furnished room, entered from a hall on its south side", {width, depth + hall}, seed, {doorMid, 0.65}, 90);
  knownSpread(w, 0.15, 10);
  // The house beside the hall (solid), and round door posts.
  w.walls = {rectangleWall({0, 0}, {doorAt, hall}), rectangleWall({doorAt + door, 0}, {width, hall}), circleWall({doorAt, hall}, 0.1),
             circleWall({doorAt + door, hall}, 0.1)};
  const Point2 room(doorMid, hall + 1.0);
  w.points.push_back({"room", room});
  // Counters against the north wall, and tables, pillars and round tables standing free: every gap
  // either closed or wide enough to pass, nothing in the doorway.
  for (int attempt = 0, pieces = r.integer(2, 5); pieces > 0 && attempt < 400; ++attempt) {
    const std::vector<WallDef> walls = allWalls(w);
    Piece p;
    if (r.integer(0, 3) == 0) {
      const double length = r.uniform(1.5, 3.0), d = r.uniform(0.5, 0.6);
      const double at = r.coin() ? 0.0 : r.coin() ? width - length : r.uniform(0.8, width - length - 0.8);
      p = tableWithLegs({at, hall + depth - d}, {at + length, hall + depth}, walls);
    } else {
      p = furniture(r, {r.uniform(0.8, width - 0.8), r.uniform(hall + 0.8, hall + depth - 0.8)}, walls);
    }
    if (standsClear(p, w) && distanceTo(room, p) > 1.2 && distanceTo({doorMid, hall}, p) > 1.6) add(w, p), --pieces;
  }
  return w;
}

WorldDef outline(Random& r, std::uint64_t seed) {
  const double width = r.uniform(6.0, 7.5), height = r.uniform(5.0, 6.0), margin = 0.5;
  const Point2 o(margin, margin);
  WorldDef w = base("Generated room with pillars against its walls, to follow with the wall on the right", {width + 2 * margin, height + 2 * margin},
                    seed, o + Vec2(r.uniform(1.2, 1.8), 0.83), 0);
  knownSpread(w, 0.05, 8);
  w.enclosed = false;
  // The outline counter-clockwise from its south-west corner (the robot goes round it that way with
  // the wall on its right); a pillar against the east, north or west side (two concave corners and
  // two convex ones), 2 m or more from the room's corners, so that the corners come one at a time.
  struct Side {
    Point2 from;
    Vec2 along;
    double length;
  };
  const std::array<Side, 3> sides = {Side{o + Vec2(width, 0), Vec2(0, 1), height}, Side{o + Vec2(width, height), Vec2(-1, 0), width},
                                     Side{o + Vec2(0, height), Vec2(0, -1), height}};
  std::vector<Point2> v{o};
  int pillars = 0;
  for (std::size_t k = 0; k < sides.size(); ++k) {
    const Side& s = sides[k];
    v.push_back(s.from);
    if (r.uniform(0, 1) > 0.7 && !(k == 2 && pillars == 0)) continue;
    const double across = r.uniform(1.0, 1.4), deep = r.uniform(0.8, 1.2);
    if (s.length < across + 4.0) continue;
    const Vec2 in(-s.along.y(), s.along.x());  // left of the way round: into the room
    const Point2 a = s.from + s.along * r.uniform(2.0, s.length - across - 2.0), b = a + s.along * across;
    v.insert(v.end(), {a, Point2(a + in * deep), Point2(b + in * deep), b});
    ++pillars;
  }
  w.walls.push_back(polylineWall(v, true));
  // Points on the path 40 cm from the wall (the rim's; 63 cm for the centre), in the order the robot
  // passes them: the middle of long sides after the start, then the start's side again.
  std::vector<Point2> along;
  for (std::size_t i = 1; i < v.size(); ++i) {
    const Point2 a = v[i], b = v[(i + 1) % v.size()];
    const Vec2 u = (b - a) / (b - a).norm();
    if ((b - a).norm() >= 1.8) along.push_back((a + b) / 2 + Vec2(-u.y(), u.x()) * 0.63);
  }
  if (along.size() < 5) return {};  // a world with no robot keeps no promise: another is drawn
  const char* names[] = {"a", "b", "c", "d", "e"};
  for (int j = 0; j < 5; ++j) w.points.push_back({names[j], along[static_cast<std::size_t>(std::lround(j * (along.size() - 1) / 4.0))]});
  w.points.push_back({"f", Point2(w.robots[0].start.position.x() + 1.5, o.y() + 0.63)});
  return w;
}

WorldDef lounge(Random& r, std::uint64_t seed) {
  const std::array<Point2, 4> wp = {Point2(3.0, 2.5), Point2(3.5, 7.5), Point2(9.0, 7.0), Point2(8.5, 2.5)};
  WorldDef w = base("Generated lounge: the handout's four waypoints, furniture drawn on the way between them", {12, 10}, seed, {1.5, 1.5}, 0);
  knownSpread(w, 0.25, 20);
  for (std::size_t k = 0; k < wp.size(); ++k) w.points.push_back({"wp" + std::to_string(k + 1), wp[k]});
  const Point2 start = w.robots[0].start.position;
  const auto fits = [&](const Piece& p) {
    if (gapTo(p, allWalls(w)) < 1.0) return false;
    return distanceTo(start, p) >= 0.9 && std::all_of(wp.begin(), wp.end(), [&](const Point2& q) { return distanceTo(q, p) >= 0.9; });
  };
  // One piece across each leg between waypoints, off the straight line's middle: BUG2 must go round it.
  for (std::size_t k = 0; k + 1 < wp.size(); ++k) {
    const Vec2 u = (wp[k + 1] - wp[k]).normalized();
    for (int attempt = 0; attempt < 100; ++attempt) {
      const Point2 c = wp[k] + (wp[k + 1] - wp[k]) * r.uniform(0.35, 0.65) + Vec2(-u.y(), u.x()) * r.uniform(-0.25, 0.25);
      const Piece p = furniture(r, c, allWalls(w));
      if (segmentDistance(wp[k], wp[k + 1], p) == 0 && fits(p)) {
        add(w, p);
        break;
      }
    }
  }
  // Shelves and cabinets against any wall, anywhere along it, up to 1.6 m deep, and pieces standing
  // anywhere else: no line through the room and no way along its walls is kept clear, so no route
  // fixed in advance passes all lounges (a way round every piece remains: keepsPromises).
  const auto clearOfTheWay = [&](const Piece& p) {
    return distanceTo(start, p) >= 0.9 && std::all_of(wp.begin(), wp.end(), [&](const Point2& q) { return distanceTo(q, p) >= 0.8; });
  };
  for (int attempt = 0, more = r.integer(3, 4); more > 0 && attempt < 200; ++attempt) {
    const double length = r.uniform(1.0, 3.0), deep = r.uniform(0.4, 1.6);
    const bool alongX = r.coin(), low = r.coin();
    const double at = alongX ? r.uniform(0, 12 - length) : r.uniform(0, 10 - length);
    const Piece p{alongX ? rectangleWall({at, low ? 0.0 : 10 - deep}, {at + length, low ? deep : 10.0})
                         : rectangleWall({low ? 0.0 : 12 - deep, at}, {low ? deep : 12.0, at + length})};
    if (gapTo(p, w.walls) >= 1.0 && clearOfTheWay(p)) add(w, p), --more;
  }
  for (int attempt = 0, more = r.integer(2, 3); more > 0 && attempt < 200; ++attempt) {
    const Piece p = furniture(r, {r.uniform(0.6, 11.4), r.uniform(0.6, 9.4)}, allWalls(w));
    if (standsClear(p, w) && clearOfTheWay(p)) add(w, p), --more;
  }
  return w;
}

namespace {

// The warehouse of the parallel assignment: the patrol p1 to p4 round a block of shelves, with a
// shelf along the north wall; the block's size and the start are drawn.
WorldDef warehouse(Random& r, std::uint64_t seed, const char* what) {
  WorldDef w = base(what, {8, 6}, seed, {1.0, 1.0}, 0);
  knownSpread(w, 0.2, 20);
  w.points = {{"p1", {1.5, 1.5}}, {"p2", {6.5, 1.5}}, {"p3", {6.5, 4.5}}, {"p4", {1.5, 4.5}}};
  w.walls.push_back(rectangleWall({r.uniform(2.3, 2.7), r.uniform(2.4, 2.6)}, {r.uniform(5.3, 5.7), r.uniform(3.4, 3.6)}));
  const double shelf = r.uniform(1.8, 2.2);
  w.walls.push_back(rectangleWall({shelf, r.uniform(5.4, 5.6)}, {shelf + r.uniform(3.5, 4.2), 6.0}));
  return w;
}

}  // namespace

WorldDef warehouseKeys(Random& r, std::uint64_t seed) {
  WorldDef w = warehouse(r, seed, "Generated warehouse patrol: other keys are pressed, then s");
  const double stop = r.uniform(16, 24);
  const std::string others = "abcdefghijklmnopqrtuvwxyz";
  for (int k = 0, n = r.integer(1, 3); k < n; ++k) {
    w.keys.push_back({.time = r.uniform(1, stop - 1), .key = others[r.next() % others.size()]});
  }
  // And a burst of 1 to 4 just before s, each 0.5 to 3 s after the one before, s 0.5 to 3 s after
  // the last: neither a set time nor the keys' count or spacing tells s from the others.
  double at = stop;
  for (int k = 0, n = r.integer(1, 4); k < n; ++k) {
    at -= r.uniform(0.5, 3.0);
    w.keys.push_back({.time = at, .key = others[r.next() % others.size()]});
  }
  w.keys.push_back({.time = stop, .key = 's'});
  std::sort(w.keys.begin(), w.keys.end(), [](const KeyEventDef& a, const KeyEventDef& b) { return a.time < b.time; });
  return w;
}

WorldDef warehouseBox(Random& r, std::uint64_t seed) {
  WorldDef w = warehouse(r, seed, "Generated warehouse patrol: a box left in an aisle, on the patrol's way");
  const std::array<Point2, 4> route = {Point2(1.5, 1.5), Point2(6.5, 1.5), Point2(6.5, 4.5), Point2(1.5, 4.5)};
  const std::size_t leg = static_cast<std::size_t>(r.integer(0, 2));  // met before 35 s: p4 to p1 would come too late
  const Point2 a = route[leg], b = route[leg + 1];
  const Vec2 u = (b - a).normalized();
  for (int attempt = 0; attempt < 100; ++attempt) {
    const Point2 c = a + (b - a) * r.uniform(0.3, 0.7) + Vec2(-u.y(), u.x()) * r.uniform(-0.2, 0.2);
    const Vec2 half(r.uniform(0.2, 0.35), r.uniform(0.2, 0.35));
    const WallDef box = rectangleWall(Point2(c - half), Point2(c + half));
    const bool clear =
        gapTo({box}, allWalls(w)) > 0.3 && std::all_of(route.begin(), route.end(), [&](const Point2& p) { return distanceToWall(p, box) > 0.8; });
    if (clear) {
      w.walls.push_back(box);
      break;
    }
  }
  return w;
}

WorldDef crossing(Random& r, std::uint64_t seed) {
  WorldDef w{
      .description = "Generated crossing: robots to the points opposite their starts through the centre (5, 5)", .size = {10, 10}, .seed = seed};
  const Point2 centre(5, 5);
  w.points.push_back({"centre", centre});
  const char* names[] = {"ada", "bob", "cy", "dee"};
  std::vector<Point2> starts, goals;
  std::vector<double> angles;
  for (int i = 0, n = r.integer(2, 4), attempt = 0; i < n && attempt < 400; ++attempt) {
    // Now and then face to face with one already placed, on its way (as in a swap); else anywhere.
    const double angle = !angles.empty() && r.integer(0, 2) == 0 ? angles[r.next() % angles.size()] + pi : r.uniform(-pi, pi);
    // From 2 to 4 m out: robots reach the middle up to 4 s apart, so no one clock (a roundabout in lock-step) keeps them apart.
    const double radius = r.uniform(2.0, 4.0);
    const Point2 start(mm(centre.x() + std::cos(angle) * radius), mm(centre.y() + std::sin(angle) * radius)), goal = centre + (centre - start);
    // Bodies apart at the start; goals 2 m apart, so that a robot parked at its goal is not in another's way; and ways
    // that are one line (face to face) or cross at 60 degrees or more, so that no two robots drive side by side.
    const auto between = [](double a, double b) {
      const double d = std::fmod(std::abs(a - b), pi);
      return std::min(d, pi - d);
    };
    const bool apart = std::all_of(starts.begin(), starts.end(), [&](const Point2& p) { return (p - start).norm() > 1.2; }) &&
                       std::all_of(goals.begin(), goals.end(), [&](const Point2& p) { return (p - goal).norm() > 2.0; }) &&
                       std::all_of(angles.begin(), angles.end(), [&](double a) { return between(a, angle) < 0.05 || between(a, angle) >= pi / 3; });
    if (!apart) continue;
    starts.push_back(start), goals.push_back(goal), angles.push_back(angle);
    // Each robot's wheels answer after a delay of its own, up to 4 s, and reach a top speed of its own:
    // one clock for all predicts no one.
    w.robots.push_back({.name = names[i],
                        .start = {.position = start, .heading = r.integer(-3, 4) * pi / 4},  // as the handed-out worlds face
                        .drive = {.maxSpeed = r.uniform(0.4, 0.6), .startDelay = r.uniform(0.0, 4.0)}});
    w.points.push_back({std::string("goal_") + names[i], goal});
    ++i;
  }
  // Round pillars (heard from every side) at drawn places round the middle, the centre included,
  // 1.5 m or more apart and 1 m or more from the walls, leaving room round every start and goal: no
  // way fixed in advance (a lane beside the straight way, a roundabout) stays clear in most
  // crossings, and a robot that looks out goes round them.
  for (int attempt = 0, more = r.integer(4, 6); more > 0 && attempt < 400; ++attempt) {
    const double angle = r.uniform(-pi, pi), out = r.uniform(0.0, 3.8);
    const WallDef p = circleWall(centre + out * Vec2(std::cos(angle), std::sin(angle)), r.uniform(0.2, 0.4));
    const auto roomy = [&](const Point2& q) { return distanceToWall(q, p) >= 0.9; };
    const bool apart = gapTo({p}, w.walls) >= 1.5 && gapTo({p}, allWalls(w)) >= 1.0;
    if (apart && std::all_of(starts.begin(), starts.end(), roomy) && std::all_of(goals.begin(), goals.end(), roomy)) w.walls.push_back(p), --more;
  }
  // Every circle round the centre of 1 to 3 m (a roundabout) runs into a pillar, a body 5 cm deep
  // at least: a world whose pillars leave one clear keeps no promise, and another is drawn.
  for (double radius = 1.0; radius <= 3.0; radius += 0.01) {
    const bool blocked = std::any_of(w.walls.begin(), w.walls.end(), [&](const WallDef& p) {
      return std::abs((p.points[0] - centre).norm() - radius) < p.radius + kRadius - kBlockDepth;
    });
    if (!blocked) return {};
  }
  knownSpread(w, 0.1, 10);
  return w;
}

}  // namespace frob::worlds::kit
