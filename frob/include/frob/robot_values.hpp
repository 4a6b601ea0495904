#pragma once
/// Plain values a robot exchanges with its controller: wheel commands, poses, bumper hits.

#include "frob/geometry.hpp"

#include <string>
#include <vector>

namespace frob {

/// What a controller drives: forward speed (m/s) and turn rate (rad/s, counter-clockwise positive).
struct Wheels {
  double forward = 0.0;  ///< forward speed, m/s
  double turn = 0.0;     ///< turn rate, rad/s
  friend bool operator==(const Wheels&, const Wheels&) = default;
};

/// A position and heading in the world plane.
struct Pose2 {
  Point2 position = Point2::Zero();  ///< metres
  double heading = 0.0;              ///< radians from the x axis, counter-clockwise
  friend bool operator==(const Pose2& a, const Pose2& b) { return a.position == b.position && a.heading == b.heading; }
};

/// One bumper contact: which bumper and where on the body it was struck.
struct BumperHit {
  int bumper = 0;      ///< index of the bumper, counter-clockwise from the front
  double angle = 0.0;  ///< contact direction relative to the robot's heading, radians in (-pi, pi]
  friend bool operator==(const BumperHit&, const BumperHit&) = default;
};

/// The fixed shape of one robot's body and sensors, as a controller may know it.
struct RobotSpec {
  double radius = 0.23;             ///< body radius, metres (Nomad 200)
  std::vector<double> sonarAngles;  ///< sonar directions relative to the heading, radians
  double sonarMinRange = 0.15;      ///< closest reading a sonar gives, metres
  double sonarMaxRange = 6.5;       ///< reading when nothing echoes, metres
};

/// Everything a robot's sensors report at one instant. The simulator (or a real robot's driver)
/// fills one per robot each step, before the controller samples it.
struct SensorFrame {
  std::vector<double> sonar;     ///< one range per sonar of RobotSpec::sonarAngles, metres
  Pose2 odometry;                ///< pose as the robot believes it (dead reckoning)
  double velocity = 0.0;         ///< measured forward speed, m/s
  double turnRate = 0.0;         ///< measured turn rate, rad/s
  std::vector<BumperHit> bumps;  ///< bumper contacts that began this step
  std::vector<char> keys;        ///< keys pressed this step
};

/// Readable forms for traces and messages.
[[nodiscard]] std::string toString(const Wheels& w);
[[nodiscard]] std::string toString(const Pose2& p);

}  // namespace frob
