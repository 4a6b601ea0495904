#include "frob/worlds/world_def.hpp"

#include "check.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace frob::worlds {

WallDef segmentWall(const Point2& a, const Point2& b) { return {.shape = WallShape::Segment, .points = {a, b}}; }

WallDef rectangleWall(const Point2& lo, const Point2& hi) { return {.shape = WallShape::Rectangle, .points = {lo, hi}}; }

WallDef circleWall(const Point2& centre, double radius) { return {.shape = WallShape::Circle, .points = {centre}, .radius = radius}; }

WallDef polylineWall(std::vector<Point2> vertices, bool closed) {
  return {.shape = WallShape::Polyline, .points = std::move(vertices), .closed = closed};
}

std::vector<double> sonarAngles(const SonarDef& s) {
  if (!s.angles.empty()) return s.angles;
  std::vector<double> a;
  for (int i = 0; i < s.count; ++i) a.push_back(wrapAngle(2.0 * pi * i / s.count));
  return a;
}

RobotSpec robotSpec(const RobotDef& r) {
  return {.radius = r.radius, .sonarAngles = sonarAngles(r.sonar), .sonarMinRange = r.sonar.minRange, .sonarMaxRange = r.sonar.maxRange};
}

std::optional<Point2> findPoint(const WorldDef& w, const std::string& name) {
  for (const auto& p : w.points)
    if (p.name == name) return p.position;
  return std::nullopt;
}

Status checkWorld(const WorldDef& w) { return detail::checkWorld(w, detail::SourceLines{}); }

Status checkRunnable(const WorldDef& w) {
  if (!w.robots.empty()) return {};
  return Status::failure(
      "the world has no robot to drive: add one, e.g. a [[robot]] table with start = [1, 1] "
      "(the world format: worlds/data/README.md)");
}

double distanceToWall(const Point2& p, const WallDef& wall) {
  double d = INFINITY;
  forEachEdge(
      wall, [&](const Point2& a, const Point2& b) { d = std::min(d, detail::distanceToSegment(p, a, b)); },
      [&](const Point2& lo, const Point2& hi) {
        const double dx = std::max({lo.x() - p.x(), 0.0, p.x() - hi.x()});
        const double dy = std::max({lo.y() - p.y(), 0.0, p.y() - hi.y()});
        d = std::hypot(dx, dy);
      },
      [&](const Point2& centre, double radius) { d = std::max(0.0, (p - centre).norm() - radius); });
  return d;
}

double rayToSegment(const Point2& o, const Vec2& d, const Point2& a, const Point2& b) {
  const Vec2 e = b - a, w = a - o;
  const double den = d.x() * e.y() - d.y() * e.x();
  if (std::abs(den) < 1e-12) return INFINITY;
  const double t = (w.x() * e.y() - w.y() * e.x()) / den, u = (w.x() * d.y() - w.y() * d.x()) / den;
  return t >= 0.0 && u >= 0.0 && u <= 1.0 ? t : INFINITY;
}

double rayToDisc(const Point2& o, const Vec2& d, const Point2& centre, double radius) {
  const Vec2 w = o - centre;
  const double b = w.dot(d), disc = b * b - (w.squaredNorm() - radius * radius);
  if (disc < 0.0 || -b + std::sqrt(disc) < 0.0) return INFINITY;
  return std::max(0.0, -b - std::sqrt(disc));
}

double rayToWall(const Point2& o, const Vec2& d, const WallDef& wall) {
  double best = INFINITY;
  const auto edge = [&](const Point2& a, const Point2& b) { best = std::min(best, rayToSegment(o, d, a, b)); };
  forEachEdge(
      wall, edge, [&](const Point2& lo, const Point2& hi) { forEachSide(lo, hi, edge); },
      [&](const Point2& centre, double radius) { best = std::min(best, rayToDisc(o, d, centre, radius)); });
  return best;
}

namespace detail {

std::string where(const SourceLines& at, int line) { return line > 0 ? at.file + ":" + std::to_string(line) + ": " : at.file + ": "; }

double distanceToSegment(const Point2& p, const Point2& a, const Point2& b) {
  const Vec2 ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return (a + t * ab - p).norm();
}

namespace {

constexpr double kMinLength = 1e-3;  // shorter walls are degenerate for Box2D
constexpr double kMaxSize = 1000.0;  // Box2D works in floats; keep coordinates modest
constexpr std::size_t kMaxRobots = 1000;

int lineAt(const std::vector<int>& lines, std::size_t i) { return i < lines.size() ? lines[i] : 0; }

std::string fmt(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

bool finite(const Point2& p) { return std::isfinite(p.x()) && std::isfinite(p.y()); }

// Empty if `wall` is well formed and inside the world, else what is wrong with which field.
Status checkWall(const WallDef& wall, const Vec2& size) {
  const auto& v = wall.points;
  const std::size_t need = wall.shape == WallShape::Circle ? 1 : 2;
  if (v.size() < need || (wall.shape != WallShape::Polyline && v.size() != need))
    return Status::failure("points: expected " + std::to_string(need) + (wall.shape == WallShape::Polyline ? " or more" : "") + " points, got " +
                           std::to_string(v.size()));
  for (const auto& p : v) {
    if (!finite(p)) return Status::failure("points: coordinates must be finite");
    if (p.x() < -1e-9 || p.y() < -1e-9 || p.x() > size.x() + 1e-9 || p.y() > size.y() + 1e-9)
      return Status::failure("points: (" + fmt(p.x()) + ", " + fmt(p.y()) + ") lies outside the world [0, " + fmt(size.x()) + "] x [0, " +
                             fmt(size.y()) + "]");
  }
  std::string error;
  std::size_t i = 0;  // the edge's first vertex
  forEachEdge(
      wall,
      [&](const Point2& a, const Point2& b) {
        const std::size_t k = i++;
        // The first fault only; a closed polyline's closing edge is not checked.
        if (!error.empty() || k + 1 >= v.size() || (b - a).norm() >= kMinLength) return;
        error = wall.shape == WallShape::Segment ? "to: the wall has (almost) zero length"
                                                 : "polyline: vertices " + std::to_string(k) + " and " + std::to_string(k + 1) + " coincide";
      },
      [&](const Point2& lo, const Point2& hi) {
        if (hi.x() - lo.x() < kMinLength || hi.y() - lo.y() < kMinLength)
          error = "rect: the max corner must exceed the min corner by at least 1 mm in x and y";
      },
      [&](const Point2& c, double radius) {
        if (!(radius >= kMinLength) || !std::isfinite(radius)) {
          error = "radius: must be at least 0.001 m";
        } else if (c.x() - radius < -1e-9 || c.y() - radius < -1e-9 || c.x() + radius > size.x() + 1e-9 || c.y() + radius > size.y() + 1e-9) {
          error = "radius: the pillar reaches outside the world";
        }
      });
  if (error.empty()) return {};
  return Status::failure(error);
}

Status checkRobot(const RobotDef& r) {
  auto bad = [](double v, double lo, double hi) { return !(v >= lo && v <= hi); };  // NaN is bad too
  if (bad(r.radius, 0.01, 5.0)) return Status::failure("radius: must lie in [0.01, 5] m");
  if (bad(r.density, 1e-3, 1e6)) return Status::failure("density: must lie in [0.001, 1e6] kg/m^2");
  if (r.bumpers < 1 || r.bumpers > 64) return Status::failure("bumpers: must lie in [1, 64]");
  const SonarDef& s = r.sonar;
  if (s.angles.empty() && (s.count < 0 || s.count > 64)) return Status::failure("sonar.count: must lie in [0, 64]");
  if (s.angles.size() > 64) return Status::failure("sonar.angles: at most 64 sonars");
  for (double a : s.angles)
    if (!std::isfinite(a)) return Status::failure("sonar.angles: must be finite");
  if (s.rays < 1 || s.rays > 64) return Status::failure("sonar.rays: must lie in [1, 64]");
  if (bad(s.cone, 0.0, pi)) return Status::failure("sonar.cone: must lie in [0, 180] degrees");
  if (bad(s.minRange, 0.0, 100.0)) return Status::failure("sonar.min_range: must lie in [0, 100] m");
  if (bad(s.maxRange, s.minRange, 100.0) || s.maxRange <= s.minRange)
    return Status::failure("sonar.max_range: must exceed min_range and be at most 100 m");
  if (bad(s.specularCutoff, 0.0, pi / 2)) return Status::failure("sonar.specular_cutoff: must lie in [0, 90] degrees");
  if (bad(s.noise, 0.0, 1.0)) return Status::failure("sonar.noise: must lie in [0, 1]");
  const OdometryDef& o = r.odometry;
  if (bad(o.translation, 0.0, 10.0)) return Status::failure("odometry.translation: must lie in [0, 10]");
  if (bad(o.heading, 0.0, 10.0)) return Status::failure("odometry.heading: must lie in [0, 10]");
  if (bad(o.turn, 0.0, 10.0)) return Status::failure("odometry.turn: must lie in [0, 10]");
  const DriveDef& d = r.drive;
  if (bad(d.maxSpeed, 0.0, 20.0)) return Status::failure("drive.max_speed: must lie in [0, 20] m/s");
  if (bad(d.maxTurnRate, 0.0, 50.0)) return Status::failure("drive.max_turn_rate: must lie in [0, 50] rad/s");
  if (bad(d.acceleration, 1e-6, 1e3)) return Status::failure("drive.acceleration: must lie in (0, 1000] m/s^2");
  if (bad(d.turnAcceleration, 1e-6, 1e4)) return Status::failure("drive.turn_acceleration: must lie in (0, 10000] rad/s^2");
  if (bad(d.slip, 0.0, 0.5)) return Status::failure("drive.slip: must lie in [0, 0.5]");
  if (bad(d.slipTime, 0.01, 1e4)) return Status::failure("drive.slip_time: must lie in [0.01, 10000] s");
  if (bad(d.startDelay, 0.0, 1e4)) return Status::failure("drive.start_delay: must lie in [0, 10000] s");
  if (bad(r.startSpread.position, 0.0, 1.0)) return Status::failure("start_spread.position: must lie in [0, 1] m");
  if (bad(r.startSpread.heading, 0.0, pi)) return Status::failure("start_spread.heading_deg: must lie in [0, 180] degrees");
  if (bad(r.startSpread.knownPosition, 0.0, 1.0)) return Status::failure("start_spread.known_position: must lie in [0, 1] m");
  if (bad(r.startSpread.knownHeading, 0.0, pi)) return Status::failure("start_spread.known_heading_deg: must lie in [0, 180] degrees");
  if (!finite(r.start.position) || !std::isfinite(r.start.heading)) return Status::failure("start: must be finite");
  return {};
}

}  // namespace

Status checkWorld(const WorldDef& w, const SourceLines& at) {
  if (!(w.size.x() > 0 && w.size.y() > 0 && w.size.x() <= kMaxSize && w.size.y() <= kMaxSize))
    return Status::failure(where(at, at.size) + "size: width and height must lie in (0, 1000] m, got [" + fmt(w.size.x()) + ", " + fmt(w.size.y()) +
                           "]");
  for (std::size_t i = 0; i < w.walls.size(); ++i)
    if (Status e = checkWall(w.walls[i], w.size); !e)
      return Status::failure(where(at, lineAt(at.walls, i)) + "wall[" + std::to_string(i) + "]." + e.error());
  for (std::size_t i = 0; i < w.points.size(); ++i) {
    const Point2& p = w.points[i].position;
    if (!finite(p) || p.x() < 0 || p.y() < 0 || p.x() > w.size.x() || p.y() > w.size.y())
      return Status::failure(where(at, lineAt(at.points, i)) + "points." + w.points[i].name + ": lies outside the world");
  }
  if (w.robots.size() > kMaxRobots) return Status::failure(where(at, 0) + "robot: at most 1000 robots");
  for (std::size_t i = 0; i < w.robots.size(); ++i) {
    const RobotDef& r = w.robots[i];
    const std::string field = where(at, lineAt(at.robots, i)) + "robot[" + std::to_string(i) + "].";
    if (Status e = checkRobot(r); !e) return Status::failure(field + e.error());
    const Point2& p = r.start.position;
    // Wherever the start spread puts it, the robot starts clear of everything.
    const double reach = r.radius + r.startSpread.reach();
    const std::string body = "the robot (radius " + fmt(r.radius) + " m, start_spread.position " + fmt(r.startSpread.position) + " m" +
                             (r.startSpread.knownPosition > 0 ? " and known_position " + fmt(r.startSpread.knownPosition) + " m)" : ")");
    if (p.x() - reach < 0 || p.y() - reach < 0 || p.x() + reach > w.size.x() || p.y() + reach > w.size.y())
      return Status::failure(field + "start: " + body + " may reach outside the world");
    for (std::size_t k = 0; k < w.walls.size(); ++k)
      if (distanceToWall(p, w.walls[k]) < reach)
        return Status::failure(field + "start: " + body + " may touch wall[" + std::to_string(k) +
                               "]; move it away or set start_spread.position = 0");
    for (std::size_t k = 0; k < i; ++k)
      if ((w.robots[k].start.position - p).norm() < w.robots[k].radius + w.robots[k].startSpread.reach() + reach)
        return Status::failure(field + "start: " + body + " may overlap robot[" + std::to_string(k) + "]");
  }
  for (std::size_t i = 0; i < w.keys.size(); ++i) {
    const KeyEventDef& k = w.keys[i];
    const std::string field = where(at, lineAt(at.keys, i)) + "key[" + std::to_string(i) + "].";
    if (!(k.time >= 0 && k.time < 1e7)) return Status::failure(field + "time: must lie in [0, 1e7) s");
    if (k.robot < -1 || k.robot >= static_cast<int>(w.robots.size()))
      return Status::failure(field + "robot: no robot with index " + std::to_string(k.robot));
  }
  return {};
}

}  // namespace detail
}  // namespace frob::worlds
