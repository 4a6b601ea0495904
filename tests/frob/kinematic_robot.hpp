#pragma once
// A test robot without a simulator: a point robot in a circular room, moved by integrating its
// wheel commands, with sonar ranges computed exactly from the room's geometry.

#include "frob/frob.hpp"

#include <cmath>
#include <memory>

namespace frob::testing {

class KinematicRobot {
 public:
  explicit KinematicRobot(double roomRadius = 3.0, Pose2 start = {})
      : state_(std::make_shared<State>(State{.pose = start, .roomRadius = roomRadius})),
        robot_(nomadSpec(), [s = state_, angles = nomadSpec().sonarAngles](const Instant&) -> const SensorFrame& {
          s->frame.sonar.resize(angles.size());
          for (std::size_t i = 0; i < angles.size(); ++i) s->frame.sonar[i] = s->range(s->pose.heading + angles[i]);
          s->frame.odometry = s->pose;
          return s->frame;
        }) {}

  [[nodiscard]] const Robot& robot() const { return robot_; }
  [[nodiscard]] const Pose2& pose() const { return state_->pose; }

  // Samples `controller` at each step of `dt` for `seconds`, moving by its wheels; calls
  // `each(now, wheels)` after every sample.
  template <class Each>
  void run(const Behavior<Wheels>& controller, double dt, double seconds, Each each) {
    Clock clock(dt);
    auto steps = static_cast<std::int64_t>(std::llround(seconds / dt));
    for (std::int64_t i = 0; i < steps; ++i) {
      const Instant& now = i == 0 ? clock.now() : clock.advance();
      Wheels w = controller.at(now);
      each(now, w);
      move(w, dt);
    }
  }
  void run(const Behavior<Wheels>& controller, double dt, double seconds) {
    run(controller, dt, seconds, [](const Instant&, const Wheels&) {});
  }

 private:
  struct State {
    Pose2 pose;
    double roomRadius;
    SensorFrame frame;
    // Distance from the robot along `angle` to the room's wall.
    double range(double angle) const {
      Vec2 d = unitVector(angle);
      const Point2& p = pose.position;
      double b = p.dot(d);
      double c = p.squaredNorm() - roomRadius * roomRadius;
      return -b + std::sqrt(b * b - c);
    }
  };
  void move(const Wheels& w, double dt) {
    Pose2& p = state_->pose;
    p.position += unitVector(p.heading) * (w.forward * dt);
    p.heading = wrapAngle(p.heading + w.turn * dt);
    // The wall stops the robot.
    double r = p.position.norm();
    if (r > state_->roomRadius - 0.01) p.position *= (state_->roomRadius - 0.01) / r;
  }

  std::shared_ptr<State> state_;
  Robot robot_;
};

}  // namespace frob::testing
