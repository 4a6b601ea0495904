#pragma once
/// Judging a finished run against a rubric's criteria, from what the trusted simulation recorded
/// of each robot (run_record.hpp).

#include "frob/grade/rubric.hpp"
#include "frob/run/run_record.hpp"

#include <optional>
#include <string>
#include <vector>

namespace frob::course {

/// How near the edge a run met or missed a criterion: what the judge measured against what it
/// requires, for the robot nearest the edge.
struct Margin {
  double value = 0.0;        ///< by how much it passed (> 0, or 0 on the edge) or failed (< 0), in `unit`
  std::string unit;          ///< "m", "s", "m/s", "points" (percentage points of a share) or "collisions"
  std::string text;          ///< the measure and the requirement: "reached goal at 7.6 s of 10 s"
  std::optional<double> at;  ///< the instant that decided it, seconds: the closest call, the failure
  /// The value without its sign, in its unit: "2.4 s", "0.05 m", "12 percentage points".
  [[nodiscard]] std::string amount() const;
  /// "passed by 2.4 s" or "failed by 0.05 m", then the text in brackets.
  [[nodiscard]] std::string said(bool passed) const;
};

/// Whether a run met a criterion and, if not, why, in words a student can act on.
struct Verdict {
  bool passed = false;
  std::string reason;            ///< "" when passed
  std::optional<Margin> margin;  ///< none where nothing was measured (no such point, no event)
};

/// Judges `run` against `criterion` for every robot (the first robot that fails it gives the reason).
[[nodiscard]] Verdict judge(const Criterion& criterion, const RunRecord& run);

/// How a run met one criterion of one check.
struct CriterionVerdict {
  std::string check;      ///< the check's name
  std::string criterion;  ///< as the rubric names it: "waypoints", "collisions"
  double seconds = 0.0;   ///< of the run judged: the check's, or the whole run when it is shorter
  bool passed = false;
  std::string reason;  ///< why it failed, as a grade says it; "" when it passed
  std::optional<Margin> margin;
};
/// The checks of `rubric` that run in `world` (a world file or a reference world's name); all of
/// them when none does (a world of the student's own).
[[nodiscard]] std::vector<Check> checksFor(const Rubric& rubric, const std::string& world);
/// Every criterion of `checks`, judged on `record` as a grade judges a run of the check (on the
/// run's first `Check::seconds`): what `frob run --assignment` tells a student of a run. A controller
/// that failed fails them all, with its reason.
[[nodiscard]] std::vector<CriterionVerdict> judgeChecks(const std::vector<Check>& checks, const RunRecord& record);

/// The quantities `checks`' criteria measure along `record`, each robot's once (the first criterion
/// that measures it gives its band): a wall's distance, the clearance, the distance to a point to
/// reach, the floor covered so far, the nearest other robot.
[[nodiscard]] std::vector<Measured> measuredAlong(const std::vector<Check>& checks, const RunRecord& record);

}  // namespace frob::course
