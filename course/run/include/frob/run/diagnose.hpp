#pragma once
/// Runs that explain themselves: what a robot's run shows of the common mistakes, in words that
/// name the fix. The run summary and the grader's reasons both carry these hints.
///
///   Diagnosis d(walls, size, dt);
///   each step, for each robot:  d.observe(i, time, truePose, commanded, frontSonar, maxRange);
///   each ended task:            d.taskEnded(i, record);
///   at the end:                 d.hints(i, runningTasks, endTime)

#include "frob/debug.hpp"
#include "frob/robot_values.hpp"
#include "frob/worlds/world_def.hpp"

#include <memory>
#include <string>
#include <vector>

namespace frob::course {

/// A robot whose true path is shorter than this (metres) never moved: under a centimetre of jitter
/// against a wall, but not a robot that drove a few centimetres and stopped.
inline constexpr double kNeverMoved = 0.02;

/// Watches every robot of a run and says what went wrong, when something common did.
class Diagnosis {
 public:
  /// For a run among `walls` (the enclosure's too) in a world of `size`, stepping by `dt`.
  Diagnosis(std::vector<worlds::WallDef> walls, const Vec2& size, double dt);
  ~Diagnosis();
  Diagnosis(Diagnosis&&) noexcept;
  Diagnosis& operator=(Diagnosis&&) noexcept;

  /// Robot `i` at `time`: where it truly is, what it commanded, and what its front sonar read.
  void observe(std::size_t i, double time, const Pose2& truePose, const Wheels& commanded, double frontSonar, double maxRange);
  /// A task of robot `i` ended.
  void taskEnded(std::size_t i, const TaskRecord& task);
  /// What went wrong for robot `i` (named `name`), one sentence each; `running` are its tasks still
  /// running at `end`. Empty when nothing common went wrong. A controller `meantToRunForever` (a
  /// wall follower, whose assignment never waits for its task to return) gets no hint that its tasks
  /// never ended.
  [[nodiscard]] std::vector<std::string> hints(std::size_t i, const std::string& name, const std::vector<TaskRecord>& running, double end,
                                               bool meantToRunForever = false) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace frob::course
