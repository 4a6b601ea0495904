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

double sonarAt(const SensorFrame& f, std::size_t i) { return f.sonar.at(i); }
Point2 placeOf(const SensorFrame& f, std::size_t) { return f.odometry.position; }
double headingOf(const SensorFrame& f, std::size_t) { return f.odometry.heading; }
double velocityOf(const SensorFrame& f, std::size_t) { return f.velocity; }

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
  Behavior<const SensorFrame*> frame;
  Behavior<std::vector<double>> sonars;
  Event<BumperHit> bumper;
  Event<char> keyboard;

  template <class T>
  Reading<T> read(T (*field)(const SensorFrame&, std::size_t), std::size_t index = 0) const {
    return Reading<T>(detail::FrameField<T>{field, index}, detail::Arg<Behavior<const SensorFrame*>>{frame.node()});
  }
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
  auto frameNode = frame.node();
  sensors_ = std::make_shared<const Sensors>(Sensors{
      .spec = std::move(spec),
      .frame = frame,
      .sonars = lift([](const SensorFrame* s) { return s->sonar; }, frame),
      .bumper = Event<BumperHit>(std::make_shared<FrameListEvent<BumperHit>>(frameNode, &SensorFrame::bumps)),
      .keyboard = Event<char>(std::make_shared<FrameListEvent<char>>(frameNode, &SensorFrame::keys)),
  });
}

Robot::Robot(RobotSpec spec, ScriptedSensors sensors) : Robot(spec, scriptedSource(spec, std::move(sensors))) {}

const RobotSpec& Robot::spec() const { return sensors_->spec; }

Reading<double> Robot::sonar(int i) const {
  int n = static_cast<int>(sensors_->spec.sonarAngles.size());
  return sensors_->read(&sonarAt, static_cast<std::size_t>(((i % n) + n) % n));
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

Reading<Point2> Robot::place() const { return sensors_->read(&placeOf); }
Reading<double> Robot::orientation() const { return sensors_->read(&headingOf); }
Reading<double> Robot::velocity() const { return sensors_->read(&velocityOf); }
Event<BumperHit> Robot::bumper() const { return sensors_->bumper; }
Event<char> Robot::keyboard() const { return sensors_->keyboard; }

Reading<double> frontSonar(const Robot& r) { return r.sonar(r.sonarNearest(0.0)); }
Reading<double> leftSonar(const Robot& r) { return r.sonar(r.sonarNearest(pi / 2)); }
Reading<double> rightSonar(const Robot& r) { return r.sonar(r.sonarNearest(-pi / 2)); }
Reading<double> backSonar(const Robot& r) { return r.sonar(r.sonarNearest(pi)); }

}  // namespace frob
