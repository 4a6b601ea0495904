#pragma once
/// The simulated world: Box2D walls and robots, sonar rays, bumpers, odometry, scripted keys.
/// Each step: sense() fills one SensorFrame per robot, controllers read frame(i), step() applies
/// one Wheels per robot and advances logical time by dt. Nothing reads the wall clock.
///
///   Simulation sim(*loadWorld("maze.toml"), {.seed = 42});
///   Recorder rec;
///   std::vector<Wheels> wheels(sim.robotCount());
///   std::vector<Picture> pictures(sim.robotCount());
///   while (sim.time() < 60.0) {
///     sim.sense();                                   // frames at time sim.time()
///     for (std::size_t i = 0; i < sim.robotCount(); ++i)
///       wheels[i] = /* sample controller i on sim.frame(i) */ Wheels{};
///     rec.record(sim, wheels, pictures);             // true poses, frames, commands, pictures
///     sim.step(wheels);                              // physics; time advances by dt
///   }

#include "frob/robot_values.hpp"
#include "frob/worlds/world_def.hpp"

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

namespace frob::worlds {

/// A hash of what a fixed short run does in this build (a robot with every noise, slip and start
/// spread, driving at a wall): it changes when the simulation's behaviour does, so that results
/// cached from runs can be keyed by it.
[[nodiscard]] std::uint64_t simulationFingerprint();

/// Options of one run, beside the world itself.
struct SimOptions {
  double dt = 0.01;                   ///< fixed step, seconds (100 Hz)
  std::optional<std::uint64_t> seed;  ///< replaces the world's seed when set
  std::vector<KeyEventDef> keys;      ///< scripted keys added to the world's own
  int threads = 1;                    ///< threads that sense robots in parallel (results do not depend on it)
};

/// A running world. Move-only; Box2D stays behind the implementation.
class Simulation {
 public:
  /// Builds the world. `world` must pass checkWorld() (loadWorld() guarantees it).
  explicit Simulation(const WorldDef& world, const SimOptions& options = {});
  ~Simulation();
  Simulation(Simulation&&) noexcept;
  Simulation& operator=(Simulation&&) noexcept;

  /// Reads every robot's sensors at the current instant into frame(i). Calling it twice is harmless.
  void sense();
  /// What robot `i` sensed at the last sense(): sonar, odometry, speeds, bumps and keys of this step.
  /// Refreshed in place: its address holds for the simulation's life.
  [[nodiscard]] const SensorFrame& frame(std::size_t i) const;
  /// Applies one command per robot (wheels.size() == robotCount()), then advances physics by dt.
  /// Non-finite commands are replaced by a stop and counted in invalidCommands(i).
  void step(std::span<const Wheels> wheels);

  /// Number of robots.
  [[nodiscard]] std::size_t robotCount() const;
  /// What robot `i`'s controller may know of its body and sensors.
  [[nodiscard]] const RobotSpec& spec(std::size_t i) const;
  /// Robot `i`'s definition (name, start, noise, limits).
  [[nodiscard]] const RobotDef& robot(std::size_t i) const;
  /// Robot `i`'s name for people: its own, "robot<i>" when it has none, "<name>#<i>" when another shares it.
  [[nodiscard]] std::string robotName(std::size_t i) const;
  /// Robot `i`'s true pose, for rendering and grading (controllers see only odometry).
  [[nodiscard]] Pose2 truePose(std::size_t i) const;
  /// Robot `i`'s believed pose (the odometry of the next frame). Like every call, not to be made
  /// while another is running: the last step's dead reckoning may be done here.
  [[nodiscard]] Pose2 odometry(std::size_t i) const;
  /// Commands to robot `i` that were not finite so far.
  [[nodiscard]] std::size_t invalidCommands(std::size_t i) const;
  /// Whether anything presses one of robot `i`'s bumpers now (after the last step).
  [[nodiscard]] bool touching(std::size_t i) const;

  /// Steps taken so far.
  [[nodiscard]] std::int64_t stepCount() const;
  /// Logical time, seconds: stepCount() * dt().
  [[nodiscard]] double time() const;
  /// The fixed step, seconds.
  [[nodiscard]] double dt() const;
  /// The seed in use (the options' seed, else the world's).
  [[nodiscard]] std::uint64_t seed() const;
  /// The world as built; walls() adds the enclosing walls when the world is enclosed.
  [[nodiscard]] const WorldDef& world() const;
  /// Every static wall, enclosure included, for rendering.
  [[nodiscard]] const std::vector<WallDef>& walls() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace frob::worlds
