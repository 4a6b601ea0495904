#include "frob/robot.hpp"

#include "frob/errors.hpp"

#include <cmath>
#include <utility>

namespace frob {

namespace {

// The root of a robot's sensor graph: the frame of this instant, fetched once per instant.
class FrameNode final : public detail::BehaviorNode<const SensorFrame*> {
 public:
  explicit FrameNode(FrameSource source) : source_(std::move(source)) {}

 protected:
  const SensorFrame* compute(const Instant& now) override { return &source_(now); }

 private:
  FrameSource source_;
};

// Reads one field of the frame.
template <class T, class F>
Behavior<T> field(const Behavior<const SensorFrame*>& frame, F f) {
  return lift([f](const SensorFrame* s) { return T(f(*s)); }, frame);
}

// The first item of a per-step list in the frame, as an event.
template <class T>
class FrameListEvent final : public detail::EventNode<T> {
 public:
  FrameListEvent(std::shared_ptr<detail::BehaviorNode<const SensorFrame*>> frame,
                 std::vector<T> SensorFrame::*list)
      : frame_(std::move(frame)), list_(list) {}

 protected:
  std::optional<T> compute(const Instant& now) override {
    const std::vector<T>& items = frame_->at(now)->*list_;
    if (items.empty()) return std::nullopt;
    return items.front();
  }

 private:
  std::shared_ptr<detail::BehaviorNode<const SensorFrame*>> frame_;
  std::vector<T> SensorFrame::*list_;
};

// A frame source that computes readings from functions of time.
FrameSource scriptedSource(const RobotSpec& spec, ScriptedSensors s) {
  auto frame = std::make_shared<SensorFrame>();
  int count = static_cast<int>(spec.sonarAngles.size());
  return [frame, count, s = std::move(s)](const Instant& now) -> const SensorFrame& {
    double t = now.time;
    frame->sonar.resize(static_cast<std::size_t>(count));
    for (int i = 0; i < count; ++i) frame->sonar[static_cast<std::size_t>(i)] = s.sonar(t, i);
    frame->odometry = s.odometry(t);
    frame->velocity = s.velocity(t);
    frame->bumps = s.bumps(t);
    frame->keys = s.keys(t);
    return *frame;
  };
}

}  // namespace

struct Robot::Sensors {
  RobotSpec spec;
  std::vector<Behavior<double>> sonar;
  Behavior<std::vector<double>> sonars;
  Behavior<Point2> place;
  Behavior<double> orientation;
  Behavior<double> velocity;
  Event<BumperHit> bumper;
  Event<char> keyboard;
};

RobotSpec nomadSpec(int count) {
  FROB_ASSERT(count > 0, "nomadSpec: a sonar ring needs at least one sonar");
  RobotSpec spec;
  for (int i = 0; i < count; ++i) spec.sonarAngles.push_back(wrapAngle(2.0 * pi * i / count));
  return spec;
}

Robot::Robot(RobotSpec spec, FrameSource source) {
  FROB_ASSERT(!spec.sonarAngles.empty(), "Robot: the spec has no sonars");
  FROB_ASSERT(static_cast<bool>(source), "Robot: the frame source is empty");
  Behavior<const SensorFrame*> frame(std::make_shared<FrameNode>(std::move(source)));
  std::vector<Behavior<double>> sonar;
  for (std::size_t i = 0; i < spec.sonarAngles.size(); ++i) {
    sonar.push_back(field<double>(frame, [i](const SensorFrame& s) { return s.sonar.at(i); }));
  }
  auto frameNode = frame.node();
  sensors_ = std::make_shared<const Sensors>(Sensors{
      .spec = std::move(spec),
      .sonar = std::move(sonar),
      .sonars = field<std::vector<double>>(frame, [](const SensorFrame& s) { return s.sonar; }),
      .place = field<Point2>(frame, [](const SensorFrame& s) { return s.odometry.position; }),
      .orientation = field<double>(frame, [](const SensorFrame& s) { return s.odometry.heading; }),
      .velocity = field<double>(frame, [](const SensorFrame& s) { return s.velocity; }),
      .bumper = Event<BumperHit>(std::make_shared<FrameListEvent<BumperHit>>(frameNode, &SensorFrame::bumps)),
      .keyboard = Event<char>(std::make_shared<FrameListEvent<char>>(frameNode, &SensorFrame::keys)),
  });
}

Robot::Robot(RobotSpec spec, ScriptedSensors sensors) : Robot(spec, scriptedSource(spec, std::move(sensors))) {}

const RobotSpec& Robot::spec() const { return sensors_->spec; }

Behavior<double> Robot::sonar(int i) const {
  int n = static_cast<int>(sensors_->sonar.size());
  return sensors_->sonar[static_cast<std::size_t>(((i % n) + n) % n)];
}

Behavior<std::vector<double>> Robot::sonars() const { return sensors_->sonars; }

int Robot::sonarNearest(double angle) const {
  const std::vector<double>& angles = sensors_->spec.sonarAngles;
  int best = 0;
  for (int i = 1; i < static_cast<int>(angles.size()); ++i) {
    if (std::abs(angleDiff(angles[static_cast<std::size_t>(i)], angle)) <
        std::abs(angleDiff(angles[static_cast<std::size_t>(best)], angle))) {
      best = i;
    }
  }
  return best;
}

Behavior<Point2> Robot::place() const { return sensors_->place; }
Behavior<double> Robot::orientation() const { return sensors_->orientation; }
Behavior<double> Robot::velocity() const { return sensors_->velocity; }
Event<BumperHit> Robot::bumper() const { return sensors_->bumper; }
Event<char> Robot::keyboard() const { return sensors_->keyboard; }

Behavior<double> frontSonar(const Robot& r) { return r.sonar(r.sonarNearest(0.0)); }
Behavior<double> leftSonar(const Robot& r) { return r.sonar(r.sonarNearest(pi / 2)); }
Behavior<double> rightSonar(const Robot& r) { return r.sonar(r.sonarNearest(-pi / 2)); }
Behavior<double> backSonar(const Robot& r) { return r.sonar(r.sonarNearest(pi)); }

}  // namespace frob
