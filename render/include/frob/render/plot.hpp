#pragma once
/// Plots: named signals over simulated time, with the instants where tasks switched.

#include "frob/picture.hpp"

#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace frob::render {

/// One sample of a signal.
struct Sample {
  double t = 0.0;      ///< simulated time, seconds
  double value = 0.0;  ///< in the signal's own unit
  friend bool operator==(const Sample&, const Sample&) = default;
};

/// A named signal; samples in increasing time; a value that is not finite is a gap in its line.
struct Series {
  std::string name;             ///< legend text, with its unit, e.g. "front sonar (m)"
  std::vector<Sample> samples;  ///< increasing t
  std::optional<Color> color;   ///< unset: picked from a palette by index
};

/// One chart: series sharing a value axis.
struct Plot {
  std::string title;           ///< drawn at its top left; may be empty
  std::vector<Series> series;  ///< drawn in order
  std::optional<double> yMin;  ///< unset: from the data
  std::optional<double> yMax;  ///< unset: from the data
  std::vector<double> levels;  ///< values marked across it, dashed (what an assignment wants)
};

/// An instant where a robot's task changed, marked as a vertical line.
struct TaskMark {
  double t = 0.0;    ///< simulated time, seconds
  std::string name;  ///< name of the task that starts
};

/// Charts stacked top to bottom over one shared time axis.
struct PlotSet {
  std::vector<Plot> plots;          ///< top to bottom
  std::vector<TaskMark> taskMarks;  ///< increasing t
  double tStart = 0.0;              ///< left end of the time axis, seconds
  double tEnd = 0.0;                ///< right end, seconds; if not above tStart, the last sample's time
};

/// Draw-everything cursor for renderPlots: all samples are shown.
inline constexpr double kWholeRun = std::numeric_limits<double>::infinity();

}  // namespace frob::render
