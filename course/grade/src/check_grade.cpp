// What a grade shows: a check's places, reasons, margins and hints (hidden checks say only what
// failed), a leaderboard's value, and the score.
#include "frob/grade/grade.hpp"

#include <algorithm>
#include <string>
#include <vector>

namespace frob::course {

std::string CheckGrade::place(std::size_t k) const {
  if (visibility != Visibility::Visible) return "hidden world " + std::to_string(k + 1);
  return runs.at(k).world + ", seed " + std::to_string(runs.at(k).seed);
}

std::string CheckGrade::reasonShown(std::size_t k) const {
  if (visibility == Visibility::Visible) return runs.at(k).reason;
  return runs.at(k).kind + " (hidden worlds give no details: practise with frob grade --practice)";
}

std::string CheckGrade::output() const {
  std::string out;
  for (std::size_t k = 0; k < runs.size(); ++k) {
    if (!runs[k].passed) {
      out += "in " + place(k) + ": " + reasonShown(k) + "\n";
      for (const std::string& h : hintsShown(k)) out += "  hint: " + h + "\n";
    }
    if (const std::string m = marginsShown(k); !m.empty()) out += (runs[k].passed ? "in " + place(k) + ": margins: " : "  margins: ") + m + "\n";
  }
  return out;
}

std::string CheckGrade::marginsShown(std::size_t k) const {
  std::string shown;
  if (visibility != Visibility::Visible) return shown;
  for (const CriterionVerdict& v : runs.at(k).criteria) {
    if (v.margin) shown += (shown.empty() ? "" : "; ") + v.criterion + " " + v.margin->said(v.passed);
  }
  return shown;
}

std::vector<std::string> CheckGrade::hintsShown(std::size_t k) const {
  std::vector<std::string> shown;
  if (visibility == Visibility::Visible) shown = runs.at(k).hints;
  return shown;
}

LeaderboardValue leaderboardValue(const LeaderboardMetric& m, const Grade& g) {
  LeaderboardValue v{.name = m.name, .ascending = m.ascending};
  const auto check = std::find_if(g.checks.begin(), g.checks.end(), [&](const CheckGrade& c) { return c.name == m.check; });
  if (check == g.checks.end() || check->runs.empty()) return v;
  double sum = 0.0;
  for (const RunGrade& r : check->runs) {
    const auto found =
        std::find_if(r.criteria.begin(), r.criteria.end(), [&](const CriterionVerdict& c) { return c.criterion == toString(m.criterion); });
    if (found == r.criteria.end() || !found->passed || !found->margin) return v;
    const std::optional<double> measure = m.measure == LeaderboardMetric::Measure::Time ? found->margin->at : found->margin->value;
    if (!measure) return v;
    sum += *measure;
  }
  v.value = sum / static_cast<double>(check->runs.size());
  return v;
}

double Grade::score() const {
  double s = 0;
  for (const CheckGrade& c : checks) s += c.score;
  return s - latePenalty;
}

double Grade::maxScore() const {
  double s = 0;
  for (const CheckGrade& c : checks) s += c.points;
  return s;
}

double Grade::shownSeconds() const {
  double s = wallSeconds;
  for (const CheckGrade& c : checks) {
    if (c.visibility == Visibility::Visible) continue;
    for (const RunGrade& r : c.runs) s -= r.wallSeconds;
  }
  return std::max(0.0, s);
}

}  // namespace frob::course
