#pragma once
/// One run of a world with its controllers, step by step: sensors, then every controller's
/// behavior sampled once at the instant, then physics; each instant recorded.

#include "frob/controller.hpp"
#include "frob/robot.hpp"
#include "frob/worlds/recorder.hpp"
#include "frob/worlds/simulation.hpp"

#include <memory>
#include <string>
#include <vector>

namespace frob::worlds {

/// A controller (the paper's runController argument): from a robot's sensors to its wheels.
using Controller = frob::Controller;

/// A controller that failed: it threw, gave a non-finite command, or its tasks ran away. Its robot
/// stands still from then on; the others go on.
struct ControllerFailure {
  std::size_t robot = 0;  ///< index of the robot
  double time = 0.0;      ///< simulated time of the failure, seconds
  std::string message;    ///< readable reason, naming the robot and (for tasks) the task
};

/// A world running its controllers. Logical time only; the same world, seed and controllers give
/// a bit-identical recording.
class Run {
 public:
  /// Builds the world and one controller per robot from `controllers` (one per robot, or one for all).
  Run(const WorldDef& world, const SimOptions& options, const std::vector<Controller>& controllers,
      RecorderOptions recording = {});

  /// Senses, samples every controller at the current instant, records, and steps physics once.
  void step();
  /// Steps until the simulated time reaches `seconds`.
  void runUntil(double seconds);

  /// The simulation (true poses, walls, time).
  [[nodiscard]] const Simulation& simulation() const { return *sim_; }
  /// Every recorded instant and the trajectory hash.
  [[nodiscard]] const Recorder& recorder() const { return recorder_; }
  /// Robot `i` as its controller sees it; its debugChannel() holds pictures and the task timeline.
  [[nodiscard]] const Robot& robot(std::size_t i) const { return robots_.at(i); }
  /// The controllers that failed, in the order they did.
  [[nodiscard]] const std::vector<ControllerFailure>& failures() const { return failures_; }

 private:
  void fail(std::size_t i, double time, const std::string& why);

  std::unique_ptr<Simulation> sim_;
  Clock clock_;
  bool started_ = false;
  std::vector<Robot> robots_;
  std::vector<std::optional<Behavior<Wheels>>> controllers_;  // empty once failed
  std::vector<Wheels> wheels_;
  std::vector<Picture> pictures_;
  Recorder recorder_;
  std::vector<ControllerFailure> failures_;
};

}  // namespace frob::worlds
