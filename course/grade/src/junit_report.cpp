// JUnit XML, valid against the Apache Ant JUnit schema (tests/course/grade/junit/JUnit.xsd): a
// <testsuite> with name, timestamp, hostname, counts and time, then <properties>, the <testcase>s,
// <system-out> and <system-err>; each <testcase> with a time, each <failure> with a type. XML 1.0
// forbids most control characters, even escaped.

#include "frob/grade/grade_report.hpp"
#include "markup.hpp"
#include "writers.hpp"

#include <unistd.h>

#include <algorithm>
#include <charconv>

namespace frob::course {

using namespace detail;

namespace {

// Seconds with three decimals, as xs:decimal has them.
std::string seconds(double s) {
  char buf[32];
  return {buf, std::to_chars(buf, buf + sizeof buf, std::max(0.0, s), std::chars_format::fixed, 3).ptr};
}

std::string hostName() {
  char name[256] = {};
  return ::gethostname(name, sizeof name - 1) == 0 && name[0] != '\0' ? name : "localhost";
}

}  // namespace

Status writeJUnit(const Grade& g, const std::filesystem::path& path) {
  const std::string suite = markupEscape(g.assignment.empty() ? "assignment" : g.assignment, true);
  std::string cases;
  int tests = 0, failures = 0;
  // A failure's message is its reason, shown once; its text, what else there is to read (the
  // compiler's messages, the hints).
  auto testcase = [&](const std::string& name, double time, const char* type, const std::string& message, const std::string& text) {
    ++tests;
    cases += "  <testcase name=\"" + markupEscape(name, true) + "\" classname=\"" + suite + "\" time=\"" + seconds(time) + "\"";
    if (type == nullptr) {
      cases += "/>\n";
      return;
    }
    ++failures;
    cases += ">\n    <failure type=\"" + std::string(type) + "\" message=\"" + markupEscape(message, true) + "\">" + markupEscape(text) +
             "</failure>\n  </testcase>\n";
  };
  if (!g.compileError.empty()) testcase("compile", 0.0, "compile error", "the submission did not compile", g.compileError);
  for (const CheckGrade& c : g.checks) {
    if (c.runs.empty()) {
      const std::string why = g.compileError.empty() ? "not run" : "not run: the submission did not compile";
      testcase(c.name, 0.0, outcomeOf(c) == Outcome::Pass ? nullptr : "not run", why, "");
      continue;
    }
    for (std::size_t k = 0; k < c.runs.size(); ++k) {
      const RunGrade& r = c.runs[k];
      std::string hints;
      for (const std::string& h : c.hintsShown(k)) hints += "hint: " + h + "\n";
      const char* type = r.passed ? nullptr : r.reason.starts_with("the controller failed: ") ? "run failed" : "check failed";
      testcase(c.name + " / " + c.place(k), c.visibility == Visibility::Visible ? r.wallSeconds : 0.0, type, c.reasonShown(k), hints);
    }
  }
  std::string notes;
  for (const std::string& note : g.notes) notes += note + "\n";
  std::string xml = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  xml += "<testsuite name=\"" + suite + "\" timestamp=\"" + (g.startedAt.empty() ? "1970-01-01T00:00:00" : g.startedAt) + "\" hostname=\"" +
         markupEscape(hostName(), true) + "\" tests=\"" + std::to_string(tests) + "\" failures=\"" + std::to_string(failures) +
         "\" errors=\"0\" skipped=\"0\" time=\"" + seconds(g.shownSeconds()) + "\">\n";
  xml += "  <properties>\n";
  xml += "    <property name=\"submission\" value=\"" + markupEscape(g.submission, true) + "\"/>\n";
  xml += "    <property name=\"score\" value=\"" + number(g.score()) + "\"/>\n";
  xml += "    <property name=\"max_score\" value=\"" + number(g.maxScore()) + "\"/>\n";
  xml += "  </properties>\n";
  xml += cases;
  xml += "  <system-out>" + markupEscape(notes) + "</system-out>\n";
  xml += "  <system-err></system-err>\n";
  xml += "</testsuite>\n";
  return writeWhole(path, "junit report", xml);
}

}  // namespace frob::course
