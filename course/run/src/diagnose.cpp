#include "frob/run/diagnose.hpp"

#include "frob/run/format.hpp"
#include "frob/worlds/free_space.hpp"

#include <cmath>
#include <cstdio>
#include <map>

namespace frob::course {

namespace {

constexpr double kPressedFor = 1.0;  // seconds of pushing before it counts
constexpr double kQuickTask = 1e-9;  // a task that ends at the instant it starts
constexpr int kQuickPerSecond = 20;  // that many in one second of the run: a chain going round on the spot

// One robot's run as the diagnosis keeps it.
struct Watch {
  bool started = false;
  Pose2 last;
  double lastTime = 0.0;
  double distance = 0.0;
  Wheels lastCommand;
  bool everCommanded = false;  // any wheel command but a stop
  bool everForward = false;    // a forward (or backward) speed
  // Pushing against a wall: forward commanded, little forward motion, the body at a wall.
  double pressedSince = -1, pressedTotal = 0, firstPressedAt = -1;
  Point2 firstPressedWhere = Point2::Zero();
  double sonarWhilePressed = 0, maxRange = 6.5;
  // Spinning in place: turning, hardly moving.
  double spinSince = -1, spinAngle = 0, longestSpin = 0, longestSpinAt = 0;
  Point2 spinWhere = Point2::Zero(), longestSpinWhere = Point2::Zero();
  // Tasks that end as they start, by name; and the most in one second of the run (a healthy
  // program has some: a turn already facing its goal, a task of plain code).
  std::map<std::string, int> quickEnds;
  int quickTotal = 0;
  long quickSecond = -1;
  int quickThisSecond = 0, quickMostPerSecond = 0;
};

}  // namespace

struct Diagnosis::Impl {
  std::vector<worlds::WallDef> walls;
  worlds::WallIndex index;
  double dt;
  std::vector<Watch> robots;
  Impl(std::vector<worlds::WallDef> w, const Vec2& size, double step) : walls(std::move(w)), index(walls, size, 1.0), dt(step) {}
};

Diagnosis::Diagnosis(std::vector<worlds::WallDef> walls, const Vec2& size, double dt) : impl_(std::make_unique<Impl>(std::move(walls), size, dt)) {}
Diagnosis::~Diagnosis() = default;
Diagnosis::Diagnosis(Diagnosis&&) noexcept = default;
Diagnosis& Diagnosis::operator=(Diagnosis&&) noexcept = default;

void Diagnosis::observe(std::size_t i, double time, const Pose2& pose, const Wheels& commanded, double frontSonar, double maxRange) {
  if (impl_->robots.size() <= i) impl_->robots.resize(i + 1);
  Watch& w = impl_->robots[i];
  if (commanded.forward != 0 || commanded.turn != 0) w.everCommanded = true;
  if (std::abs(commanded.forward) > 0.01) w.everForward = true;
  if (!w.started) {
    w.started = true;
    w.last = pose, w.lastTime = time, w.lastCommand = commanded;
    return;
  }
  const double dt = std::max(time - w.lastTime, 1e-9);
  const Vec2 moved = pose.position - w.last.position;
  const double forward = moved.dot(Vec2(std::cos(w.last.heading), std::sin(w.last.heading))) / dt;
  w.distance += moved.norm();
  const double radius = 0.23;

  // Pushing: at least 5 cm/s commanded ahead, under a fifth of it made good, within 3 cm of a wall.
  const bool pressed = w.lastCommand.forward > 0.05 && forward < 0.2 * w.lastCommand.forward && impl_->index.distance(pose.position) < radius + 0.03;
  if (pressed) {
    if (w.pressedSince < 0) w.pressedSince = time;
    if (time - w.pressedSince >= kPressedFor && w.firstPressedAt < 0) {
      w.firstPressedAt = w.pressedSince, w.firstPressedWhere = pose.position, w.sonarWhilePressed = frontSonar;
    }
    w.pressedTotal += dt;
  } else {
    w.pressedSince = -1;
  }
  w.maxRange = maxRange;

  // Spinning: turning faster than 0.2 rad/s with the centre moving under 2 cm/s.
  double turned = std::remainder(pose.heading - w.last.heading, 2 * pi);
  if (std::abs(w.lastCommand.turn) > 0.2 && moved.norm() / dt < 0.02) {
    if (w.spinSince < 0) w.spinSince = time, w.spinAngle = 0, w.spinWhere = pose.position;
    w.spinAngle += std::abs(turned);
    if (w.spinAngle > w.longestSpin) w.longestSpin = w.spinAngle, w.longestSpinAt = w.spinSince, w.longestSpinWhere = w.spinWhere;
  } else {
    w.spinSince = -1;
  }
  w.last = pose, w.lastTime = time, w.lastCommand = commanded;
}

void Diagnosis::taskEnded(std::size_t i, const TaskRecord& task) {
  if (impl_->robots.size() <= i) impl_->robots.resize(i + 1);
  Watch& w = impl_->robots[i];
  if (task.depth > 0 && task.how == TaskEnd::Returned && task.end - task.start <= kQuickTask) {
    ++w.quickEnds[task.name];
    ++w.quickTotal;
    const auto second = static_cast<long>(std::floor(task.end));
    w.quickThisSecond = second == w.quickSecond ? w.quickThisSecond + 1 : 1;
    w.quickSecond = second;
    w.quickMostPerSecond = std::max(w.quickMostPerSecond, w.quickThisSecond);
  }
}

std::vector<std::string> Diagnosis::hints(std::size_t i, const std::string& name, const std::vector<TaskRecord>& running, double end,
                                          bool meantToRunForever) const {
  std::vector<std::string> out;
  if (i >= impl_->robots.size()) return out;
  const Watch& w = impl_->robots[i];
  if (w.distance < kNeverMoved && w.everForward) {
    out.push_back(name + " never moved, though its controller commanded a forward speed: is it boxed in, or pushing into a wall from the start?");
  } else if (w.distance < kNeverMoved && !w.everCommanded) {
    out.push_back(name + " never moved: its controller commanded no motion at all (every wheel command was {0, 0})");
  }
  if (w.firstPressedAt >= 0) {
    std::string hint =
        format("%s pushed against a wall for %.0f s of the run while commanding forward speed (the first time from %.1f s at (%.1f, %.1f))",
               name.c_str(), w.pressedTotal, w.firstPressedAt, w.firstPressedWhere.x(), w.firstPressedWhere.y());
    if (w.sonarWhilePressed >= w.maxRange) {
      hint += format(
          "; its front sonar read %.1f m (no echo) there: a sonar misses a wall met at a grazing angle, so look ahead "
          "with several sonars (the nearest echo of sonars 14, 15, 0, 1 and 2) and end the task on the bumper too",
          w.sonarWhilePressed);
    } else {
      hint += format("; its front sonar read %.2f m there: the task drove on regardless, so end it on that reading or on the bumper",
                     w.sonarWhilePressed);
    }
    out.push_back(hint);
  }
  if (w.longestSpin >= 4 * pi) {
    out.push_back(
        format("%s spun in place %.0f times from %.1f s at (%.1f, %.1f): a turn that waits for a condition that never comes "
               "(a sonar that cannot see the way out?)",
               name.c_str(), w.longestSpin / (2 * pi), w.longestSpinAt, w.longestSpinWhere.x(), w.longestSpinWhere.y()));
  }
  if (w.quickMostPerSecond >= kQuickPerSecond) {
    std::string names;
    for (const auto& [task, count] : w.quickEnds) names += (names.empty() ? "'" : ", '") + task + "'";
    out.push_back(
        format("%s's tasks ended at the very instant they began %d times (%s): each one's event had already "
               "occurred when it started, so the chain went round on the spot; make a task's end condition differ "
               "from the one that starts it",
               name.c_str(), w.quickTotal, names.c_str()));
  }
  // Tasks that ran from near the start to the end, nested in each other: one hint, for the innermost
  // (its enclosing tasks wait for it), naming the others.
  const TaskRecord* innermost = nullptr;
  std::string enclosing;
  for (const TaskRecord& t : running) {
    if (t.depth == 0 || t.start > 0.1 * end || end <= 5.0) continue;
    if (innermost != nullptr) enclosing += (enclosing.empty() ? " (inside '" : "', '") + innermost->name;
    if (innermost == nullptr || t.depth > innermost->depth) innermost = &t;
  }
  if (innermost != nullptr && !meantToRunForever) {
    out.push_back(format("%s's task '%s'%s ran from %.1f s to the end of the run: the event that should end it never occurred", name.c_str(),
                         innermost->name.c_str(), enclosing.empty() ? "" : (enclosing + "')").c_str(), innermost->start));
  }
  return out;
}

}  // namespace frob::course
