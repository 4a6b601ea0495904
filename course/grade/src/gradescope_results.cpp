// Gradescope's autograder results.json, as its specification says
// (https://gradescope-autograders.readthedocs.io/en/latest/specs/; gradescope/autograder_samples,
// docs/specs.md): "status" is "passed" or "failed", "visibility" one of "hidden", "after_due_date",
// "after_published", "visible"; the top-level output defaults to "simple_format" (HTML), so we say "text";
// a test's output is markdown ("md"); "leaderboard" entries are {name, value, order}; "extra_data" is
// kept for staff and never shown.

#include "frob/grade/grade_report.hpp"
#include "frob/run/format.hpp"
#include "writers.hpp"

#include <algorithm>
#include <cctype>
#include <cinttypes>
#include <cmath>
#include <set>

namespace frob::course {

using namespace detail;

namespace {

// `text` as literal markdown: every ASCII punctuation character escaped (CommonMark allows it before
// any), so nothing a controller names becomes a link, an image, markup or a heading.
std::string markdownText(const std::string& text) {
  std::string out;
  for (char ch : text) {
    if (std::ispunct(static_cast<unsigned char>(ch)) != 0) out += '\\';
    out += ch == '\n' ? ' ' : ch;
  }
  return out;
}

// A check's output as markdown: a line per run with its outcome, reason, hints and margins.
std::string markdownOutput(const CheckGrade& c) {
  std::string md;
  for (std::size_t k = 0; k < c.runs.size(); ++k) {
    const RunGrade& r = c.runs[k];
    md += "- **" + markdownText(c.place(k)) + "**: " + (r.passed ? "passed" : "failed: " + markdownText(c.reasonShown(k))) + "\n";
    for (const std::string& h : c.hintsShown(k)) md += "  - hint: " + markdownText(h) + "\n";
    if (const std::string m = c.marginsShown(k); !m.empty()) md += "  - margins: " + markdownText(m) + "\n";
  }
  return md;
}

}  // namespace

Status writeGradescope(const Grade& g, const std::filesystem::path& path) {
  Json doc;
  doc["score"] = rounded(g.score());
  doc["execution_time"] = std::llround(g.shownSeconds());
  doc["output"] = summaryOf(g);
  doc["output_format"] = "text";
  Json tests = Json::array();
  for (const CheckGrade& c : g.checks) {
    Json t;
    t["name"] = c.name;
    t["score"] = rounded(c.score);
    t["max_score"] = rounded(c.points);
    t["status"] = outcomeOf(c) == Outcome::Pass ? "passed" : "failed";
    t["output"] = markdownOutput(c);
    t["output_format"] = "md";
    t["visibility"] = toString(c.visibility);
    Json tags = Json::array();
    std::set<std::string> seen;
    for (const RunGrade& r : c.runs) {  // the worlds of a check that is not visible are not named
      if (c.visibility == Visibility::Visible && seen.insert(r.world).second) tags.push_back(r.world);
    }
    t["tags"] = std::move(tags);
    tests.push_back(std::move(t));
  }
  doc["tests"] = std::move(tests);
  Json board = Json::array();
  for (const LeaderboardValue& v : g.leaderboard) {  // a submission that missed the criterion has no place on that board
    if (v.value) board.push_back(Json{{"name", v.name}, {"value", std::round(*v.value * 1000) / 1000}, {"order", v.ascending ? "asc" : "desc"}});
  }
  if (!board.empty()) doc["leaderboard"] = std::move(board);
  // Gradescope returns results.json alone: the graded trajectories' hashes stay with it, so that a
  // regrade elsewhere (frob grade --logs, then --replay) can be shown to be of the same runs.
  Json runs = Json::array();
  for (const CheckGrade& c : g.checks) {
    for (std::size_t k = 0; k < c.runs.size(); ++k) {
      runs.push_back(Json{{"check", c.name}, {"run", c.place(k)}, {"trajectory", format("%016" PRIx64, c.runs[k].trajectoryHash)}});
    }
  }
  doc["extra_data"] = Json{{"submission_sha256", g.submissionHash}, {"runs", std::move(runs)}};
  return writeWhole(path, "gradescope results", jsonText(doc));
}

}  // namespace frob::course
