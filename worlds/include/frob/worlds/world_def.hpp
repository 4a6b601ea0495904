#pragma once
/// Definitions of a simulated world: plain structs with defaults, filled with designated initializers
/// in code or by the world-file loader (world_file.hpp). All lengths in metres, angles in radians.

#include "frob/base/result.hpp"
#include "frob/geometry.hpp"
#include "frob/robot_values.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace frob::worlds {

/// The shape of one wall.
enum class WallShape {
  Segment,    ///< points = {from, to}; a thin wall
  Polyline,   ///< points = vertices (>= 2), joined in order; closed joins the last to the first
  Rectangle,  ///< points = {min corner, max corner}; a solid axis-aligned block
  Circle,     ///< points = {centre}; radius; a solid round pillar
};

/// One static wall.
struct WallDef {
  WallShape shape = WallShape::Segment;  ///< which of the shapes below
  std::vector<Point2> points;            ///< meaning depends on shape (see WallShape)
  double radius = 0.0;                   ///< Circle radius, metres
  bool closed = false;                   ///< Polyline: also join the last vertex to the first
};

/// A thin wall from `a` to `b`.
[[nodiscard]] WallDef segmentWall(const Point2& a, const Point2& b);
/// A solid axis-aligned block between corners `lo` and `hi`.
[[nodiscard]] WallDef rectangleWall(const Point2& lo, const Point2& hi);
/// A solid round pillar.
[[nodiscard]] WallDef circleWall(const Point2& centre, double radius);
/// Thin walls joining `vertices` in order (and back to the first when `closed`).
[[nodiscard]] WallDef polylineWall(std::vector<Point2> vertices, bool closed = false);

/// The one walk over a wall's shape, shared by physics, sonar, distances, checks and drawing: each
/// thin edge as `edge(a, b)` (a segment's; a polyline's in order, then the closing one when closed),
/// a rectangle as `block(first, second)` (its corners as written; checkWorld makes the first the
/// minimum) and a circle as `disc(centre, radius)`. A wall with too few points gives nothing.
template <class Edge, class Block, class Disc>
void forEachEdge(const WallDef& wall, Edge&& edge, Block&& block, Disc&& disc) {
  const std::vector<Point2>& p = wall.points;
  switch (wall.shape) {
    case WallShape::Segment:
      if (p.size() >= 2) edge(p[0], p[1]);
      break;
    case WallShape::Polyline:
      for (std::size_t i = 0; i + 1 < p.size(); ++i) edge(p[i], p[i + 1]);
      if (wall.closed && p.size() >= 2) edge(p.back(), p.front());
      break;
    case WallShape::Rectangle:
      if (p.size() >= 2) block(p[0], p[1]);
      break;
    case WallShape::Circle:
      if (!p.empty()) disc(p[0], wall.radius);
      break;
  }
}

/// The four sides of the block between corners `lo` and `hi`, counter-clockwise from `lo`, as `edge(a, b)`.
template <class Edge>
void forEachSide(const Point2& lo, const Point2& hi, Edge&& edge) {
  const Point2 b(hi.x(), lo.y()), d(lo.x(), hi.y());
  edge(lo, b), edge(b, hi), edge(hi, d), edge(d, lo);
}

/// A named point of interest of a world (a goal, a landmark); drawn as a render::Marker.
struct Landmark {
  std::string name;                  ///< e.g. "goal"
  Point2 position = Point2::Zero();  ///< metres
};

/// A ring of sonars on a robot. Each sonar is a cone sampled by `rays` rays; it reads the nearest
/// echo among its rays. A ray meeting a surface further than `specularCutoff` from the surface
/// normal is reflected away and reads `maxRange`.
struct SonarDef {
  int count = 16;                             ///< sonars evenly spaced counter-clockwise from the front, unless `angles` is set
  std::vector<double> angles;                 ///< explicit directions relative to heading, radians; empty: evenly spaced
  double cone = 25.0 * pi / 180.0;            ///< full cone width, radians
  int rays = 5;                               ///< rays per cone, spread evenly across it (1: the axis only)
  double minRange = 0.15;                     ///< closest reading, metres
  double maxRange = 6.5;                      ///< reading when nothing echoes, metres
  double specularCutoff = 22.5 * pi / 180.0;  ///< largest angle from a surface normal that still echoes, radians
  double noise = 0.01;                        ///< Gaussian noise standard deviation as a fraction of the range
};

/// Dead-reckoning noise. Errors accumulate as random walks: after travelling d metres and turning
/// a radians, the along-track error has standard deviation translation*sqrt(d) metres and the
/// heading error sqrt(heading^2*d + turn^2*a) radians. The defaults drift as a Nomad's odometry
/// does on a good floor: after 10 m and a full turn, some 1.6 cm along and 0.34 degrees of heading.
/// All zero: odometry follows the true motion exactly.
struct OdometryDef {
  double translation = 0.005;  ///< along-track error, m per sqrt(m) travelled
  double heading = 0.001;      ///< heading drift, rad per sqrt(m) travelled
  double turn = 0.002;         ///< heading error, rad per sqrt(rad) turned
};

/// Synchro drive limits: commanded speeds are clamped, then approached at bounded acceleration.
/// The wheels slip: the speed and turn rate achieved differ from those commanded by a relative
/// error that wanders slowly (standard deviation `slip`, correlation time `slipTime`), drawn from
/// the seed, so a recorded sequence of commands does not retrace its path.
struct DriveDef {
  double maxSpeed = 0.6;          ///< m/s (Nomad 200: about 0.6)
  double maxTurnRate = 1.0;       ///< rad/s
  double acceleration = 1.0;      ///< m/s^2
  double turnAcceleration = 3.0;  ///< rad/s^2
  double slip = 0.03;             ///< relative error of the achieved speeds, standard deviation (0: none)
  double slipTime = 2.0;          ///< seconds over which the slip error changes
  double startDelay = 0.0;        ///< seconds from the start during which the wheels do not answer (a late start; 0: none)
};

/// Where a robot starts. Its odometry begins at its `start` moved by an offset drawn from the seed
/// within `knownPosition` metres and `knownHeading` radians (the robot knows it: a start drawn anew
/// in every run, handed-out and generated worlds alike), and it really starts within `position`
/// metres and `heading` radians of that, drawn too (the robot does not know this offset). All zero:
/// it starts exactly at `start`.
struct StartSpreadDef {
  double position = 0.02;           ///< metres, at most
  double heading = 0.5 * pi / 180;  ///< radians either way, at most
  double knownPosition = 0.0;       ///< metres, at most
  double knownHeading = 0.0;        ///< radians either way, at most
  /// How far from `start` the robot's body may begin, in metres.
  [[nodiscard]] double reach() const { return knownPosition + position; }
};

/// One robot: a disc (Nomad 200 style) with sonars, bumpers and odometry.
struct RobotDef {
  std::string name;            ///< may be empty; then "robot<i>"
  Pose2 start;                 ///< starting pose, as the robot believes it (see startSpread)
  StartSpreadDef startSpread;  ///< how far the known and the true start may lie from `start`
  double radius = 0.23;        ///< body radius, metres
  double density = 50.0;       ///< kg/m^2 (only matters when robots push each other)
  int bumpers = 8;             ///< bumper sectors around the body, counter-clockwise from the front
  SonarDef sonar;              ///< sonar ring
  OdometryDef odometry;        ///< dead-reckoning noise
  DriveDef drive;              ///< speed and acceleration limits
};

/// A scripted key press, delivered in the sensor frame of the first step at or after `time`.
struct KeyEventDef {
  double time = 0.0;  ///< seconds of logical time
  char key = ' ';     ///< the key
  int robot = -1;     ///< robot index, or -1 for every robot
};

/// A whole world. The world spans [0, size.x] x [0, size.y]; everything lies inside it.
struct WorldDef {
  std::string description;        ///< one line for people, may be empty
  Vec2 size{10.0, 10.0};          ///< metres
  bool enclosed = true;           ///< put thin walls along the four sides
  std::vector<WallDef> walls;     ///< static walls (bitmap and mesh maps are already expanded here)
  std::vector<Landmark> points;   ///< goals and landmarks
  std::vector<RobotDef> robots;   ///< at least one for a useful run
  std::vector<KeyEventDef> keys;  ///< scripted keyboard
  std::uint64_t seed = 1;         ///< the one seed every random stream derives from
};

/// The fixed spec a controller may know about robot `r`: radius and sonar directions and ranges.
[[nodiscard]] RobotSpec robotSpec(const RobotDef& r);
/// Sonar directions of `s` relative to heading, radians (explicit `angles`, or `count` evenly spaced).
[[nodiscard]] std::vector<double> sonarAngles(const SonarDef& s);
/// Distance from `p` to the nearest point of `wall`, metres (0 inside a solid wall).
[[nodiscard]] double distanceToWall(const Point2& p, const WallDef& wall);
/// How far the ray from `o` along the unit vector `d` goes before it meets the segment a-b; INFINITY when it misses.
[[nodiscard]] double rayToSegment(const Point2& o, const Vec2& d, const Point2& a, const Point2& b);
/// How far the ray from `o` along the unit vector `d` goes before it meets the disc (0 from inside it); INFINITY when it misses.
[[nodiscard]] double rayToDisc(const Point2& o, const Vec2& d, const Point2& centre, double radius);
/// How far the ray from `o` along the unit vector `d` goes before it meets `wall`; INFINITY when it misses.
[[nodiscard]] double rayToWall(const Point2& o, const Vec2& d, const WallDef& wall);
/// The named point `name`, if the world has one.
[[nodiscard]] std::optional<Point2> findPoint(const WorldDef& w, const std::string& name);
/// Checks a world built in code for contradictions (robot inside a wall, outside the world, bad
/// sizes). Fails with a readable message naming the field.
[[nodiscard]] Status checkWorld(const WorldDef& w);
/// Checks that `w` has something to run: at least one robot; else fails with a message that says
/// how to add one. A world with no robot is fine to draw, not to run or grade.
[[nodiscard]] Status checkRunnable(const WorldDef& w);

}  // namespace frob::worlds
