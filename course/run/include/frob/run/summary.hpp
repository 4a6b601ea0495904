#pragma once
/// A run's summary as people read it and as JSON, with the wall time the caller measured.

#include "frob/run/session.hpp"

#include <string>
#include <string_view>

namespace frob::course {

/// The summary as a few lines of text; `wallSeconds` > 0 adds the wall time and real-time factor.
[[nodiscard]] std::string formatSummary(const Summary& summary, double wallSeconds);
/// The same as a JSON object (one line per field), ending with a newline.
[[nodiscard]] std::string summaryJson(const Summary& summary, double wallSeconds);

/// What frob says before a run or grade on a machine of architecture `machine` (uname's: "x86_64",
/// "aarch64"): nothing on amd64, whose bits the graders' are; elsewhere that its trajectories and
/// grades are not bit-identical to the grader's, and why.
[[nodiscard]] std::string determinismNote(std::string_view machine);

/// What frob says once it compiled controller `name` (with --check's checks when `checked`) in
/// `wallSeconds`, of which the compiler worked `cpuSeconds` (CPU time, its processes'): on a busy
/// machine, where the two differ much, that the rest was waiting, so that no one reads the wait
/// as the compile's cost.
[[nodiscard]] std::string compiledNote(std::string_view name, bool checked, double wallSeconds, double cpuSeconds);

}  // namespace frob::course
