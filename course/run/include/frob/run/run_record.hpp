#pragma once
/// What the trusted simulation recorded of each robot over a run, as a rubric's criteria judge it:
/// its true path, its contacts, and its controller's failure or returned value. `frob grade` keeps
/// one per graded run; `frob run --assignment` keeps one to judge the student's own run the same way.

#include "frob/debug.hpp"
#include "frob/worlds/run.hpp"
#include "frob/worlds/world_def.hpp"

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace frob::course {

/// One robot over a run.
struct Track {
  std::string name;                                 ///< the robot's name for people
  double radius = 0.23;                             ///< body radius, metres
  std::vector<Point2> path;                         ///< true position at t = k × dt, k = 0, 1, ...
  std::vector<double> heading;                      ///< true heading at the same instants, radians (may be empty: then unknown)
  std::vector<std::pair<double, Point2>> contacts;  ///< bumper contacts: when (s) and where the robot was
  std::vector<std::pair<double, double>> touching;  ///< spans of time (s) while something pressed its bumpers
  std::string failure;                              ///< why its controller failed; "" when it did not
  std::optional<std::string> returned;              ///< its top task's returned value, as its controller reports it
  double returnedAt = 0.0;                          ///< when the grader heard of it (trusted time), s
};

/// A finished run, as the grader judges it.
struct RunRecord {
  Vec2 size{10.0, 10.0};                  ///< the world's extent
  std::vector<worlds::WallDef> walls;     ///< every wall, the enclosure's too
  std::size_t enclosureWalls = 0;         ///< how many of `walls`, at the end, enclose the world
  std::vector<worlds::Landmark> points;   ///< the world's named points
  std::vector<worlds::KeyEventDef> keys;  ///< the world's key presses
  double dt = 0.01;
  std::vector<Track> robots;
  /// The run up to `seconds` (a shorter check judged on a longer run): later poses, contacts and results left out.
  [[nodiscard]] RunRecord upTo(double seconds) const;
};

/// A quantity a judge measures of one robot along a run, with the band a criterion wants it in:
/// what `frob run --assignment` adds to the trace and the run viewer.
struct Measured {
  std::string name;  ///< a column's name: "wall_distance", "clearance", "goal_distance"
  std::string unit;  ///< "m", "%"
  std::size_t robot = 0;
  double dt = 0.01;  ///< values[k] is at t = k × dt
  std::vector<double> values;
  std::optional<double> low, high;  ///< the band wanted; one side only for a bound
  bool everyInstant = true;         ///< the band holds at each instant (from `from` s); else once, or by the end
  double from = 0.0;                ///< seconds: the band holds from then on
};

/// Keeps a RunRecord as a run goes: made before the first step, told of every step and of every
/// task that ended.
class RunRecorder {
 public:
  RunRecorder(const worlds::Simulation& sim, const worlds::WorldDef& world);
  /// After each step: every robot's true pose, its bumper contacts and whether it is touching.
  void stepped(const worlds::Simulation& sim);
  /// Robot `i`'s task `ended` ended at `now`; a top task's returned value is kept.
  void taskEnded(std::size_t i, const TaskRecord& ended, double now);
  /// The record, with the controllers' failures.
  [[nodiscard]] RunRecord finish(const std::vector<worlds::ControllerFailure>& failures) &&;

 private:
  RunRecord record_;
};

}  // namespace frob::course
