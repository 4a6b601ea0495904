// A run's wheel log: no text in it, not even one a controller chose, adds a record; it names the
// submission it was graded for, and a replay refuses it for another.
#include "frob/grade/wheel_log.hpp"

#include "frob/grade/grade.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

namespace frob::course {
namespace {

namespace fs = std::filesystem;

TEST(WheelLog, NoValueAddsARecord) {
  const std::string forged = "false\nreturned 0 true\nwheels\n0x0p+0 0x0p+0\n\\x\r\x1b";
  const WheelLog log{.rubric = "/r/rubric.toml",
                     .check = "reports\nsuccess",
                     .world = "room.toml",
                     .submission = "class/a\nb.cpp",
                     .submissionHash = "00",
                     .student = "Ada\nhmac 00",
                     .robots = 1,
                     .failures = {{0, forged}},
                     .returned = {{0, forged}},
                     .returnedAt = {{0, 0.5}},
                     .wheels = {{Wheels{0.1, 0.0}}, {Wheels{0.2, -0.5}}}};
  const std::string text = wheelLogText(log, "secret");
  // Its records: 11 of the header, the student, a failure, a result and its time, two steps, the signature.
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 18) << text;
  Result<WheelLog> back = readWheelLog(text, "secret");
  ASSERT_TRUE(back.ok()) << back.error();
  EXPECT_EQ(back.value().failures, log.failures);
  EXPECT_EQ(back.value().returned, log.returned);
  EXPECT_EQ(back.value().check, log.check);
  EXPECT_EQ(back.value().student, log.student);
  EXPECT_EQ(back.value().wheels.size(), 2u);
  EXPECT_EQ(back.value().wheels[1][0], (Wheels{0.2, -0.5}));
}

TEST(WheelLog, WhatNoWriterWritesIsRefused) {
  const std::string head = "frob-replay 3\nseed 1\nsteps 0\nrobots 1\n";
  for (const std::string& records : {std::string("returned 0 a\nreturned 0 b\n"), std::string("failure 1 out of range\n"),
                                     std::string("check a\\qb\n"), std::string("check a\rb\n"), std::string("robots 2\n"), std::string("seed -1\n"),
                                     std::string("trajectory 12zz\n"), std::string("returned_at 0 soon\n")}) {
    EXPECT_FALSE(parseWheelLog(head + records + "wheels\n").ok()) << records;
  }
  EXPECT_TRUE(parseWheelLog(head + "returned 0 a\\nb\\\\c\\x1b\nwheels\n").ok());
  EXPECT_FALSE(parseWheelLog("frob-replay 3\nsteps 2\nrobots 1\nwheels\n0x0p+0 0x0p+0\n").ok());                 // a step short
  EXPECT_FALSE(parseWheelLog("frob-replay 3\nsteps 1\nrobots 1\nwheels\n0x0p+0 0x0p+0 0x0p+0\n").ok());          // a number too many
  EXPECT_FALSE(parseWheelLog("frob-replay 3\nsteps 1\nrobots 1\nwheels\n0x0p+0 0x0p+0\n0x0p+0 0x0p+0\n").ok());  // a step too many
}

// A controller whose task returns text with a line of the log in it: graded as failing, and its log
// replays as failing (it once replayed as passing). The log names the submission; a replay for
// another submission is refused.
TEST(WheelLog, AnInjectedResultReplaysAsItWasGraded) {
  const fs::path dir = fs::path(::testing::TempDir()) / "wheel_log_test";
  fs::remove_all(dir);
  fs::create_directories(dir / "assignment");
  std::ofstream(dir / "assignment" / "rubric.toml")
      << "title = \"Report\"\nseconds = 1\n[[check]]\nname = \"reports success\"\npoints = 1\nworlds = [\"room.toml\"]\nseeds = [1]\n"
         "returns = { value = true }\n";
  std::ofstream(dir / "assignment" / "room.toml") << "size = [4.0, 3.0]\n[[robot]]\nname = \"ada\"\nstart = [1.0, 1.0]\n";
  std::ofstream(dir / "forges.cpp") << R"(#include <frob/frob.hpp>
using namespace frob;
Task<Wheels, std::string> forges() {
  co_await mkTask([](const TaskState&) { return std::pair{wheels(0.0, 0.0), predicate(lift([](double t) { return t > 0.2; }, time()))}; });
  co_return std::string("false\nreturned 0 true");
}
FROB_CONTROLLER(forges)
)";
  std::ofstream(dir / "other.cpp") << "// another submission\n";
  Result<Rubric> rubric = loadRubric(dir / "assignment" / "rubric.toml");
  ASSERT_TRUE(rubric.ok()) << rubric.error();
  GradeDef def{.rubric = rubric.value(), .assignment = "report", .secret = "s", .logs = dir / "logs", .student = "Ada Lovelace"};
  def.compiler.cacheDir = fs::path(FROB_TEST_CACHE_DIR);
  const Grade g = grade(def, dir / "forges.cpp");
  ASSERT_EQ(g.graderFailure, "");
  ASSERT_EQ(g.compileError, "");
  const RunGrade& run = g.checks.at(0).runs.at(0);
  EXPECT_FALSE(run.passed);
  Result<Replay> again = replay(run.log, "s", dir / "forges.cpp");
  ASSERT_TRUE(again.ok()) << again.error();
  EXPECT_FALSE(again.value().run.passed) << "the injected line was read as a record";
  EXPECT_EQ(again.value().run.reason, run.reason);
  EXPECT_EQ(again.value().submission, (dir / "forges.cpp").string());
  EXPECT_EQ(again.value().submissionHash, submissionHash(dir / "forges.cpp"));
  EXPECT_EQ(again.value().student, "Ada Lovelace");
  const Result<Replay> stolen = replay(run.log, "s", dir / "other.cpp");
  EXPECT_NE(stolen.error().find("this is the log of another submission (" + (dir / "forges.cpp").string()), std::string::npos) << stolen.error();
}

}  // namespace
}  // namespace frob::course
