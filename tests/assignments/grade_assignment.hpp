#pragma once
// Grading a submission against one of assignments/<name>/ as an instructor would, hidden checks
// included: the hidden seeds come from a test secret (never an instructor's).
#include "frob/grade/grade.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <sstream>
#include <string>

namespace frob::testing {

inline constexpr const char* kTestSecret = "ci-test-secret";

// `submission` graded against `assignment`, which it must compile for.
inline course::Grade gradeFile(const std::string& assignment, const std::filesystem::path& submission) {
  Result<course::Rubric> rubric = course::loadRubric(std::filesystem::path(FROB_ASSIGNMENTS_DIR) / assignment / "rubric.toml");
  EXPECT_TRUE(rubric.ok()) << rubric.error();
  // Every submission in the same hidden worlds (the first fair ones), not worlds of its own: the
  // expected scores of these tests then name worlds, not a hash of the file's bytes.
  for (course::Check& c : rubric.value().checks) {
    if (c.generated) c.generated->pool = c.generated->secret;
  }
  course::GradeDef def{.rubric = rubric.value(), .assignment = assignment, .secret = kTestSecret};
  def.compiler.cacheDir = FROB_TEST_CACHE_DIR;
  course::Grade g = course::grade(def, submission);
  EXPECT_EQ(g.compileError, "") << submission;
  return g;
}

// What the grader told the student about `check`'s failed runs (a line each, and their hints; the
// margins every run is told left out), "" when it passed.
inline std::string reasons(const course::Grade& g, const std::string& check) {
  for (const course::CheckGrade& c : g.checks) {
    if (c.name != check) continue;
    std::istringstream lines(c.output());
    std::string told;
    for (std::string line; std::getline(lines, line);) {
      if (line.find("margins: ") == std::string::npos) told += line + "\n";
    }
    return told;
  }
  ADD_FAILURE() << "no check named '" << check << "'";
  return "";
}

// Why each run of `check` failed, as the instructor reads it (a student reads only what failed in a
// check that is not visible): "in hidden world 2: <reason>", its hints below.
inline std::string judged(const course::Grade& g, const std::string& check) {
  for (const course::CheckGrade& c : g.checks) {
    if (c.name != check) continue;
    std::string out;
    for (std::size_t k = 0; k < c.runs.size(); ++k) {
      if (c.runs[k].passed) continue;
      out += "in " + c.place(k) + ": " + c.runs[k].reason + "\n";
      for (const std::string& h : c.runs[k].hints) out += "  hint: " + h + "\n";
    }
    return out;
  }
  ADD_FAILURE() << "no check named '" << check << "'";
  return "";
}

// The worlds of the failed runs of a check, one per line, as the instructor sees them (a student reads
// "hidden world 2" for a check that is not visible).
inline std::string failedIn(const course::Grade& g, const std::string& check) {
  std::string worlds;
  for (const course::CheckGrade& c : g.checks) {
    if (c.name != check) continue;
    for (const course::RunGrade& r : c.runs) worlds += r.passed ? "" : r.world + "\n";
    return worlds;
  }
  ADD_FAILURE() << "no check named '" << check << "'";
  return "";
}

inline std::filesystem::path assignmentFile(const std::string& assignment, const std::string& file) {
  return std::filesystem::path(FROB_ASSIGNMENTS_DIR) / assignment / file;
}
inline std::filesystem::path wrongSubmission(const std::string& assignment, const std::string& file) {
  return std::filesystem::path(FROB_WRONG_DIR) / assignment / file;
}
inline std::filesystem::path example(const std::string& file) { return std::filesystem::path(FROB_EXAMPLES_DIR) / file; }

// Each check's score by name, to compare with what a submission should get.
inline std::map<std::string, double> scores(const course::Grade& g) {
  std::map<std::string, double> out;
  for (const course::CheckGrade& c : g.checks) out[c.name] = c.score;
  return out;
}

}  // namespace frob::testing
