#pragma once
/// Recording a run: per-step state for the renderer, traces and graders, and a hash of the
/// trajectory for golden tests.

#include "frob/picture.hpp"
#include "frob/robot_values.hpp"
#include "frob/worlds/fnv.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace frob::worlds {

class Simulation;

/// One robot at one recorded instant.
struct RobotRecord {
  Pose2 truePose;                ///< where the robot really is
  Pose2 odometry;                ///< where it believes it is
  Wheels wheels;                 ///< the command its controller gave at this instant
  std::vector<double> sonar;     ///< ranges, metres
  std::vector<BumperHit> bumps;  ///< bumper contacts that began in the step before
  std::vector<char> keys;        ///< keys delivered at this instant
  Picture picture;               ///< the controller's debug overlay (filled by the run loop; may be empty)
};

/// Every robot at one instant.
struct StepRecord {
  std::int64_t step = 0;            ///< step index
  double time = 0.0;                ///< logical time, seconds
  std::vector<RobotRecord> robots;  ///< one per robot
};

/// What a Recorder keeps.
struct RecorderOptions {
  bool keepSteps = true;  ///< keep StepRecords; false keeps only the hash (long runs, benchmarks)
  /// Keep only the newest `window` StepRecords (0: every one). A run whose readers take each step
  /// as it comes (frob run: its video, plots and trace) needs 1, and its memory stays flat.
  std::size_t window = 0;
};

/// FNV-1a over the exact bytes of a pose's x, y and heading (doubles), continuing from `hash`.
[[nodiscard]] std::uint64_t hashPose(std::uint64_t hash, const Pose2& pose);

/// Records a run: call record() after sense() and after the controllers chose their wheels.
class Recorder {
 public:
  /// An empty recording.
  explicit Recorder(RecorderOptions options = {}) : options_(options) {}
  /// Appends the current instant of `sim` with the chosen `wheels` (one per robot) and optional
  /// `pictures` (one per robot, or empty), and folds every true pose into the trajectory hash.
  void record(const Simulation& sim, std::span<const Wheels> wheels, std::span<const Picture> pictures = {});
  /// The recorded instants: every one, the newest `window`, or none (keepSteps false).
  [[nodiscard]] const std::vector<StepRecord>& steps() const { return steps_; }
  /// The last recorded instant, e.g. to attach pictures; only when steps() is not empty.
  [[nodiscard]] StepRecord& last() { return steps_.back(); }
  /// FNV-1a hash of every recorded true pose, robot by robot, step by step.
  [[nodiscard]] std::uint64_t trajectoryHash() const { return hash_; }
  /// Number of instants recorded.
  [[nodiscard]] std::int64_t count() const { return count_; }

 private:
  RecorderOptions options_;
  std::vector<StepRecord> steps_;
  std::uint64_t hash_ = kFnvOffset;
  std::int64_t count_ = 0;
};

}  // namespace frob::worlds
