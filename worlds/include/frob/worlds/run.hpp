#pragma once
/// One run of a world with its controllers, step by step: sensors, then every controller's
/// behavior sampled once at the instant, then physics; each instant recorded.

#include "frob/controller.hpp"
#include "frob/robot.hpp"
#include "frob/worlds/recorder.hpp"
#include "frob/worlds/simulation.hpp"

#include <functional>
#include <memory>
#include <span>
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

/// The controllers of a run as the simulation sees them: at each instant every robot's frame goes
/// in and its wheels come out. In this process (inProcess), or in a sandboxed controller host.
class ControllerDriver {
 public:
  virtual ~ControllerDriver() = default;
  /// Sets wheels[i] and pictures[i] for every robot at `now`, from the simulation's frames. A
  /// controller that fails appends (robot, reason) to `failed` once and commands a stop from then on.
  virtual void decide(const Instant& now, std::span<Wheels> wheels, std::span<Picture> pictures,
                      std::vector<std::pair<std::size_t, std::string>>& failed) = 0;
  /// Robot `i`'s task timeline as its controller reports it.
  [[nodiscard]] virtual Timeline& timeline(std::size_t i) = 0;
  /// Whether robot `i`'s controller is done: its task returned, and it commands a stop for ever.
  [[nodiscard]] virtual bool finished(std::size_t /*i*/) const { return false; }
};

/// Makes the driver of a run once its simulation is built.
using DriverFactory = std::function<std::unique_ptr<ControllerDriver>(const Simulation&)>;

/// Controllers run in this process: one per robot, or one for all robots.
[[nodiscard]] DriverFactory inProcess(std::vector<Controller> controllers);

/// A world running its controllers. Logical time only; the same world, seed and controllers give
/// a bit-identical recording.
class Run {
 public:
  /// Builds the world and one controller per robot from `controllers` (one per robot, or one for all).
  Run(const WorldDef& world, const SimOptions& options, const std::vector<Controller>& controllers, RecorderOptions recording = {});
  /// Builds the world, then its controllers' driver with `driver`.
  Run(const WorldDef& world, const SimOptions& options, const DriverFactory& driver, RecorderOptions recording = {});

  /// Senses, samples every controller at the current instant, records, and steps physics once.
  void step();
  /// Steps until the simulated time reaches `seconds`.
  void runUntil(double seconds);

  /// The simulation (true poses, walls, time).
  [[nodiscard]] const Simulation& simulation() const { return *sim_; }
  /// Every recorded instant and the trajectory hash.
  [[nodiscard]] const Recorder& recorder() const { return recorder_; }
  /// Robot `i`'s task timeline, as its controller reports it.
  [[nodiscard]] Timeline& timeline(std::size_t i) const { return driver_->timeline(i); }
  /// Whether robot `i`'s controller is done: its task returned, and it stands still from then on.
  [[nodiscard]] bool finished(std::size_t i) const { return driver_->finished(i); }
  /// The wheels applied at the last step, one per robot (a failed controller's robot stands still).
  [[nodiscard]] const std::vector<Wheels>& commands() const { return wheels_; }
  /// The controllers that failed, in the order they did.
  [[nodiscard]] const std::vector<ControllerFailure>& failures() const { return failures_; }

 private:
  std::unique_ptr<Simulation> sim_;
  std::unique_ptr<ControllerDriver> driver_;
  Clock clock_;
  bool started_ = false;
  std::vector<Wheels> wheels_;
  std::vector<Picture> pictures_;
  std::vector<std::pair<std::size_t, std::string>> failed_;  // this step's new failures
  Recorder recorder_;
  std::vector<ControllerFailure> failures_;
};

}  // namespace frob::worlds
