// JUnit XML, as the Jenkins/Surefire schema junit-10.xsd has it (<testsuite> needs name, tests,
// failures, errors; time with at most three decimals); XML 1.0 forbids most control characters, even
// escaped.

#include "frob/grade/grade_report.hpp"
#include "markup.hpp"
#include "writers.hpp"

#include <algorithm>
#include <charconv>

namespace frob::course {

using namespace detail;

Status writeJUnit(const Grade& g, const std::filesystem::path& path) {
  const std::string suite = markupEscape(g.assignment, true);
  std::string cases;
  int tests = 0, failures = 0;
  auto testcase = [&](const std::string& name, const std::string* failure, const std::string& message) {
    ++tests;
    cases += "  <testcase name=\"" + markupEscape(name, true) + "\" classname=\"" + suite + "\"";
    if (failure == nullptr) {
      cases += "/>\n";
      return;
    }
    ++failures;
    cases += ">\n    <failure message=\"" + markupEscape(message, true) + "\">" + markupEscape(*failure) + "</failure>\n  </testcase>\n";
  };
  if (!g.compileError.empty()) testcase("compile", &g.compileError, "the submission did not compile");
  for (const CheckGrade& c : g.checks) {
    if (c.runs.empty()) {
      const std::string why = g.compileError.empty() ? "not run" : "not run: the submission did not compile";
      testcase(c.name, outcomeOf(c) == Outcome::Pass ? nullptr : &why, why);
      continue;
    }
    for (std::size_t k = 0; k < c.runs.size(); ++k) {
      const std::string why = c.reasonShown(k);
      testcase(c.name + " / " + c.place(k), c.runs[k].passed ? nullptr : &why, why);
    }
  }
  char buf[32];
  const std::string seconds(buf, std::to_chars(buf, buf + sizeof buf, std::max(0.0, g.wallSeconds), std::chars_format::fixed, 3).ptr);
  std::string xml = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  xml += "<testsuite name=\"" + suite + "\" tests=\"" + std::to_string(tests) + "\" failures=\"" + std::to_string(failures) +
         "\" errors=\"0\" skipped=\"0\" time=\"" + seconds + "\">\n";
  xml += cases;
  if (!g.notes.empty()) {
    std::string notes;
    for (const std::string& note : g.notes) notes += note + "\n";
    xml += "  <system-out>" + markupEscape(notes) + "</system-out>\n";
  }
  xml += "</testsuite>\n";
  return writeWhole(path, "junit report", xml);
}

}  // namespace frob::course
