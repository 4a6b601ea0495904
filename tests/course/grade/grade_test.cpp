// frob grade's engine: real submissions compiled, run in the sandboxed host, scored from the true
// trajectory; the same grade twice; each run's wheel log replayed to the same verdict bit for bit.
#include "frob/grade/grade.hpp"

#include "frob/run/format.hpp"
#include "frob/run/host.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace frob::course {
namespace {

namespace fs = std::filesystem;

// A 6 x 4 m room: the robot at (1, 2) facing the goal at (5, 2), with a little odometry drift, so
// that each seed drives a slightly different path.
constexpr const char* kWorld = R"(size = [6.0, 4.0]
seed = 9
[odometry]
translation = 0.02
[points]
goal = [5.0, 2.0]
[[robot]]
name = "nomad"
start = [1.0, 2.0]
)";

constexpr const char* kRubric = R"(title = "Drive to the goal"
seconds = 20

[[check]]
name = "reaches the goal"
points = 4
worlds = ["worlds/field.toml"]
seeds = [1, 2]
goal = { within = 0.3, by = 20 }
collisions = { max = 0 }

[[check]]
name = "stops there"
points = 2
visibility = "hidden"
worlds = ["worlds/field.toml"]
secret_seeds = 1
stopped = { speed = 0.05 }

[[check]]
name = "reports success"
points = 1
visibility = "after_due_date"
worlds = ["worlds/field.toml"]
returns = { value = true }

[[check]]
name = "survives generated rooms"
points = 1
visibility = "hidden"
seconds = 5
generated = { kind = "rooms", seeds = [3], secret = 1 }
collisions = { max = 1000 }

[[leaderboard]]
name = "Seconds to the goal"
check = "reaches the goal"
criterion = "goal"
measure = "time"
)";

// Drives ahead until odometry says x > 4.8, then returns true (and the robot stops).
constexpr const char* kGood = R"(#include <frob/frob.hpp>
using namespace frob;
Task<Wheels, bool> toGoal() {
  co_await mkTask([](const TaskState& ts) {
    return std::pair{wheels(0.4, 0.0), predicate(lift([](Point2 p) { return p.x() > 4.8; }, place(ts.robot())))};
  });
  co_return true;
}
FROB_CONTROLLER(toGoal)
)";

constexpr const char* kCrash = R"(#include <frob/frob.hpp>
using namespace frob;
Behavior<Wheels> crash(const Robot&) {
  return toBehavior(lift([](double t) { if (t > 1.0) *static_cast<volatile int*>(nullptr) = 1; return Wheels{0.4, 0.0}; }, time()));
}
FROB_CONTROLLER(crash)
)";

// Stands still, printing "a run" at its first step.
constexpr const char* kTalks = R"(#include <frob/frob.hpp>
#include <cstdio>
using namespace frob;
Behavior<Wheels> talks(const Robot&) {
  return toBehavior(lift([](double t) { if (t == 0.0) std::printf("a run\n"); return Wheels{0.0, 0.0}; }, time()));
}
FROB_CONTROLLER(talks)
)";

class Grading : public ::testing::Test {
 protected:
  void SetUp() override {
    // A folder of its own: ctest runs the tests of this file at the same time.
    dir_ = fs::path(::testing::TempDir()) / "grade_test" / ::testing::UnitTest::GetInstance()->current_test_info()->name();
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "assignment" / "worlds");
    std::ofstream(dir_ / "assignment" / "worlds" / "field.toml") << kWorld;
    std::ofstream(dir_ / "assignment" / "rubric.toml") << kRubric;
    std::ofstream(dir_ / "good.cpp") << kGood;
    std::ofstream(dir_ / "crash.cpp") << kCrash;
    std::ofstream(dir_ / "broken.cpp") << "#include <frob/frob.hpp>\nthis is not C++\n";
    Result<Rubric> rubric = loadRubric(dir_ / "assignment" / "rubric.toml");
    ASSERT_TRUE(rubric.ok()) << rubric.error();
    def_ = {.rubric = rubric.value(), .assignment = "drive", .secret = "test-secret"};
    def_.compiler.cacheDir = fs::path(FROB_TEST_CACHE_DIR);
  }
  fs::path dir_;
  GradeDef def_;
};

TEST_F(Grading, AGoodSubmissionGetsFullMarks) {
  const Grade g = grade(def_, dir_ / "good.cpp");
  EXPECT_EQ(g.compileError, "");
  ASSERT_EQ(g.checks.size(), 4u);
  // The visible check says how near the edge each run was; the others say nothing (a margin is a
  // number the controller could choose).
  EXPECT_EQ(g.checks[0].output(),
            "in worlds/field.toml, seed 1: margins: goal passed by 10.5 s (reached goal at 9.5 s of 20 s); collisions passed by 0 collisions (no "
            "collision; at most 0)\n"
            "in worlds/field.toml, seed 2: margins: goal passed by 10.4 s (reached goal at 9.6 s of 20 s); collisions passed by 0 collisions (no "
            "collision; at most 0)\n");
  for (std::size_t k = 1; k < g.checks.size(); ++k) EXPECT_EQ(g.checks[k].output(), "") << g.checks[k].name;
  EXPECT_EQ(g.checks[0].runs.size(), 2u);  // two seeds
  EXPECT_EQ(g.checks[1].runs.size(), 1u);  // one secret seed
  ASSERT_EQ(g.checks[3].runs.size(), 2u);  // two generated worlds, one of them the secret's
  EXPECT_EQ(g.checks[3].runs[1].world, "generated rooms, hidden world 1");
  EXPECT_DOUBLE_EQ(g.score(), 8.0);
  EXPECT_DOUBLE_EQ(g.maxScore(), 8.0);
  // One place on the board per metric: the mean of the two runs' times.
  ASSERT_EQ(g.leaderboard.size(), 1u);
  EXPECT_EQ(g.leaderboard[0].name, "Seconds to the goal");
  ASSERT_TRUE(g.leaderboard[0].value);
  EXPECT_NEAR(*g.leaderboard[0].value, 9.55, 0.1);  // the margins above print each to a tenth
}

// What a controller prints reaches frob's output in the runs students see, and in no other: it
// could print what it senses in a hidden world. Here it prints once a run: the two runs of the one
// visible check, not those of the hidden and after-the-due-date ones (four more).
TEST_F(Grading, WhatAControllerPrintsInAHiddenRunIsShownNowhere) {
  std::ofstream(dir_ / "talks.cpp") << kTalks;
  std::string printed;
  def_.host.output = [&](std::string_view text) { printed += text; };
  const Grade g = grade(def_, dir_ / "talks.cpp");
  ASSERT_EQ(g.compileError, "");
  ASSERT_EQ(g.checks.size(), 4u);
  EXPECT_EQ(g.checks[1].runs.size() + g.checks[2].runs.size() + g.checks[3].runs.size(), 4u);
  EXPECT_EQ(printed, "a run\na run\n");
}

// The runs students see are made before any hidden one, whatever the rubric's order: nothing a
// controller leaves behind in a run (what the kernel caches, a file's access time) can carry a
// hidden world into a visible one. When the visible run prints, one host has started, not two.
TEST_F(Grading, EveryVisibleRunIsMadeBeforeAnyHiddenOne) {
  std::ofstream(dir_ / "assignment" / "hidden_first.toml") << R"(title = "Hidden first"
seconds = 1
[[check]]
name = "hidden"
visibility = "hidden"
worlds = ["worlds/field.toml"]
secret_seeds = 1
collisions = { max = 0 }
[[check]]
name = "visible"
worlds = ["worlds/field.toml"]
collisions = { max = 0 }
)";
  std::ofstream(dir_ / "talks.cpp") << kTalks;
  Result<Rubric> rubric = loadRubric(dir_ / "assignment" / "hidden_first.toml");
  ASSERT_TRUE(rubric.ok()) << rubric.error();
  def_.rubric = rubric.value();
  const std::uint64_t before = ControllerHost::started();
  std::uint64_t startedBeforeTheVisibleRun = 0;
  def_.host.output = [&](std::string_view) { startedBeforeTheVisibleRun = ControllerHost::started() - before; };
  const Grade g = grade(def_, dir_ / "talks.cpp");
  ASSERT_EQ(g.compileError, "");
  ASSERT_EQ(g.checks.size(), 2u);
  EXPECT_EQ(g.checks[0].name, "hidden");  // reported in the rubric's order
  EXPECT_EQ(ControllerHost::started() - before, 2u);
  EXPECT_EQ(startedBeforeTheVisibleRun, 1u) << "a hidden run was made before the visible one";
}

// A class folder: each .cpp file in it is a submission alone, each subfolder a submission of
// several files; `frob grade A file.cpp` grades the file's folder when the file is its one controller
// with helpers beside it. A stray file without a controller in the class compiles with no one's.
TEST_F(Grading, AClassHoldsFilesAloneAndFoldersOfSeveralFiles) {
  const fs::path klass = dir_ / "class";
  fs::create_directories(klass / "bob");
  fs::create_directories(klass / "empty");
  std::ofstream(klass / "alice.cpp") << kGood;
  std::ofstream(klass / "carol.cpp") << kCrash;
  std::ofstream(klass / "stray.cpp") << "int unrelated() { return 1; }\n";
  std::ofstream(klass / "bob" / "to_goal.cpp") << "#include <frob/frob.hpp>\nfrob::Task<frob::Wheels, bool> toGoal();\nFROB_CONTROLLER(toGoal)\n";
  std::string helper = kGood;
  helper.erase(helper.find("FROB_CONTROLLER(toGoal)"));
  std::ofstream(klass / "bob" / "helpers.cpp") << helper;
  EXPECT_EQ(submissionsIn(klass), (std::vector<fs::path>{klass / "alice.cpp", klass / "bob", klass / "carol.cpp", klass / "stray.cpp"}));
  EXPECT_EQ(submissionOf(klass / "bob" / "to_goal.cpp"), klass / "bob");
  EXPECT_EQ(submissionOf(klass / "alice.cpp"), klass / "alice.cpp");  // another controller lies beside it
  EXPECT_EQ(submissionOf(dir_ / "good.cpp"), dir_ / "good.cpp");      // nothing to compile with it
  def_.visibleOnly = true;
  const std::vector<Grade> grades = gradeAll(def_, submissionsIn(klass), 1);
  ASSERT_EQ(grades.size(), 4u);
  EXPECT_DOUBLE_EQ(grades[0].score(), grades[0].maxScore());
  EXPECT_EQ(grades[1].submission, (klass / "bob").string());
  EXPECT_EQ(grades[1].compileError, "");
  EXPECT_DOUBLE_EQ(grades[1].score(), grades[1].maxScore());
  EXPECT_EQ(grades[3].compileError, "");
  EXPECT_DOUBLE_EQ(grades[3].score(), 0.0);
}

TEST_F(Grading, ACrashFailsEveryRunWithItsReasonAndNothingElse) {
  const Grade g = grade(def_, dir_ / "crash.cpp");
  EXPECT_DOUBLE_EQ(g.score(), 0.0);
  EXPECT_EQ(g.checks[0].output(),
            "in worlds/field.toml, seed 1: the controller failed: nomad: crashed with SIGSEGV (a bad pointer, or an index out of "
            "range?) at t = 1.01 s\n"
            "in worlds/field.toml, seed 2: the controller failed: nomad: crashed with SIGSEGV (a bad pointer, or an index out of "
            "range?) at t = 1.01 s\n");
}

TEST_F(Grading, ACompileErrorScoresZeroAndSaysSo) {
  const Grade g = grade(def_, dir_ / "broken.cpp");
  // The reason first, then the compiler's messages, which it points to.
  const std::size_t reason = g.compileError.find("could not compile"), where = g.compileError.find("broken.cpp:2:");
  ASSERT_NE(reason, std::string::npos) << g.compileError;
  ASSERT_NE(where, std::string::npos) << g.compileError;
  EXPECT_LT(reason, where);
  EXPECT_NE(g.compileError.find("(the compiler's messages follow)\n"), std::string::npos) << g.compileError;
  EXPECT_DOUBLE_EQ(g.score(), 0.0);
  EXPECT_EQ(
      g.checks[2].output(),
      "in hidden world 1: the submission did not compile (hidden worlds give no details: practise with frob grade --practice)\n");  // a hidden check
                                                                                                                                    // names no world
}

TEST_F(Grading, PartialCreditIsTheShareOfRunsPassed) {
  // At 0.4 m/s from x = 1, within 0.3 m of x = 5 after about 9.5 s: allowed 9 s, neither seed
  // passes; allowed 10 s, both do.
  def_.rubric.checks[0].criteria[0].seconds = 9;
  EXPECT_DOUBLE_EQ(grade(def_, dir_ / "good.cpp").checks[0].score, 0.0);
  def_.rubric.checks[0].criteria[0].seconds = 10;
  def_.rubric.checks[0].seeds = {1};
  def_.rubric.checks[0].worlds.push_back({.name = "empty"});  // no goal there: that run fails
  const Grade g = grade(def_, dir_ / "good.cpp");
  EXPECT_DOUBLE_EQ(g.checks[0].score, 2.0);
  EXPECT_EQ(g.checks[0].output(),
            "in worlds/field.toml, seed 1: margins: goal passed by 0.5 s (reached goal at 9.5 s of 10 s); collisions passed by 0 collisions (no "
            "collision; at most 0)\n"
            "in empty, seed 1: the world has no point 'goal' to reach\n"
            "  margins: collisions passed by 0 collisions (no collision; at most 0)\n");
}

TEST_F(Grading, VisibleOnlyGradesTheVisibleChecks) {
  def_.visibleOnly = true;
  const Grade g = grade(def_, dir_ / "good.cpp");
  ASSERT_EQ(g.checks.size(), 1u);
  EXPECT_EQ(g.checks[0].name, "reaches the goal");
}

TEST_F(Grading, TheSameSubmissionTwiceGivesTheSameGrade) {
  const Grade a = grade(def_, dir_ / "good.cpp"), b = grade(def_, dir_ / "good.cpp");
  ASSERT_EQ(a.checks.size(), b.checks.size());
  for (std::size_t c = 0; c < a.checks.size(); ++c) {
    EXPECT_EQ(a.checks[c].score, b.checks[c].score);
    ASSERT_EQ(a.checks[c].runs.size(), b.checks[c].runs.size());
    for (std::size_t r = 0; r < a.checks[c].runs.size(); ++r) {
      EXPECT_EQ(a.checks[c].runs[r].seed, b.checks[c].runs[r].seed);
      EXPECT_EQ(a.checks[c].runs[r].trajectoryHash, b.checks[c].runs[r].trajectoryHash);
      EXPECT_EQ(a.checks[c].runs[r].reason, b.checks[c].runs[r].reason);
    }
  }
  // Different seeds drive different trajectories: the hash sees the noise.
  EXPECT_NE(a.checks[0].runs[0].trajectoryHash, a.checks[0].runs[1].trajectoryHash);
}

TEST_F(Grading, EveryRunsLogReplaysToTheSameVerdictBitForBit) {
  // A tighter rubric file (replay reads the rubric the log names), so that some runs fail with a reason.
  std::string text = kRubric;
  text.replace(text.find("by = 20"), 7, "by = 9");
  std::ofstream(dir_ / "assignment" / "rubric.toml") << text;
  def_.rubric = loadRubric(dir_ / "assignment" / "rubric.toml").value();
  def_.logs = dir_ / "logs";
  int failed = 0;
  for (const char* submission : {"good.cpp", "crash.cpp"}) {
    const Grade g = grade(def_, dir_ / submission);
    for (const CheckGrade& c : g.checks) {
      for (const RunGrade& r : c.runs) {
        ASSERT_TRUE(fs::exists(r.log)) << r.log;
        Result<Replay> again = replay(r.log, def_.secret);
        ASSERT_TRUE(again.ok()) << again.error();
        EXPECT_EQ(again.value().check, c.name);
        EXPECT_EQ(again.value().run.seed, r.seed);
        EXPECT_EQ(again.value().run.trajectoryHash, r.trajectoryHash) << r.log;
        EXPECT_EQ(again.value().run.passed, r.passed) << r.log;
        EXPECT_EQ(again.value().run.reason, r.reason) << r.log;
        failed += !r.passed;
      }
    }
  }
  EXPECT_EQ(failed, 8);  // the good one late in both seeds; the crash in all six runs
}

// Checks that name the same world and seeds for as long judge one run each: the controller's
// host starts once per world and seed (its global constructor prints once), not once per check; a
// check of another length, or with the same criteria kept apart, makes its own. Each check still
// judges by its own criteria, with its own log.
TEST_F(Grading, ChecksOfTheSameWorldSeedAndLengthShareTheRun) {
  std::ofstream(dir_ / "counted.cpp") << kGood << "#include <cstdio>\nstatic const int started = std::puts(\"host started\");\n";
  std::ofstream(dir_ / "assignment" / "shared.toml")
      << "title = \"Shared\"\nseconds = 12\n"
         "[[check]]\nname = \"reaches\"\nworlds = [\"worlds/field.toml\"]\nseeds = [1, 2]\ngoal = { within = 0.3, by = 12 }\n"
         "[[check]]\nname = \"soon\"\nworlds = [\"worlds/field.toml\"]\nseeds = [1, 2]\ngoal = { within = 0.3, by = 5 }\n"
         "[[check]]\nname = \"shorter\"\nworlds = [\"worlds/field.toml\"]\nseeds = [1]\nseconds = 11\ngoal = { within = 0.3 }\n";
  GradeDef def = def_;
  def.rubric = loadRubric(dir_ / "assignment" / "shared.toml").value();
  def.logs = dir_ / "logs";
  std::string output;
  def.host.output = [&](std::string_view text) { output += text; };
  const Grade g = grade(def, dir_ / "counted.cpp");
  ASSERT_EQ(g.compileError, "");
  ASSERT_EQ(g.checks.size(), 3u);
  std::size_t starts = 0;
  for (std::size_t at = 0; (at = output.find("host started", at)) != std::string::npos; at += 1) ++starts;
  EXPECT_EQ(starts, 3u) << output;  // seeds 1 and 2 for 12 s, seed 1 for 11 s
  for (std::size_t k = 0; k < 2; ++k) {
    EXPECT_EQ(g.checks[0].runs[k].trajectoryHash, g.checks[1].runs[k].trajectoryHash);
    EXPECT_TRUE(g.checks[0].runs[k].passed) << g.checks[0].runs[k].reason;
    EXPECT_FALSE(g.checks[1].runs[k].passed);  // the goal at 9.5 s, not by 5 s
    EXPECT_NE(g.checks[0].runs[k].log, g.checks[1].runs[k].log);
    EXPECT_TRUE(fs::is_regular_file(g.checks[1].runs[k].log));
  }
  EXPECT_NE(g.checks[2].runs[0].trajectoryHash, g.checks[0].runs[0].trajectoryHash);
  // Judged again from the logs, each check's runs replay to the same verdicts.
  const std::optional<Grade> again = rejudge(def, dir_ / "counted.cpp", def.logs);
  ASSERT_TRUE(again.has_value());
  for (std::size_t c = 0; c < 3; ++c)
    for (std::size_t k = 0; k < g.checks[c].runs.size(); ++k) EXPECT_EQ(again->checks[c].runs[k].passed, g.checks[c].runs[k].passed);
}

// A log is signed with the secret: a student who edits a failing log (to stop early and report what
// the check wants) gets a refusal, not a replay; so does an unsigned log, or the wrong secret.
TEST_F(Grading, AnEditedOrUnsignedLogIsRefused) {
  def_.logs = dir_ / "logs";
  const Grade g = grade(def_, dir_ / "crash.cpp");
  const fs::path log = g.checks.at(2).runs.at(0).log;  // "reports success": the crash never reports
  ASSERT_TRUE(replay(log, def_.secret).ok());
  std::string text;
  {
    std::ifstream in(log);
    std::ostringstream all;
    all << in.rdbuf();
    text = all.str();
  }
  const auto written = [&](const std::string& as) {
    const fs::path edited = dir_ / "edited.log";
    std::ofstream(edited) << as;
    return edited;
  };
  std::string forged = text;
  forged.replace(forged.find("wheels\n"), 7, "returned_at 0 0x1p+0\nreturned 0 true\nwheels\n");
  EXPECT_EQ(replay(written(forged), def_.secret).error(),
            (dir_ / "edited.log").string() + ": the log was changed after grading, or signed with another secret: its signature does not match");
  EXPECT_EQ(replay(log, "another secret").error(),
            log.string() + ": the log was changed after grading, or signed with another secret: its signature does not match");
  const std::string unsigned_ = text.substr(0, text.rfind("hmac "));
  EXPECT_EQ(
      replay(written(unsigned_), def_.secret).error(),
      (dir_ / "edited.log").string() + ": the log is not signed (graded without the instructor's secret, or cut short), so nothing vouches for it");
  EXPECT_EQ(replay(log, "").error(),
            log.string() + ": give the secret it was graded with (--secret FILE or $FROB_GRADE_SECRET) to check its signature");
}

// The report's film is the graded run run again: its trajectory hash is the graded one's, and a film
// that strays from the graded run (here, a graded hash that is not the film's) is refused.
TEST_F(Grading, TheFilmIsTheGradedRun) {
  const Grade g = grade(def_, dir_ / "good.cpp");
  const RunGrade& run = g.checks.at(0).runs.at(1);
  Result<std::uint64_t> film = filmRun(def_, dir_ / "good.cpp", g.checks[0].name, run, {.plot = (dir_ / "film.png").string()});
  ASSERT_TRUE(film.ok()) << film.error();
  EXPECT_EQ(film.value(), run.trajectoryHash);
  EXPECT_TRUE(fs::exists(dir_ / "film.png"));
  RunGrade other = run;
  other.trajectoryHash ^= 1;
  EXPECT_EQ(filmRun(def_, dir_ / "good.cpp", g.checks[0].name, other, {}).error(),
            format("the film's run (trajectory %016llx) is not the graded run (trajectory %016llx), so it is not shown",
                   static_cast<unsigned long long>(run.trajectoryHash), static_cast<unsigned long long>(other.trajectoryHash)));
}

TEST(Replay, ALogThatIsNotOneSaysSo) {
  const fs::path log = fs::path(::testing::TempDir()) / "not_a_log.txt";
  std::ofstream(log) << "hello\nhmac 00\n";
  EXPECT_EQ(replay(log, "s").error(),
            log.string() + ": the log was changed after grading, or signed with another secret: its signature does not match");
}

// A class folder lists its links and special files, so that compiling each refuses it (never
// following it) and the gradebook says why; a linked folder is not a student's folder of files.
TEST(Submissions, LinksAndSpecialFilesInAClassAreListedToBeRefused) {
  const fs::path klass = fs::path(::testing::TempDir()) / "grade_test_links" / "class";
  fs::remove_all(klass.parent_path());
  fs::create_directories(klass / "bob");
  std::ofstream(klass / "bob" / "go.cpp") << "// bob's\n";
  std::ofstream(klass / "ann.cpp") << "// ann's\n";
  fs::create_symlink("/etc/shadow", klass / "eve.cpp");
  fs::create_symlink("ann.cpp", klass / "notes.txt");
  fs::create_directory_symlink("bob", klass / "dan");
  EXPECT_EQ(submissionsIn(klass), (std::vector<fs::path>{klass / "ann.cpp", klass / "bob", klass / "dan", klass / "eve.cpp", klass / "notes.txt"}));
}

}  // namespace
}  // namespace frob::course
