#pragma once
/// Judging a finished run against a rubric's criteria, from what the trusted simulation recorded
/// of each robot: its true path, its contacts, and its controller's failure or returned value.

#include "frob/grade/rubric.hpp"
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
};

/// Whether a run met a criterion and, if not, why, in words a student can act on.
struct Verdict {
  bool passed = false;
  std::string reason;  ///< "" when passed
};

/// Judges `run` against `criterion` for every robot (the first robot that fails it gives the reason).
[[nodiscard]] Verdict judge(const Criterion& criterion, const RunRecord& run);

}  // namespace frob::course
