// What frob grade does when the failure is its own or the machine's, not the submission's: a host
// program that cannot start, a compiler that crashes. No score stands (never 0 as the student's),
// and the cause is named.
#include "../../support/unloadable_program.hpp"
#include "frob/grade/grade.hpp"
#include "frob/grade/grade_report.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

namespace frob::course {
namespace {

namespace fs = std::filesystem;

constexpr const char* kRubric = R"(title = "Stand"
seconds = 1
[[check]]
name = "stands"
points = 2
worlds = ["room.toml"]
seeds = [1, 2]
collisions = { max = 0 }
)";

constexpr const char* kStill =
    "#include <frob/frob.hpp>\nfrob::Behavior<frob::Wheels> still(const frob::Robot&) { return frob::wheels(0.0, 0.0); }\nFROB_CONTROLLER(still)\n";

class GraderFailure : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::path(::testing::TempDir()) / "grade_infrastructure_test" / ::testing::UnitTest::GetInstance()->current_test_info()->name();
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "assignment");
    std::ofstream(dir_ / "assignment" / "rubric.toml") << kRubric;
    std::ofstream(dir_ / "assignment" / "room.toml") << "size = [4.0, 3.0]\n[[robot]]\nname = \"ada\"\nstart = [1.0, 1.0]\n";
    std::ofstream(dir_ / "still.cpp") << kStill;
    Result<Rubric> rubric = loadRubric(dir_ / "assignment" / "rubric.toml");
    ASSERT_TRUE(rubric.ok()) << rubric.error();
    def_ = {.rubric = rubric.value(), .assignment = "stand"};
    def_.compiler.cacheDir = fs::path(FROB_TEST_CACHE_DIR);
  }
  fs::path dir_;
  GradeDef def_;
};

TEST_F(GraderFailure, AHostThatCannotStartIsNoGrade) {
  def_.host.program = frob::testing::unloadableProgram(dir_);
  const Grade g = grade(def_, dir_ / "still.cpp");
  EXPECT_NE(g.graderFailure.find("the grader failed: the controller host could not start: exit status 127"), std::string::npos) << g.graderFailure;
  ASSERT_EQ(g.checks.size(), 1u);
  EXPECT_EQ(g.checks[0].runs.size(), 1u) << "grading went on after the grader failed";
  // The gradebook gives it no score (not 0) and no maximum, and says why.
  ASSERT_TRUE(writeGradebook({g}, dir_ / "grades.csv").ok());
  std::ifstream in(dir_ / "grades.csv");
  std::string header, row;
  std::getline(in, header), std::getline(in, row);
  EXPECT_EQ(row.rfind((dir_ / "still.cpp").string() + ",,,NOT GRADED: the grader failed: the controller host could not start", 0), 0u) << row;
  EXPECT_EQ(row.back(), '\r');
  EXPECT_EQ(row.substr(row.size() - 2), ",\r") << "a check's column holds a score: " << row;
}

// clang crashes on purpose at `#pragma clang __debug crash` when frob does not disable it, as a
// compiler with a bug would; before it, more warnings than the output kept: the crash's own words,
// at the end, are kept.
TEST_F(GraderFailure, ACompilerCrashIsNoGradeAndItsEndIsKept) {
  std::vector<std::string>& flags = def_.compiler.flags;
  const auto disabled = std::find(flags.begin(), flags.end(), "-disable-pragma-debug-crash");
  ASSERT_NE(disabled, flags.end());
  flags.erase(disabled - 1, disabled + 1);  // with its -Xclang
  std::string source = "#include <frob/frob.hpp>\n";
  for (int i = 0; i < 12000; ++i) source += "#warning a long warning to push the crash past the first half of what is kept\n";
  source += "#pragma clang __debug crash\n";
  std::ofstream(dir_ / "crashes_clang.cpp") << source << kStill;
  const Grade g = grade(def_, dir_ / "crashes_clang.cpp");
  EXPECT_EQ(g.compileError, "");
  EXPECT_EQ(g.graderFailure.rfind("the grader failed: the compiler crashed compiling '", 0), 0u) << g.graderFailure.substr(0, 300);
  EXPECT_NE(g.graderFailure.find("bytes cut ...]"), std::string::npos);
  EXPECT_NE(g.graderFailure.find("PLEASE submit a bug report"), std::string::npos);
  // The whole command it prints names the grader's folders by name only.
  EXPECT_EQ(g.graderFailure.find(fs::absolute(def_.compiler.cacheDir).string()), std::string::npos);
  EXPECT_EQ(g.graderFailure.find(def_.compiler.precompiledHeader), std::string::npos);
  EXPECT_EQ(g.graderFailure.find("frob-compile-"), std::string::npos) << "the compiler's own folder";
  EXPECT_NE(g.graderFailure.find("-include-pch frob.pch"), std::string::npos);
  EXPECT_TRUE(g.checks.empty());
}

// What the source makes the compiler print, or a debug pragma it asks for, is the submission's: a
// compile that says "PLEASE submit a bug report" (a message, or a line of the source quoted with an
// error) but did not crash is graded as it compiled, never "not graded".
TEST_F(GraderFailure, ASubmissionCannotPassItselfOffAsACompilerCrash) {
  const std::string crashWords = "PLEASE submit a bug report to https://github.com/llvm/llvm-project/issues/";
  std::ofstream(dir_ / "says_it_crashed.cpp") << "#pragma message(\"" << crashWords << "\")\n" << kStill;
  std::ofstream(dir_ / "quotes_a_crash.cpp") << kStill << crashWords << "\nclang: error: clang frontend command failed due to signal\n";
  std::ofstream(dir_ / "asks_for_a_crash.cpp") << "#pragma clang __debug crash\n#pragma clang __debug llvm_fatal_error\n" << kStill;
  const Grade says = grade(def_, dir_ / "says_it_crashed.cpp");
  EXPECT_EQ(says.graderFailure, "");
  EXPECT_EQ(says.compileError, "");
  EXPECT_EQ(says.score(), 2.0);
  const Grade quotes = grade(def_, dir_ / "quotes_a_crash.cpp");
  EXPECT_EQ(quotes.graderFailure, "");
  EXPECT_NE(quotes.compileError.find(crashWords), std::string::npos) << quotes.compileError;
  const Grade asks = grade(def_, dir_ / "asks_for_a_crash.cpp");
  EXPECT_EQ(asks.graderFailure, "") << asks.graderFailure.substr(0, 300);
  EXPECT_EQ(asks.score(), 2.0);
}

}  // namespace
}  // namespace frob::course
