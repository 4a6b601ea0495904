#include "frob/robot.hpp"

#include "frob/errors.hpp"

#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

namespace frob {

void detail::sonarOutOfRange(std::size_t index, std::size_t size) {
  throw std::out_of_range("Robot: sonar " + std::to_string(index) + " read from a frame of " + std::to_string(size) + " sonars");
}

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

// The root of a robot's sensor graph when its owner refreshes the frame in place: always that frame.
class FixedFrameNode final : public detail::BehaviorNode<const SensorFrame*> {
 public:
  // Holds the frame from the start, so that readings find it in value() without sampling the node.
  explicit FixedFrameNode(std::shared_ptr<const SensorFrame> frame) : frame_(std::move(frame)) { hold(frame_.get()); }

 protected:
  const SensorFrame* compute(const Instant&) override { return frame_.get(); }

 private:
  std::shared_ptr<const SensorFrame> frame_;
};

// The first item of a per-step list in the frame, as an event.
template <class T>
class FrameListEvent final : public detail::EventNode<T> {
 public:
  FrameListEvent(detail::NodeRef<detail::BehaviorNode<const SensorFrame*>> frame, std::vector<T> SensorFrame::*list)
      : frame_(std::move(frame)), list_(list) {}

 protected:
  std::optional<T> compute(const Instant& now) override {
    const std::vector<T>& items = frame_->at(now)->*list_;
    if (items.empty()) return std::nullopt;
    return items.front();
  }

 private:
  detail::NodeRef<detail::BehaviorNode<const SensorFrame*>> frame_;
  std::vector<T> SensorFrame::*list_;
};

detail::NodeRef<detail::BehaviorNode<const SensorFrame*>> makeFrameNode(FrameSource source) {
  FROB_ASSERT(static_cast<bool>(source), "Robot: the frame source is empty");
  return detail::makeNode<FrameNode>(std::move(source));
}

detail::NodeRef<detail::BehaviorNode<const SensorFrame*>> makeFixedFrameNode(std::shared_ptr<const SensorFrame> frame) {
  FROB_ASSERT(frame != nullptr, "Robot: the frame is null");
  return detail::makeNode<FixedFrameNode>(std::move(frame));
}

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
  Behavior<const SensorFrame*> frame;
  bool inPlace;  // the frame is refreshed in place by its owner, not fetched at each instant
  Behavior<std::vector<double>> sonars;
  Event<BumperHit> bumper;
  Event<char> keyboard;

  template <class T>
  Reading<T> read(detail::FrameField<T> field) const {
    return Reading<T>(field, detail::FrameArg{&frame.node()->value(), !inPlace, frame.node()});
  }
  Reading<double> read(detail::FrameSlot slot, std::size_t index = 0) const { return read(detail::FrameField<double>{slot, index}); }
};

RobotSpec nomadSpec(int count) {
  FROB_ASSERT(count > 0, "nomadSpec: a sonar ring needs at least one sonar");
  RobotSpec spec;
  for (int i = 0; i < count; ++i) spec.sonarAngles.push_back(wrapAngle(2.0 * pi * i / count));
  return spec;
}

Robot::Robot(RobotSpec spec, detail::NodeRef<detail::BehaviorNode<const SensorFrame*>> frameNode, bool inPlace) {
  FROB_ASSERT(!spec.sonarAngles.empty(), "Robot: the spec has no sonars");
  Behavior<const SensorFrame*> frame(frameNode);
  sensors_ = std::make_shared<const Sensors>(Sensors{
      .spec = std::move(spec),
      .frame = frame,
      .inPlace = inPlace,
      .sonars = lift([](const SensorFrame* s) { return s->sonar; }, frame),
      .bumper = Event<BumperHit>(detail::makeNode<FrameListEvent<BumperHit>>(frameNode, &SensorFrame::bumps)),
      .keyboard = Event<char>(detail::makeNode<FrameListEvent<char>>(frameNode, &SensorFrame::keys)),
  });
}

Robot::Robot(RobotSpec spec, FrameSource source) : Robot(std::move(spec), makeFrameNode(std::move(source)), false) {}

Robot::Robot(RobotSpec spec, std::shared_ptr<const SensorFrame> frame) : Robot(std::move(spec), makeFixedFrameNode(std::move(frame)), true) {}

Robot::Robot(RobotSpec spec, ScriptedSensors sensors) : Robot(spec, scriptedSource(spec, std::move(sensors))) {}

const RobotSpec& Robot::spec() const { return sensors_->spec; }

Reading<double> Robot::sonar(int i, std::source_location loc) const {
  int n = static_cast<int>(sensors_->spec.sonarAngles.size());
  if (i < 0 || i >= n) {
    throw UsageError(std::string(loc.file_name()) + ":" + std::to_string(loc.line()) + ": sonar(r, " + std::to_string(i) +
                     ") does not exist: the ring has " + std::to_string(n) + " sonars, 0 (front) to " + std::to_string(n - 1) + " counter-clockwise");
  }
  return sensors_->read(detail::FrameSlot::sonar, static_cast<std::size_t>(i));
}

Behavior<std::vector<double>> Robot::sonars() const { return sensors_->sonars; }

int Robot::sonarNearest(double angle) const {
  const std::vector<double>& angles = sensors_->spec.sonarAngles;
  int best = 0;
  for (int i = 1; i < static_cast<int>(angles.size()); ++i) {
    if (std::abs(angleDiff(angles[static_cast<std::size_t>(i)], angle)) < std::abs(angleDiff(angles[static_cast<std::size_t>(best)], angle))) {
      best = i;
    }
  }
  return best;
}

Reading<Point2> Robot::place() const { return sensors_->read(detail::FrameField<Point2>{}); }
Reading<double> Robot::orientation() const { return sensors_->read(detail::FrameSlot::heading); }
Reading<double> Robot::velocity() const { return sensors_->read(detail::FrameSlot::velocity); }
Event<BumperHit> Robot::bumper() const { return sensors_->bumper; }
Event<char> Robot::keyboard() const { return sensors_->keyboard; }

Reading<double> frontSonar(const Robot& r) { return r.sonar(r.sonarNearest(0.0)); }
Reading<double> leftSonar(const Robot& r) { return r.sonar(r.sonarNearest(pi / 2)); }
Reading<double> rightSonar(const Robot& r) { return r.sonar(r.sonarNearest(-pi / 2)); }
Reading<double> backSonar(const Robot& r) { return r.sonar(r.sonarNearest(pi)); }

Behavior<Wheels> detail::numbers::wheels(const Behavior<double>& forward, const Behavior<double>& turn) {
  return lift([](double f, double t) { return Wheels{f, t}; }, forward, turn);
}

}  // namespace frob
