#pragma once
// Grading a submission against one of assignments/<name>/ as an instructor would, hidden checks
// included: the hidden seeds come from a test secret (never an instructor's).
#include "frob/course/grade.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <string>

namespace frob::testing {

inline constexpr const char* kTestSecret = "ci-test-secret";

inline course::Grade gradeAssignment(const std::string& assignment, const std::filesystem::path& submission) {
  Result<course::Rubric> rubric = course::loadRubric(std::filesystem::path(FROB_ASSIGNMENTS_DIR) / assignment / "rubric.toml");
  EXPECT_TRUE(rubric.ok()) << rubric.error();
  course::GradeDef def{.rubric = rubric.value(), .assignment = assignment, .secret = kTestSecret};
  def.compiler.cacheDir = FROB_TEST_CACHE_DIR;
  return course::grade(def, submission);
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
