#pragma once
/// The state a task sees: its robot and where the robot was when the task began (the paper's
/// TaskState with snapRobot), and the error type tasks raise.

#include "frob/robot.hpp"

#include <stdexcept>
#include <string>

namespace frob {

/// An error raised by a task (the paper's RoboErr): caught by taskCatch or try/catch.
class RoboErr : public std::runtime_error {
 public:
  /// An error with a readable message.
  explicit RoboErr(const std::string& message) : std::runtime_error(message) {}
  explicit RoboErr(const char* message) : std::runtime_error(message) {}
};

/// What a task knows when it starts. Captured at every task transition, so a task can say
/// "turn 90 degrees from where I started".
class TaskState {
 public:
  /// The state of a task of robot `r` starting now at its odometry pose.
  explicit TaskState(Robot r) : robot_(std::move(r)) {}

  /// The robot whose sensors the task reads.
  [[nodiscard]] const Robot& robot() const { return robot_; }
  /// Where the robot believed it was when this task started, metres.
  [[nodiscard]] const Point2& initialPlace() const { return place_; }
  /// The robot's believed heading when this task started, radians.
  [[nodiscard]] double initialOrientation() const { return orientation_; }
  /// Simulated time this task started, seconds on the run's clock (as the timeline shows it): the
  /// instant of the event that ended the task before, which may fall between two samples.
  [[nodiscard]] double startTime() const { return startTime_; }

  /// Changes the recorded start pose and time (for setTaskState).
  TaskState& setInitialPlace(const Point2& p) {
    place_ = p;
    return *this;
  }
  TaskState& setInitialOrientation(double radians) {
    orientation_ = radians;
    return *this;
  }
  TaskState& setStartTime(double seconds) {
    startTime_ = seconds;
    return *this;
  }

 private:
  Robot robot_;
  Point2 place_ = Point2::Zero();
  double orientation_ = 0.0;
  double startTime_ = 0.0;
};

}  // namespace frob
