// Copies found as a reader of copies finds them: a solution renamed, reformatted and reordered is
// the same code; independent solutions of one assignment are not; runs the same to the last bit in
// every graded world are flagged unless half the class has them.
#include "frob/grade/similarity.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <regex>
#include <sstream>

namespace frob::course {
namespace {

namespace fs = std::filesystem;

std::string readFile(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The share of the smaller one's fingerprints the two have in common.
double shared(std::string_view a, std::string_view b) {
  const std::vector<std::uint64_t> x = codeFingerprints(a), y = codeFingerprints(b);
  std::vector<std::uint64_t> both;
  std::set_intersection(x.begin(), x.end(), y.begin(), y.end(), std::back_inserter(both));
  return static_cast<double>(both.size()) / static_cast<double>(std::min(x.size(), y.size()));
}

std::vector<SimilarPair> pairsOf(const std::vector<std::pair<std::string, std::string>>& texts) {
  std::vector<StudentWork> work;
  for (const auto& [student, text] : texts) work.push_back({student, codeFingerprints(text), {}});
  return similarPairs(work);
}

const fs::path kAssignments = FROB_ASSIGNMENTS_DIR;

TEST(Similarity, ACopyIsTheSameCodeUpToNamesLayoutCommentsAndOrder) {
  const std::string original = readFile(kAssignments / "bug" / "solution.cpp");
  ASSERT_GT(original.size(), 2000u);
  // Every name of its own renamed, every comment gone, the layout squeezed, the functions in reverse order.
  std::string copy = std::regex_replace(original, std::regex(R"(//[^\n]*)"), "");
  copy = std::regex_replace(
      copy, std::regex(R"(\b(bug|goAround|wallOnLeft|blockedAhead|roomAhead|faceGoal|recoverFrom|driveTo|followWall|circleOnce|goal|g)\b)"),
      "my_$1_renamed");
  std::vector<std::string> parts;
  for (std::size_t at = 0; at < copy.size();) {
    const std::size_t end = copy.find("\n}\n", at);
    parts.push_back(copy.substr(at, end == std::string::npos ? std::string::npos : end + 3 - at));
    at = end == std::string::npos ? copy.size() : end + 3;
  }
  ASSERT_GT(parts.size(), 4u);
  std::reverse(parts.begin() + 1, parts.end());
  std::string reordered;
  for (const std::string& p : parts) reordered += std::regex_replace(p, std::regex(R"(\n +)"), "\n\t  ");
  const std::vector<SimilarPair> flagged = pairsOf({{"alice", original}, {"bob", reordered}});
  ASSERT_EQ(flagged.size(), 1u);
  EXPECT_EQ(flagged[0].a, "alice");
  EXPECT_EQ(flagged[0].kind, "code");
  EXPECT_GT(flagged[0].score, 0.8) << flagged[0].evidence;
}

TEST(Similarity, IndependentSolutionsOfOneAssignmentAreNotFlagged) {
  // The assignments' solutions and the course's examples of the same skills, written apart in the
  // same style with the same names of the paper (measured: 0.15 to 0.38 shared; a renamed copy 0.93).
  // (The BUG solution and example share 75 lines word for word: 0.48.)
  const fs::path examples = FROB_EXAMPLES_DIR;
  for (const auto& [a, b] : {std::pair{kAssignments / "wall_follow" / "solution.cpp", examples / "02_wall_follower.cpp"},
                             {kAssignments / "go_to_goal" / "solution.cpp", examples / "04_drive_to.cpp"},
                             {kAssignments / "wander" / "solution.cpp", examples / "01_run_around.cpp"},
                             {kAssignments / "wander" / "solution.cpp", kAssignments / "wall_follow" / "solution.cpp"}}) {
    EXPECT_LT(shared(readFile(a), readFile(b)), 0.4) << a << " and " << b;
    EXPECT_TRUE(pairsOf({{"a", readFile(a)}, {"b", readFile(b)}}).empty()) << a << " and " << b;
  }
}

TEST(Similarity, RunsTheSameToTheLastBitAreFlaggedUnlessCommon) {
  std::vector<StudentWork> work{{"ann", {}, {1, 2, 3}}, {"ben", {}, {1, 2, 3}}, {"cat", {}, {5, 6, 4}}, {"dan", {}, {9, 9, 9}}};
  std::vector<SimilarPair> pairs = similarPairs(work);
  ASSERT_EQ(pairs.size(), 1u);
  EXPECT_EQ(pairs[0].a + " " + pairs[0].b + " " + pairs[0].kind, "ann ben behaviour");
  EXPECT_EQ(pairs[0].evidence, "the same trajectory, to the last bit, in all 3 graded runs");
  // Three students who never move share every run: no sign of copying.
  for (const char* s : {"eve", "fay", "gus"}) work.push_back({s, {}, {7, 7, 7}});
  work.push_back({"hal", {}, {7, 7, 7}});
  pairs = similarPairs(work);
  EXPECT_EQ(pairs.size(), 1u);
}

}  // namespace
}  // namespace frob::course
