// Gradescope's autograder results.json, as its specification says
// (https://gradescope-autograders.readthedocs.io/en/latest/specs/; gradescope/autograder_samples,
// docs/specs.md): "status" is "passed" or "failed", "visibility" one of "hidden", "after_due_date",
// "after_published", "visible"; the top-level output defaults to "simple_format" (HTML), so we say "text".

#include "frob/grade/grade_report.hpp"
#include "writers.hpp"

#include <algorithm>
#include <cmath>
#include <set>

namespace frob::course {

using namespace detail;

Status writeGradescope(const Grade& g, const std::filesystem::path& path) {
  Json doc;
  doc["score"] = rounded(g.score());
  doc["execution_time"] = std::llround(std::max(0.0, g.wallSeconds));
  doc["output"] = summaryOf(g);
  doc["output_format"] = "text";
  Json tests = Json::array();
  for (const CheckGrade& c : g.checks) {
    Json t;
    t["name"] = c.name;
    t["score"] = rounded(c.score);
    t["max_score"] = rounded(c.points);
    t["status"] = outcomeOf(c) == Outcome::Pass ? "passed" : "failed";
    t["output"] = c.output();
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
  return writeWhole(path, "gradescope results", jsonText(doc));
}

}  // namespace frob::course
