#pragma once
/// Judging a finished run against a rubric's criteria, from what the trusted simulation recorded
/// of each robot (run_record.hpp).

#include "frob/grade/rubric.hpp"
#include "frob/run/run_record.hpp"

#include <string>

namespace frob::course {

/// Whether a run met a criterion and, if not, why, in words a student can act on.
struct Verdict {
  bool passed = false;
  std::string reason;  ///< "" when passed
};

/// Judges `run` against `criterion` for every robot (the first robot that fails it gives the reason).
[[nodiscard]] Verdict judge(const Criterion& criterion, const RunRecord& run);

}  // namespace frob::course
