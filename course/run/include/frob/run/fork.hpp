#pragma once
/// A run forked from an instant of an earlier one (frob run --from RUN#t=T): the earlier run's
/// wheels are played back up to T, each step checked against the true poses it recorded, so the
/// world at T is the earlier run's to the last bit (poses, velocities, odometry, whatever was moved,
/// the random state, the clock); from T on, the controllers drive.

#include "frob/base/result.hpp"
#include "frob/worlds/run.hpp"

#include <string>
#include <vector>

namespace frob::course {

/// An earlier run up to one of its instants, as its trace (--trace) or viewer page (--html) recorded it.
struct ForkPoint {
  std::string source;                       ///< the trace or page, as named
  double at = 0.0;                          ///< the instant the controllers take over, seconds
  std::vector<std::vector<Wheels>> wheels;  ///< per step before it, per robot: what the earlier run's controllers commanded
  std::vector<std::vector<Pose2>> poses;    ///< per step up to it, per robot: the earlier run's true poses
  double tolerance = 0.0;                   ///< how far a pose may stray from them: 0 from a trace, half a millimetre from a page
};

/// Reads `spec` ("run.csv#t=12.5" or "run.html#t=12.5"), the trace or viewer page of a run with steps of
/// `dt`; says what is wrong with it.
[[nodiscard]] Result<ForkPoint> readForkPoint(const std::string& spec, double dt);

/// `controllers`, taking over at the fork's instant; before it the earlier run's wheels, and a robot
/// whose true pose strays from the earlier run's fails there, saying it is not a run of this world and seed.
[[nodiscard]] worlds::DriverFactory forkedAt(const ForkPoint& fork, worlds::DriverFactory controllers);

}  // namespace frob::course
