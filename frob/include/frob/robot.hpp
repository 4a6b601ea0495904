#pragma once
/// The sensor side of one robot, as behaviors and events. A controller sees only this.

#include "frob/debug.hpp"
#include "frob/detail/call_site.hpp"
#include "frob/detail/robot.hpp"
#include "frob/event.hpp"
#include "frob/robot_values.hpp"

#include <cstdint>
#include <functional>
#include <memory>
#include <source_location>
#include <vector>

namespace frob {

/// Gives the sensor readings at an instant. A simulator returns the frame it refreshed this step;
/// a real robot's driver would return its latest readings; tests compute them from time.
using FrameSource = std::function<const SensorFrame&(const Instant&)>;

/// Sensors given as plain functions of time (seconds), for testing without a simulator.
struct ScriptedSensors {
  std::function<double(double t, int sonar)> sonar = [](double, int) { return 6.5; };
  std::function<Pose2(double t)> odometry = [](double) { return Pose2{}; };
  std::function<double(double t)> velocity = [](double) { return 0.0; };
  std::function<std::vector<BumperHit>(double t)> bumps = [](double) { return std::vector<BumperHit>{}; };
  std::function<std::vector<char>(double t)> keys = [](double) { return std::vector<char>{}; };
};

/// A sensor reading: a behavior read straight from the robot's frame of the instant, which is
/// fetched once per instant however many readings use it. Converts to Behavior<T>.
template <class T>
using Reading = Pointwise<T, detail::FrameField<T>, detail::FrameArg>;

/// A ring of `count` sonars evenly spaced counter-clockwise from the front (16 on a Nomad 200).
[[nodiscard]] RobotSpec nomadSpec(int count = 16);

/// One robot's sensors. Cheap to copy; copies share the same sensor behaviors, which are read once
/// per instant however many parts of a controller use them.
class Robot {
 public:
  /// A robot of shape `spec` whose sensors read the frames `source` gives.
  Robot(RobotSpec spec, FrameSource source);
  /// A robot whose sensors read `frame`, which its owner (a simulator, a robot's driver) refreshes
  /// in place before each step; cheaper than a FrameSource, which is called at every instant.
  Robot(RobotSpec spec, std::shared_ptr<const SensorFrame> frame);
  /// A robot whose sensors follow `sensors` as functions of time.
  Robot(RobotSpec spec, ScriptedSensors sensors);

  /// Body radius and sonar layout.
  [[nodiscard]] const RobotSpec& spec() const;
  /// Range of sonar `i` (0 = front, counter-clockwise), metres. An index outside the ring is a
  /// mistake: UsageError naming the index, the ring's size and the caller's file and line.
  [[nodiscard]] Reading<double> sonar(int i, std::source_location loc = detail::callSite()) const;
  /// All sonar ranges, metres.
  [[nodiscard]] Behavior<std::vector<double>> sonars() const;
  /// The index of the sonar pointing nearest to `angle` (radians from the heading).
  [[nodiscard]] int sonarNearest(double angle) const;
  /// Position as the robot believes it (odometry), metres.
  [[nodiscard]] Reading<Point2> place() const;
  /// Heading as the robot believes it, radians.
  [[nodiscard]] Reading<double> orientation() const;
  /// Measured forward speed, m/s.
  [[nodiscard]] Reading<double> velocity() const;
  /// Bumper contacts as they begin.
  [[nodiscard]] Event<BumperHit> bumper() const;
  /// Key presses (scripted in headless runs).
  [[nodiscard]] Event<char> keyboard() const;
  /// Where this robot's tasks publish pictures and their timeline (shared by all copies).
  [[nodiscard]] const std::shared_ptr<DebugChannel>& debugChannel() const { return debug_; }

 private:
  Robot(RobotSpec spec, detail::NodeRef<detail::BehaviorNode<const SensorFrame*>> frameNode, bool inPlace);
  struct Sensors;
  std::shared_ptr<const Sensors> sensors_;
  std::shared_ptr<DebugChannel> debug_ = std::make_shared<DebugChannel>();
};

/// The paper's sensor functions, in C++.
[[nodiscard]] inline Reading<double> sonar(const Robot& r, int i, std::source_location loc = detail::callSite()) { return r.sonar(i, loc); }
[[nodiscard]] inline Behavior<std::vector<double>> sonars(const Robot& r) { return r.sonars(); }
[[nodiscard]] Reading<double> frontSonar(const Robot& r);
[[nodiscard]] Reading<double> leftSonar(const Robot& r);
[[nodiscard]] Reading<double> rightSonar(const Robot& r);
[[nodiscard]] Reading<double> backSonar(const Robot& r);
[[nodiscard]] inline Reading<Point2> place(const Robot& r) { return r.place(); }
[[nodiscard]] inline Reading<double> orientation(const Robot& r) { return r.orientation(); }
[[nodiscard]] inline Reading<double> velocity(const Robot& r) { return r.velocity(); }
[[nodiscard]] inline Event<BumperHit> bumper(const Robot& r) { return r.bumper(); }
[[nodiscard]] inline Event<char> keyboard(const Robot& r) { return r.keyboard(); }

/// The paper's `pairB`: a wheel command from a forward speed (m/s) and a turn rate (rad/s).
template <class F, class T>
  requires std::convertible_to<ValueOf<F>, double> && std::convertible_to<ValueOf<T>, double>
[[nodiscard]] auto wheels(const F& forward, const T& turn) {
  if constexpr (detail::NumberOperand<F> && detail::NumberOperand<T>) {
    return detail::numbers::wheels(detail::number(forward), detail::number(turn));
  } else {
    return lift([](double f, double t) { return Wheels{f, t}; }, forward, turn);
  }
}

}  // namespace frob

// The sonar ring of Robot::sonar, seen from above (16 sonars, 22.5 degrees apart, counter-clockwise
// from the front; the same picture is in frob/README.md and course/lessons/01_behaviors.md):
//
//                      front
//                 1    0    15
//             2               14
//           3                   13
//      left 4        (o)        12 right
//           5                   11
//             6               10
//                 7    8    9
//                      back
//
// Ranges are measured from the body's surface, 0.15 m to 6.5 m; 6.5 m means no echo. A sonar hears
// a flat wall only within about 35 degrees of head-on (a 25-degree cone, and a surface met more than
// 22.5 degrees off its normal reflects the sound away), so the 45-degree sonars (2, 6, 10, 14) never
// hear a wall parallel to the robot: look with several (nearestEcho). Noise: 1% of the range.
