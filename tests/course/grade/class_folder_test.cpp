// A class graded into one folder: students named by file or folder, what became of each, the
// gradebook's rows replaced a student at a time, and the summary page as Chromium shows it.
#include "frob/grade/class_folder.hpp"

#include "../../support/chromium.hpp"
#include "grade_samples.hpp"

namespace frob::course::testing {
namespace {

using support::chromium, support::Ran, support::requireChromium;

TEST(ClassFolder, StudentsAreNamedByFileOrFolderEachOnce) {
  EXPECT_EQ(studentNames({"class/alice.cpp", "class/alice", "class/bob.cpp", "class/.hidden.cpp", "class/gradebook.csv.cpp", "class/summary.html"}),
            (std::vector<std::string>{"alice.cpp", "alice", "bob", "_.hidden", "_gradebook.csv", "_summary.html"}));
  // A file whose stem is a folder's whole name; control characters as their escapes, so that a
  // name that holds one never meets another student's; a name still shared takes a number.
  EXPECT_EQ(studentNames({"class/dana.v2.cpp", "class/dana.v2", "class/e\x1b[2Jve.cpp", "class/e_[2Jve.cpp", "class/b\\x01.cpp", "class/b\x01.cpp"}),
            (std::vector<std::string>{"dana.v2.cpp", "dana.v2", "e\\x1b[2Jve", "e_[2Jve", "b\\x01.cpp", "b\\x01.cpp~2"}));
}

TEST(ClassFolder, TheResultTellsACompileAHangAndACrashApart) {
  Grade g = sample();
  EXPECT_EQ(resultKind(g), "graded");
  g.checks[1].runs[0].reason = "the controller failed: threw std::runtime_error: boom";
  EXPECT_EQ(resultKind(g), "failed at run time");
  g.checks[0].runs[1] = fail("maze", 2, "the controller failed: used more than 1 s of CPU in one step (an endless loop?)");
  EXPECT_EQ(resultKind(g), "timed out");
  g.checks[0].runs[1].reason = "the controller failed: did not answer within 1 s in one step (it waited or slept)";
  EXPECT_EQ(resultKind(g), "timed out");
  g.checks[0].runs[1].reason = "the controller failed: the run took longer than 120 s of wall-clock time";
  EXPECT_EQ(resultKind(g), "timed out");
  EXPECT_EQ(resultKind(uncompiled("a.cpp:1:1: error: nope")), "did not compile");
  g.graderFailure = "the controller host did not start";
  EXPECT_EQ(resultKind(g), "autograder error");
}

TEST(ClassFolder, AStudentGradedAgainReplacesTheirRowOnly) {
  const fs::path dir = scratch("class_folder_rows");
  const std::vector<std::string> checks{"reaches the goal", "avoids walls, maze"};
  const Grade alice = scored("class/alice.cpp", 2, 1), bob = scored("class/bob", 0, 1);
  ASSERT_TRUE(updateClassGradebook(dir, checks, {{"alice", &alice}, {"bob", &bob}}).ok());
  const Grade better = scored("class/bob", 2, 1);
  ASSERT_TRUE(updateClassGradebook(dir, checks, {{"bob", &better}}).ok());
  EXPECT_EQ(readFile(dir / "gradebook.csv"),
            "student,score,max_score,result,reaches the goal,\"avoids walls, maze\",reasons,submission\r\n"
            "alice,3,3,graded,2,1,,class/alice.cpp\r\n"
            "bob,3,3,graded,2,1,,class/bob\r\n");
  // Found again by their submission, or a file in it.
  EXPECT_EQ(knownStudent(dir, "class/bob/controller.cpp").value().student, "bob");
  EXPECT_EQ(knownStudent(dir, "class/alice.cpp").value().submission, "class/alice.cpp");
  EXPECT_FALSE(knownStudent(dir, "class/carol.cpp").has_value());
  // Another rubric's columns are refused, not mixed in.
  const Status other = updateClassGradebook(dir, {"reaches the goal"}, {{"bob", &better}});
  EXPECT_NE(other.error().find((dir / "gradebook.csv").string() + ":1: written for other checks than this rubric's"), std::string::npos)
      << other.error();
}

// Three students, their grade.json files as grading writes them, and the page made from them.
fs::path classWithThree(const std::string& name) {
  const fs::path dir = scratch(name);
  Grade alice = sample();
  alice.checks[1].score = 1, alice.checks[1].runs[0] = pass("maze", 3);
  alice.checks[2].score = 2, alice.checks[2].runs[0] = pass("rooms", 7);
  Grade hostile = sample();
  hostile.checks[0].runs[1] = fail("maze", 2, "never came within 0.40 m of goal (closest 1.25 m)");
  hostile.checks[0].runs[1].hints = {"it turned in place for 12.5 s"};
  hostile.checks[0].score = 1, hostile.checks[1].score = 0;
  hostile.checks[1].runs[0] = fail("maze", 3, "never came within 0.40 m of goal (closest 0.93 m)");
  hostile.checks[1].runs[0].wallSeconds = 7.5;
  for (const auto& [student, g] :
       {std::pair<std::string, Grade>{"alice", alice}, {"<b>eve&", hostile}, {"bob", uncompiled("b.cpp:3:1: error: expected ';'\nmore")}}) {
    fs::create_directories(dir / student);
    EXPECT_TRUE(writeGradeJson(g, student, {}, dir / student / "grade.json").ok());
  }
  std::ofstream(dir / "<b>eve&" / "report.html") << "report";
  EXPECT_TRUE(writeClassSummary(dir, "go_to_goal").ok());
  return dir;
}

TEST(ClassFolderInChromium, TheSummaryShowsScoresChecksReasonsCompilesAndEveryStudent) {
  requireChromium();
  const fs::path dir = classWithThree("class_summary");
  const Ran ran = chromium(dir, {"--dump-dom"}, dir / "summary.html", dir / "dom.html");
  ASSERT_EQ(ran.status, 0) << ran.err;
  const Doc dom = parseHtml(readFile(dir / "dom.html"));
  ASSERT_TRUE(dom);
  EXPECT_EQ(one(dom.get(), "//title"), "go_to_goal: the class");
  EXPECT_EQ(one(dom.get(), "//p[@class='total']"), "3 students, on average 40% of the points");
  // Alice 5 of 5, Eve 1 of 5 (20%), Bob 0 of 2 (did not compile).
  EXPECT_EQ(select(dom.get(), "//table[@class='histogram']/tbody/tr/td[2]"),
            (std::vector<std::string>{"1", "0", "1", "0", "0", "0", "0", "0", "0", "0", "1"}));
  EXPECT_EQ(select(dom.get(), "//table[@class='checks']/tbody/tr/td[1]"),
            (std::vector<std::string>{"reaches the goal", "avoids walls", "secret worlds"}));
  EXPECT_EQ(select(dom.get(), "//table[@class='checks']/tbody/tr/td[3]"), (std::vector<std::string>{"1 of 3", "1 of 2", "1 of 2"}));
  // Two runs that came short by different distances are one reason.
  EXPECT_EQ(select(dom.get(), "//table[@class='reasons']/tbody/tr[1]/td"),
            (std::vector<std::string>{"never came within # m of goal (closest # m)", "1", "2"}));
  EXPECT_EQ(select(dom.get(), "//table[@class='hints']/tbody/tr/td[1]"), (std::vector<std::string>{"it turned in place for # s"}));
  EXPECT_EQ(select(dom.get(), "//table[@class='compiles']/tbody/tr/td"), (std::vector<std::string>{"bob", "error: expected ';'"}));
  EXPECT_EQ(select(dom.get(), "//table[@class='slowest']/tbody/tr[1]/td"),
            (std::vector<std::string>{"<b>eve&", "avoids walls", "maze, seed 3", "7.5"}));
  // Every student, their name as text, linked to their report where they have one.
  EXPECT_EQ(select(dom.get(), "//table[@class='students']/tbody/tr/td[1]"), (std::vector<std::string>{"<b>eve&", "alice", "bob"}));
  EXPECT_EQ(select(dom.get(), "//table[@class='students']/tbody/tr/td[1]/a/@href"),
            (std::vector<std::string>{"%3Cb%3Eeve%26/report.html", "alice/grade.json", "bob/grade.json"}));
  EXPECT_TRUE(select(dom.get(), "//b").empty());
  EXPECT_TRUE(select(dom.get(), "//script").empty());
}

}  // namespace
}  // namespace frob::course::testing
