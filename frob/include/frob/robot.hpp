#pragma once
/// The sensor side of one robot, as behaviors and events. A controller sees only this.

#include "frob/debug.hpp"
#include "frob/event.hpp"
#include "frob/robot_values.hpp"

#include <functional>
#include <memory>
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

namespace detail {
// Reads one field of the robot's frame of the instant (for sonar `index` where it matters).
template <class T>
struct FrameField {
  T (*read)(const SensorFrame&, std::size_t index);
  std::size_t index = 0;
  T operator()(const SensorFrame* frame) const { return read(*frame, index); }
};
}  // namespace detail

/// A sensor reading: a behavior read straight from the robot's frame of the instant, which is
/// fetched once per instant however many readings use it. Converts to Behavior<T>.
template <class T>
using Reading = Pointwise<T, detail::FrameField<T>, detail::Arg<Behavior<const SensorFrame*>>>;

/// A ring of `count` sonars evenly spaced counter-clockwise from the front (16 on a Nomad 200).
[[nodiscard]] RobotSpec nomadSpec(int count = 16);

/// One robot's sensors. Cheap to copy; copies share the same sensor behaviors, which are read once
/// per instant however many parts of a controller use them.
class Robot {
 public:
  /// A robot of shape `spec` whose sensors read the frames `source` gives.
  Robot(RobotSpec spec, FrameSource source);
  /// A robot whose sensors follow `sensors` as functions of time.
  Robot(RobotSpec spec, ScriptedSensors sensors);

  /// Body radius and sonar layout.
  [[nodiscard]] const RobotSpec& spec() const;
  /// Range of sonar `i` (0 = front, counter-clockwise), metres. Index taken modulo the ring size.
  [[nodiscard]] Reading<double> sonar(int i) const;
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
  struct Sensors;
  std::shared_ptr<const Sensors> sensors_;
  std::shared_ptr<DebugChannel> debug_ = std::make_shared<DebugChannel>();
};

/// The paper's sensor functions, in C++.
[[nodiscard]] inline Reading<double> sonar(const Robot& r, int i) { return r.sonar(i); }
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
  return lift([](double f, double t) { return Wheels{f, t}; }, forward, turn);
}

}  // namespace frob
