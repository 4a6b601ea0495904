#include "frob/worlds/recorder.hpp"

#include "frob/worlds/fnv.hpp"
#include "frob/worlds/simulation.hpp"

#include <cstring>

namespace frob::worlds {

std::uint64_t hashPose(std::uint64_t hash, const Pose2& pose) {
  return Fnv1a(hash).add(pose.position.x()).add(pose.position.y()).add(pose.heading).value();
}

void Recorder::record(const Simulation& sim, std::span<const Wheels> wheels, std::span<const Picture> pictures) {
  const std::size_t n = sim.robotCount();
  for (std::size_t i = 0; i < n; ++i) hash_ = hashPose(hash_, sim.truePose(i));
  ++count_;
  if (!options_.keepSteps) return;
  StepRecord s{.step = sim.stepCount(), .time = sim.time()};
  s.robots.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    const SensorFrame& f = sim.frame(i);
    s.robots.push_back({.truePose = sim.truePose(i),
                        .odometry = f.odometry,
                        .wheels = i < wheels.size() ? wheels[i] : Wheels{},
                        .sonar = f.sonar,
                        .bumps = f.bumps,
                        .keys = f.keys,
                        .picture = i < pictures.size() ? pictures[i] : Picture{}});
  }
  if (options_.window != 0 && steps_.size() == options_.window) steps_.erase(steps_.begin());
  steps_.push_back(std::move(s));
}

}  // namespace frob::worlds
