// The hostile submissions of tests/course/sandbox/hostile/, graded through frob grade: each fails the check
// that runs past its misbehaviour with the reason, the check that ends before it is still graded,
// and results.json and the JUnit file are whole and valid.
#include "run_frob.hpp"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

namespace frob::testing {
namespace {

namespace fs = std::filesystem;

// Each submission misbehaves from 0.5 s on: "before" ends at 0.4 s, "after" runs 2 s.
constexpr const char* kRubric = R"(title = "Hostile"
[[check]]
name = "before"
points = 1
worlds = ["room.toml"]
seconds = 0.4
collisions = { max = 0 }
[[check]]
name = "after"
points = 1
worlds = ["room.toml"]
seconds = 2
collisions = { max = 0 }
)";

struct Case {
  std::string submission;
  std::string reason;        // in the failed check's output
  std::string orReason;      // another true reason, when the machine's speed decides which comes first
  bool beforePasses = true;  // false when it fails before the first step (a global constructor)
};
void PrintTo(const Case& c, std::ostream* os) { *os << c.submission; }

class GradeHostile : public ::testing::TestWithParam<Case> {};

TEST_P(GradeHostile, FailsItsCheckWithTheReasonAndTheGraderStaysWhole) {
  const Case& c = GetParam();
  const fs::path dir = freshFolder("grade_hostile_" + c.submission);
  fs::create_directories(dir / "hostile");
  std::ofstream(dir / "hostile" / "rubric.toml") << kRubric;
  std::ofstream(dir / "hostile" / "room.toml") << "size = [4.0, 3.0]\n[[robot]]\nname = \"ada\"\nstart = [1.0, 1.0]\n";
  const fs::path source = fs::path(FROB_HOSTILE_DIR) / (c.submission + ".cpp");
  const FrobResult r = runFrob(dir, {"grade", "hostile", source.string(), "--results", "results.json", "--junit", "junit.xml"});
  ASSERT_EQ(r.status, 0) << r.err << r.out;
  const nlohmann::json results = nlohmann::json::parse(readFile(dir / "results.json"));
  ASSERT_EQ(results["tests"].size(), 2u) << results.dump(1);
  EXPECT_EQ(results["tests"][0]["score"], c.beforePasses ? 1.0 : 0.0) << results.dump(1);
  EXPECT_EQ(results["tests"][1]["score"], 0.0) << results.dump(1);
  const std::string output = markdownRead(results["tests"][1]["output"]);
  EXPECT_TRUE(output.find(c.reason) != std::string::npos || (!c.orReason.empty() && output.find(c.orReason) != std::string::npos)) << results.dump(1);
  const std::string junit = readFile(dir / "junit.xml");
  EXPECT_EQ(junit.rfind("<?xml", 0), 0u);
  EXPECT_NE(junit.find("</testsuite>"), std::string::npos);
  EXPECT_EQ(junit.find(c.beforePasses ? "failures=\"2\"" : "failures=\"0\""), std::string::npos) << junit;
}

INSTANTIATE_TEST_SUITE_P(
    Grade, GradeHostile,
    ::testing::Values(
        Case{"segfault", "crashed with SIGSEGV"}, Case{"abort", "crashed with SIGABRT"}, Case{"stack_overflow", "its stack overflowed"},
        Case{"endless_loop", "used more than 1 s of CPU in one step"},
        Case{"sleeps",
             "did not answer within 1 s in one step"},  // Filling 1 GiB of fresh pages can take more than the 1 s a step may take on a busy machine.
        Case{"memory_bomb", "memory", "used more than 1 s of CPU in one step"}, Case{"forks", "tried to start another process"},
        Case{"runs_shell", "tried to start another process"}, Case{"opens_socket", "tried to open a network socket"},
        Case{"signals_parent", "tried to signal another process"}, Case{"reads_outside", "tried to read /etc/passwd"},
        Case{"writes_outside", "tried to write /tmp/frob-hostile-was-here"}, Case{"forged_exit", "ended its program with exit status 0"},
        Case{"throws_int", "an exception of unknown type"}, Case{"commands_nan", "non-finite wheels"},
        Case{"sleeps_each_step", "fell behind: it took"},
        Case{"endless_constructor", "did not finish starting within 10 s (an endless loop?)", "", false},
        Case{"crash_in_constructor", "crashed with SIGSEGV", "", false}),
    [](const ::testing::TestParamInfo<Case>& info) { return info.param.submission; });

// A class with attacks in it, graded two at a time: every submission gets its line in the
// gradebook, the harmless one its marks, and no scratch folder is left behind.
TEST(GradeHostileClass, AClassWithAttacksInItWritesItsWholeGradebook) {
  const fs::path dir = freshFolder("grade_hostile_class");
  fs::create_directories(dir / "hostile");
  std::ofstream(dir / "hostile" / "rubric.toml") << kRubric;
  std::ofstream(dir / "hostile" / "room.toml") << "size = [4.0, 3.0]\n[[robot]]\nname = \"ada\"\nstart = [1.0, 1.0]\n";
  const std::vector<std::string> attacks{"truncates_channel", "forges_records", "fills_scratch", "starts_many_threads",
                                         "segfault",          "memory_bomb",    "shares_memory", "writes_scratch"};
  fs::create_directories(dir / "class");
  for (const std::string& a : attacks) fs::copy_file(fs::path(FROB_HOSTILE_DIR) / (a + ".cpp"), dir / "class" / (a + ".cpp"));
  fs::copy_file(fs::path(FROB_HOSTILE_DIR) / "misbehave.hpp", dir / "class" / "misbehave.hpp");
  const fs::path temp = dir / "tmp";
  fs::create_directories(temp);
  const FrobResult r = runFrob(dir, {"grade", "hostile", "class", "--jobs", "2", "--gradebook", "grades.csv"}, FROB_TEST_CACHE_DIR, temp);
  ASSERT_EQ(r.status, 0) << r.err << r.out;
  const std::string csv = readFile(dir / "grades.csv");
  for (const std::string& a : attacks) EXPECT_NE(csv.find("class/" + a + ".cpp,"), std::string::npos) << a << "\n" << csv;
  EXPECT_NE(csv.find("class/writes_scratch.cpp,2,2"), std::string::npos) << csv;
  EXPECT_NE(csv.find("class/segfault.cpp,1,2"), std::string::npos) << csv;
  EXPECT_TRUE(fs::is_empty(temp)) << "a scratch folder was left in " << temp;
}

}  // namespace
}  // namespace frob::testing
