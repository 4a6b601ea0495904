#pragma once
/// FrameScene: a plain view model of one instant of a run, all the renderer needs to draw it.

#include "frob/geometry.hpp"
#include "frob/picture.hpp"
#include "frob/robot_values.hpp"

#include <optional>
#include <string>
#include <vector>

namespace frob::render {

/// An axis-aligned rectangle of the world, metres.
struct Bounds {
  Point2 min = Point2(0, 0);  ///< lower-left corner
  Point2 max = Point2(1, 1);  ///< upper-right corner
};

/// A wall drawn as a thick segment.
struct Wall {
  Point2 a = Point2::Zero();  ///< one end, metres
  Point2 b = Point2::Zero();  ///< other end, metres
  double thickness = 0.05;    ///< metres
};

/// A solid rectangular obstacle (a box).
struct Block {
  Point2 center = Point2::Zero();     ///< metres
  Vec2 halfExtents = Vec2(0.5, 0.5);  ///< half width and half height before rotation, metres
  double angle = 0.0;                 ///< rotation, radians counter-clockwise
};

/// A solid round obstacle (a pillar).
struct Pillar {
  Point2 center = Point2::Zero();  ///< metres
  double radius = 0.1;             ///< metres
};

/// A labelled point drawn in a scene (a goal, a waypoint); a world's come from its worlds::Landmark list.
struct Marker {
  std::string name;            ///< label drawn beside it; may be empty
  Point2 at = Point2::Zero();  ///< metres
  std::optional<Color> color;  ///< unset: the renderer's default
};

/// One robot at this instant, with what it has done so far.
struct RobotView {
  std::string name;                  ///< shown in the HUD; may be empty
  Pose2 pose;                        ///< true pose
  std::optional<Pose2> odometry;     ///< pose as the robot believes it; unset: not drawn
  RobotSpec spec;                    ///< body radius and sonar directions
  std::vector<double> sonar;         ///< one reading per spec.sonarAngles entry, metres; may be empty
  std::vector<BumperHit> bumps;      ///< bumper contacts this step
  std::vector<Point2> path;          ///< true positions so far, oldest first
  std::vector<Point2> odometryPath;  ///< believed positions so far, oldest first
  Picture picture;                   ///< what its current task publishes (withPicture), world coordinates
  std::string task;                  ///< name of its current task; may be empty
  Wheels wheels;                     ///< its wheel command this step
  std::optional<Color> color;        ///< unset: picked from a palette by robot index
};

/// Everything drawn for one frame.
struct FrameScene {
  double time = 0.0;              ///< simulated time, seconds
  Bounds bounds;                  ///< the world's extent; the camera fits it
  std::vector<Wall> walls;        ///< wall segments
  std::vector<Block> blocks;      ///< filled rectangular obstacles
  std::vector<Pillar> pillars;    ///< filled round obstacles
  std::vector<Marker> points;     ///< labelled points
  std::vector<RobotView> robots;  ///< robots, drawn in order
  std::string note;               ///< a line under the time in the HUD (e.g. that the run is settling); may be empty
};

/// The index of the sonar whose direction is closest to straight ahead, or -1 if there is none.
[[nodiscard]] int frontSonarIndex(const RobotSpec& spec);

}  // namespace frob::render
