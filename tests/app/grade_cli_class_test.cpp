// frob grade of a class from the command line: in shards merged to the same gradebook, and into a
// folder of evidence per student, graded again in part.
#include "grade_cli.hpp"
#include "run_frob.hpp"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

namespace frob::testing {
namespace {

namespace fs = std::filesystem;

TEST(GradeCli, AClassInShardsMergesToTheWholeClassesGradebook) {
  const fs::path dir = assignment("grade_cli_class");
  fs::create_directories(dir / "class" / "dana");
  std::ofstream(dir / "class" / "ann.cpp") << driver("0.5");
  std::ofstream(dir / "class" / "ben.cpp") << driver("0.1");
  std::ofstream(dir / "class" / "cat.cpp") << "not C++";
  std::ofstream(dir / "class" / "dana" / "controller.cpp") << driver("0.5");
  const FrobResult whole = runFrob(dir, {"grade", "forward", "class", "--jobs", "2", "--gradebook", "all.csv"});
  ASSERT_EQ(whole.status, 0) << whole.err;
  for (int shard : {1, 2}) {
    const std::string n = std::to_string(shard);
    ASSERT_EQ(runFrob(dir, {"grade", "forward", "class", "--shard", n + "/2", "--gradebook", "s" + n + ".csv"}).status, 0);
  }
  const FrobResult merged = runFrob(dir, {"grade", "--merge", "s1.csv", "s2.csv", "--gradebook", "merged.csv"});
  ASSERT_EQ(merged.status, 0) << merged.err;
  EXPECT_EQ(merged.out, "merged 4 submissions into merged.csv\n");
  EXPECT_EQ(readFile(dir / "merged.csv"), readFile(dir / "all.csv"));
  const std::string csv = readFile(dir / "all.csv");
  EXPECT_NE(csv.find("class/ann.cpp,3,3,graded,"), std::string::npos) << csv;
  EXPECT_NE(csv.find("class/ben.cpp,1,3,graded,"), std::string::npos) << csv;
  EXPECT_NE(csv.find("class/cat.cpp,0,3,did not compile: "), std::string::npos) << csv;
  EXPECT_NE(csv.find("class/dana,3,3,graded,"), std::string::npos) << csv;
  EXPECT_EQ(runFrob(dir, {"grade", "forward", "class", "--shard", "3/2"}).status, 2);
}

// The gradebook's row of `student` in `csv`, up to its reasons (which may hold line ends).
std::string rowOf(const std::string& csv, const std::string& student) {
  const std::size_t at = csv.find("\r\n" + student + ",");
  return at == std::string::npos ? "" : csv.substr(at + 2, csv.find("\r\n", at + 2) - at - 2);
}

// --out DIR: a row per student named by file or folder, with what became of them and every reason
// whole; a folder per student with what they read and the logs; the summary; and grading one student
// again replaces their row and folder only, whether named by their file or a file of their folder.
TEST(GradeCli, AClassIntoAFolderGivesEachStudentTheirOwnEvidence) {
  const fs::path dir = assignment("grade_cli_out");
  fs::create_directories(dir / "class" / "dana");
  std::ofstream(dir / "class" / "ann.cpp") << driver("0.5");
  std::ofstream(dir / "class" / "ben.cpp") << driver("0.1");
  std::ofstream(dir / "class" / "cat.cpp") << "not C++";
  std::ofstream(dir / "class" / "dana" / "controller.cpp") << driver("0.1");
  std::ofstream(dir / "class" / "eve.cpp") << "#include <frob/frob.hpp>\n#include <stdexcept>\nusing namespace frob;\n"
                                              "Behavior<Wheels> go(const Robot&) {\n  return lift([](double t) {\n"
                                              "    if (t > 1) throw std::runtime_error(\"eve's own failure\");\n"
                                              "    return Wheels{0.5, 0.0};\n  }, time());\n}\nFROB_CONTROLLER(go)\n";
  std::ofstream(dir / "secret.txt") << "course secret\n";
  const FrobResult r = runFrob(dir, {"grade", "forward", "class", "--jobs", "2", "--out", "out", "--secret", "secret.txt"});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("ann                        3.00 / 3.00  graded\n"), std::string::npos) << r.out;
  const std::string csv = readFile(dir / "out" / "gradebook.csv");
  EXPECT_EQ(csv.substr(0, csv.find("\r\n")), "student,score,max_score,result,goes forward,no bumps,reasons,submission");
  EXPECT_EQ(rowOf(csv, "ann"), "ann,3,3,graded,2,1,,class/ann.cpp");
  EXPECT_EQ(rowOf(csv, "ben").rfind("ben,1,3,graded,0,1,\"goes forward, room.toml, seed 1: never came within 0.40 m of goal", 0), 0u) << csv;
  EXPECT_NE(rowOf(csv, "cat").find("cat,0,3,did not compile,0,0,"), std::string::npos) << csv;
  EXPECT_NE(csv.find("dana,1,3,graded,"), std::string::npos) << csv;
  EXPECT_NE(rowOf(csv, "eve").find("eve,"), std::string::npos) << csv;
  EXPECT_NE(rowOf(csv, "eve").find(",failed at run time,"), std::string::npos) << csv;
  EXPECT_NE(csv.find("eve's own failure"), std::string::npos) << csv;
  // Each student's folder: what Gradescope and CI read, the grade whole, the signed logs; a report for those who lost points.
  for (const char* file : {"results.json", "junit.xml", "grade.json", "logs/goes_forward__room__1.log"}) {
    EXPECT_TRUE(fs::is_regular_file(dir / "out" / "ann" / file)) << file << ": " << ::testing::PrintToString(filesIn(dir / "out" / "ann"));
  }
  EXPECT_FALSE(fs::exists(dir / "out" / "ann" / "report.html"));
  EXPECT_TRUE(fs::is_regular_file(dir / "out" / "ben" / "report.html"));
  EXPECT_EQ(nlohmann::json::parse(readFile(dir / "out" / "ben" / "results.json"))["score"], 1.0);
  const std::string summary = readFile(dir / "out" / "summary.html");
  EXPECT_NE(summary.find("<a href=\"ben/report.html\">ben</a>"), std::string::npos);
  EXPECT_NE(summary.find("<a href=\"ann/grade.json\">ann</a>"), std::string::npos);
  // The logs name the rubric by its assignment's folder: they replay wherever the assignment is.
  const FrobResult replayed = runFrob(dir, {"grade", "--replay", "out/ann/logs/goes_forward__room__1.log", "--secret", "secret.txt"});
  EXPECT_EQ(replayed.status, 0) << replayed.err;

  // Ben and Dana fix theirs: each is graded again alone, and only their rows and folders change.
  const std::string annGrade = readFile(dir / "out" / "ann" / "grade.json");
  std::ofstream(dir / "class" / "ben.cpp") << driver("0.5");
  std::ofstream(dir / "class" / "dana" / "controller.cpp") << driver("0.5");
  ASSERT_EQ(runFrob(dir, {"grade", "forward", "class/ben.cpp", "--out", "out", "--secret", "secret.txt"}).status, 0);
  const FrobResult dana = runFrob(dir, {"grade", "forward", "class/dana/controller.cpp", "--out", "out", "--secret", "secret.txt"});
  ASSERT_EQ(dana.status, 0) << dana.err;
  const std::string after = readFile(dir / "out" / "gradebook.csv");
  EXPECT_EQ(rowOf(after, "ben"), "ben,3,3,graded,2,1,,class/ben.cpp");
  EXPECT_EQ(rowOf(after, "dana"), "dana,3,3,graded,2,1,,class/dana");
  EXPECT_EQ(rowOf(after, "ann"), rowOf(csv, "ann"));
  EXPECT_EQ(rowOf(after, "cat"), rowOf(csv, "cat"));
  EXPECT_EQ(rowOf(after, "controller"), "") << "Dana was graded as someone new";
  EXPECT_EQ(readFile(dir / "out" / "ann" / "grade.json"), annGrade);
  EXPECT_FALSE(fs::exists(dir / "out" / "ben" / "report.html")) << "the report of ben's old grade stayed";
  for (const std::string& name : filesIn(dir / "out")) EXPECT_FALSE(name.ends_with(".partial") || name.ends_with(".old")) << name;
}

// A student graded again when frob or the machine fails (here a compile cache that cannot be made)
// keeps no score of an older grade: their row and folder say "autograder error", with no score, and
// frob says to grade them again (status 1). Graded again on a sound machine, they are graded.
TEST(GradeCli, AGraderFailureLeavesAStudentNoOlderScore) {
  const fs::path dir = assignment("grade_cli_out_failure");
  fs::create_directories(dir / "class");
  std::ofstream(dir / "class" / "ann.cpp") << driver("0.5");
  std::ofstream(dir / "secret.txt") << "course secret\n";
  const std::vector<std::string> ann{"grade", "forward", "class/ann.cpp", "--out", "out", "--secret", "secret.txt"};
  ASSERT_EQ(runFrob(dir, ann).status, 0);
  EXPECT_EQ(rowOf(readFile(dir / "out" / "gradebook.csv"), "ann"), "ann,3,3,graded,2,1,,class/ann.cpp");

  std::ofstream(dir / "class" / "ann.cpp") << driver("0.1");  // her new file, which no one grades
  const FrobResult failed = runFrob(dir, ann, "/dev/null/cache");
  EXPECT_EQ(failed.status, 1) << failed.err;
  EXPECT_NE(failed.out.find("NOT GRADED: the grader failed: cannot create the controller cache"), std::string::npos) << failed.out;
  const std::string row = rowOf(readFile(dir / "out" / "gradebook.csv"), "ann");
  EXPECT_EQ(row.rfind("ann,,,autograder error,,,the grader failed: cannot create the controller cache", 0), 0u) << row;
  EXPECT_TRUE(nlohmann::json::parse(readFile(dir / "out" / "ann" / "grade.json"))["score"].is_null());
  EXPECT_FALSE(fs::exists(dir / "out" / "ann" / "results.json")) << "the results of her older grade stayed";

  ASSERT_EQ(runFrob(dir, ann).status, 0);
  EXPECT_EQ(rowOf(readFile(dir / "out" / "gradebook.csv"), "ann").rfind("ann,1,3,graded,0,1,", 0), 0u);
}

// --changed after a fix of the rubric: each student's logged runs are judged again under it, and only
// those whose row it changes are graded again (their folders rewritten), with those whose runs it
// now makes otherwise (no logs: a failed compile; another length); the others are left as they were.
TEST(GradeCli, AFixedRubricGradesAgainOnlyThoseItChanges) {
  const fs::path dir = assignment("grade_cli_changed");
  fs::create_directories(dir / "class");
  std::ofstream(dir / "class" / "ann.cpp") << driver("0.5");
  std::ofstream(dir / "class" / "ben.cpp") << driver("0.1");
  std::ofstream(dir / "class" / "cat.cpp") << "not C++";
  std::ofstream(dir / "secret.txt") << "course secret\n";
  const std::vector<std::string> again{"grade", "forward", "class", "--out", "out", "--secret", "secret.txt", "--changed"};
  ASSERT_EQ(runFrob(dir, {"grade", "forward", "class", "--out", "out", "--secret", "secret.txt"}).status, 0);
  const auto graded = [&](const std::string& student) { return readFile(dir / "out" / student / "grade.json"); };  // it says when it was graded
  const std::string ann = graded("ann"), ben = graded("ben");
  ASSERT_EQ(rowOf(readFile(dir / "out" / "gradebook.csv"), "ben").rfind("ben,1,3,graded,0,1,", 0), 0u);

  const FrobResult same = runFrob(dir, again);
  ASSERT_EQ(same.status, 0) << same.err;
  EXPECT_NE(same.err.find("frob: of 3 students, 2 unchanged, 0 changed by the rubric as it now is, 1 without logs of the runs it now makes: "
                          "grading again cat\n"),
            std::string::npos)
      << same.err;
  EXPECT_EQ(graded("ann"), ann);
  EXPECT_EQ(graded("ben"), ben);

  // A goal of 0.9 m: ben's slow robot (0.3 m driven) now comes near enough; ann's result is as it was.
  std::string rubric = kRubric;
  rubric.replace(rubric.find("within = 0.4"), 12, "within = 0.9");
  std::ofstream(dir / "forward" / "rubric.toml") << rubric;
  const FrobResult fixed = runFrob(dir, again);
  ASSERT_EQ(fixed.status, 0) << fixed.err;
  EXPECT_NE(fixed.err.find("frob: of 3 students, 1 unchanged, 1 changed by the rubric as it now is, 1 without logs of the runs it now makes: "
                           "grading again ben, cat\n"),
            std::string::npos)
      << fixed.err;
  EXPECT_EQ(rowOf(readFile(dir / "out" / "gradebook.csv"), "ben"), "ben,3,3,graded,2,1,,class/ben.cpp");
  EXPECT_EQ(graded("ann"), ann);
  EXPECT_NE(graded("ben"), ben);

  // Runs of 4 s, not 3: no student's logs are of the runs the rubric now makes.
  rubric.replace(rubric.find("seconds = 3"), 11, "seconds = 4");
  std::ofstream(dir / "forward" / "rubric.toml") << rubric;
  const FrobResult longer = runFrob(dir, again);
  ASSERT_EQ(longer.status, 0) << longer.err;
  EXPECT_NE(longer.err.find("frob: of 3 students, 0 unchanged, 0 changed by the rubric as it now is, 3 without logs"), std::string::npos)
      << longer.err;
  EXPECT_NE(graded("ann"), ann);
}

}  // namespace
}  // namespace frob::testing
