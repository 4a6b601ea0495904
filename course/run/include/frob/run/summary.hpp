#pragma once
/// A run's summary as people read it and as JSON, with the wall time the caller measured.

#include "frob/run/session.hpp"

#include <string>

namespace frob::course {

/// The summary as a few lines of text; `wallSeconds` > 0 adds the wall time and real-time factor.
[[nodiscard]] std::string formatSummary(const Summary& summary, double wallSeconds);
/// The same as a JSON object (one line per field), ending with a newline.
[[nodiscard]] std::string summaryJson(const Summary& summary, double wallSeconds);

}  // namespace frob::course
