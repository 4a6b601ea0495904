// The grade's writers: the terminal table and the CSV byte for byte, the results.json files field by
// field, and the JUnit XML read back by libxml2. The HTML report: html_report_test.cpp.
#include "frob/grade/grade_report.hpp"

#include "grade_samples.hpp"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

namespace frob::course {
namespace {

namespace fs = std::filesystem;
using namespace frob::course::testing;
using nlohmann::json;

// ---- The score table -----------------------------------------------------------------------------

TEST(ScoreTable, ExactText) {
  EXPECT_EQ(scoreTable(sample()),
            "go_to_goal: students/alice.cpp\n"
            "Check             Score    Result\n"
            "----------------  -------  -------\n"
            "reaches the goal    2 / 2  PASS\n"
            "avoids walls      0.5 / 1  PARTIAL\n"
            "    in maze, seed 3: touched a wall at 41.2 s at (3.1, 4.5)\n"
            "secret worlds       0 / 2  FAIL     [hidden]\n"
            "    in hidden world 1: it failed the rubric's \"goal\" criterion" +
                kNoDetails +
                "\n"
                "----------------  -------  -------\n"
                "Total             2.5 / 5\n"
                "Note: the controller printed more than 1 MB; the rest was cut\n");
}

// A check that is not visible names no world, seed or place, and says only what failed: no measure,
// time or text a controller could choose to read a hidden world out through its reason or hints.
TEST(CheckGrade, AHiddenRunSaysOnlyWhatFailed) {
  CheckGrade c{.name = "hidden",
               .points = 1,
               .visibility = Visibility::Hidden,
               .runs = {fail("generated obstacles, hidden world 1", 1234, "never came within 0.30 m of wp1 (closest 1.86 m, at (3.1, -4.5))",
                             "it failed the rubric's \"waypoints\" criterion")}};
  c.runs[0].hints = {"nomad's task 'sonar 1.86' ran from 0.0 s to the end of the run"};
  EXPECT_EQ(c.output(), "in hidden world 1: it failed the rubric's \"waypoints\" criterion" + kNoDetails + "\n");
  c.visibility = Visibility::AfterDueDate;
  EXPECT_EQ(c.output(), "in hidden world 1: it failed the rubric's \"waypoints\" criterion" + kNoDetails + "\n");
  c.visibility = Visibility::Visible;
  EXPECT_EQ(c.output(),
            "in generated obstacles, hidden world 1, seed 1234: never came within 0.30 m of wp1 (closest 1.86 m, at (3.1, -4.5))\n"
            "  hint: nomad's task 'sonar 1.86' ran from 0.0 s to the end of the run\n");
}

// A visible check says every run's margins; a hidden one none (a number the controller could choose).
TEST(CheckGrade, AVisibleRunSaysItsMarginsAHiddenOneNone) {
  RunGrade near = pass("maze", 2);
  near.criteria = {{.criterion = "goal", .passed = true, .margin = Margin{.value = 2.4, .unit = "s", .text = "reached goal at 7.6 s of 10 s"}},
                   {.criterion = "collisions", .passed = true, .margin = Margin{.value = 0, .unit = "collisions", .text = "1 collision; at most 1"}}};
  RunGrade far = fail("maze", 3, "never came within 0.30 m of goal (closest 0.42 m, at 9.0 s)");
  far.criteria = {
      {.criterion = "goal", .passed = false, .margin = Margin{.value = -0.12, .unit = "m", .text = "closest 0.42 m to goal; 0.30 m needed"}},
      {.criterion = "collisions", .passed = true}};
  CheckGrade c{.name = "reaches the goal", .points = 2, .score = 1, .runs = {near, far}};
  EXPECT_EQ(
      c.output(),
      "in maze, seed 2: margins: goal passed by 2.4 s (reached goal at 7.6 s of 10 s); collisions passed by 0 collisions (1 collision; at most 1)\n"
      "in maze, seed 3: never came within 0.30 m of goal (closest 0.42 m, at 9.0 s)\n"
      "  margins: goal failed by 0.12 m (closest 0.42 m to goal; 0.30 m needed)\n");
  c.visibility = Visibility::Hidden;
  EXPECT_EQ(c.marginsShown(0), "");
  EXPECT_EQ(c.output(), "in hidden world 2: never came within 0.30 m of goal (closest 0.42 m, at 9.0 s)" + kNoDetails + "\n");
}

// frob grade --practice: a row per world, each criterion's margin, and how to watch a failed world.
TEST(PracticeTable, ARowPerWorldWithMarginsAndHowToWatchAFailure) {
  Grade g;
  g.assignment = "go_to_goal";
  g.submission = "mine.cpp";
  RunGrade good{.world = "generated lounge, seed 42", .seed = 7, .generator = "lounge --seed 42", .passed = true};
  good.criteria = {{.criterion = "goal", .passed = true, .margin = Margin{.value = 2.4, .unit = "s"}},
                   {.criterion = "collisions", .passed = true, .margin = Margin{.value = 1, .unit = "collisions"}}};
  RunGrade bad{.world = "generated lounge, seed 9", .seed = 7, .generator = "lounge --seed 9", .passed = false, .reason = "x"};
  bad.criteria = {{.criterion = "goal", .passed = false, .margin = Margin{.value = -0.12, .unit = "m"}},
                  {.criterion = "collisions", .passed = true, .margin = Margin{.value = 0, .unit = "collisions"}}};
  RunGrade crashed{
      .world = "generated lounge, seed 5", .seed = 7, .generator = "lounge --seed 5", .passed = false, .reason = "the controller failed: \x1b[2J"};
  g.checks = {{.name = "practice", .points = 1, .score = 1.0 / 3, .runs = {good, bad, crashed}}};
  EXPECT_EQ(practiceTable(g),
            "Practice: 1 of 3 runs passed; margins are by how much each criterion was met (+) or missed (-)\n"
            "World                              Result  goal     collisions\n"
            "generated lounge, seed 42, seed 7  PASS    +2.4 s   +1 collision\n"
            "generated lounge, seed 9, seed 7   FAIL    -0.12 m  +0 collisions\n"
            "    to watch it: frob world generate lounge --seed 9 --out lounge-9.toml && frob run mine.cpp --world lounge-9.toml --seed 7 "
            "--assignment go_to_goal --html lounge-9.html\n"
            "generated lounge, seed 5, seed 7   FAIL  the controller failed: \\x1b[2J\n"
            "    to watch it: frob world generate lounge --seed 5 --out lounge-5.toml && frob run mine.cpp --world lounge-5.toml --seed 7 "
            "--assignment go_to_goal --html lounge-5.html\n");
}

TEST(ScoreTable, CompileErrorAndControlCharacters) {
  Grade g = uncompiled("bob.cpp:3:1: error: expected ';'\r\n  int x = 1\n          ^\n");
  g.checks[0].name = "esc\x1b[2J";  // an escape sequence would clear the terminal
  g.checks.push_back({.name = "third of a point",
                      .points = 1,
                      .score = 1.0 / 3.0,
                      .visibility = Visibility::AfterDueDate,
                      .runs = {pass("maze", 1), fail("maze", 2, "bad \x07 bell"), fail("maze", 3, "x")}});
  EXPECT_EQ(scoreTable(g),
            "go_to_goal: students/bob.cpp\n"
            "Check             Score       Result\n"
            "----------------  ----------  -------\n"
            "esc\\x1b[2J             0 / 2  FAIL\n"
            "    in empty, seed 1: the submission did not compile\n"
            "third of a point  0.3333 / 1  PARTIAL  [after_due_date]\n"
            "    in hidden world 2: bad \\x07 bell" +
                kNoDetails +
                "\n"
                "    in hidden world 3: x" +
                kNoDetails +
                "\n"
                "The submission did not compile:\n"
                "    bob.cpp:3:1: error: expected ';'\n"
                "      int x = 1\n"
                "              ^\n"
                "----------------  ----------  -------\n"
                "Total             0.3333 / 3\n");
}

// ---- Gradescope ----------------------------------------------------------------------------------

TEST(Gradescope, FieldsAsTheSpecificationNamesThem) {
  const fs::path dir = scratch("gradescope");
  const Grade g = sample();
  const Status s = writeGradescope(g, dir / "results.json");
  ASSERT_TRUE(s.ok()) << s.error();
  EXPECT_EQ(filesIn(dir), std::vector<std::string>{"results.json"});  // no .partial left behind
  const json doc = json::parse(readFile(dir / "results.json"));
  const json want = {
      {"score", 2.5},
      {"execution_time", 13},
      {"output",
       "1 of 2 visible checks passed: 2.5 / 3 points.\n1 more check is graded but not shown here.\n"
       "Note: the controller printed more than 1 MB; the rest was cut\n"},
      {"output_format", "text"},
      {"tests",
       {{{"name", "reaches the goal"},
         {"score", 2},
         {"max_score", 2},
         {"status", "passed"},
         {"output", "- **empty\\, seed 1**: passed\n- **maze\\, seed 2**: passed\n"},
         {"output_format", "md"},
         {"visibility", "visible"},
         {"tags", {"empty", "maze"}}},
        {{"name", "avoids walls"},
         {"score", 0.5},
         {"max_score", 1},
         {"status", "failed"},
         {"output", "- **maze\\, seed 3**: failed: touched a wall at 41\\.2 s at \\(3\\.1\\, 4\\.5\\)\n- **maze\\, seed 4**: passed\n"},
         {"output_format", "md"},
         {"visibility", "visible"},
         {"tags", {"maze"}}},
        {{"name", "secret worlds"},
         {"score", 0},
         {"max_score", 2},
         {"status", "failed"},
         {"output",
          "- **hidden world 1**: failed: it failed the rubric\\'s \\\"goal\\\" criterion \\(hidden worlds give no details\\: practise with frob "
          "grade \\-\\-practice\\)\n"},
         {"output_format", "md"},
         {"visibility", "hidden"},
         {"tags", json::array()}}}},
      {"extra_data",
       {{"submission_sha256", "5ca1ab1e"},
        {"runs",
         {{{"check", "reaches the goal"}, {"run", "empty, seed 1"}, {"trajectory", "0000000000000011"}},
          {{"check", "reaches the goal"}, {"run", "maze, seed 2"}, {"trajectory", "0000000000000012"}},
          {{"check", "avoids walls"}, {"run", "maze, seed 3"}, {"trajectory", "0000000000000013"}},
          {{"check", "avoids walls"}, {"run", "maze, seed 4"}, {"trajectory", "0000000000000014"}},
          {{"check", "secret worlds"}, {"run", "hidden world 1"}, {"trajectory", "0000000000000017"}}}}}},
  };
  EXPECT_EQ(doc, want) << doc.dump(2);
  EXPECT_TRUE(doc["execution_time"].is_number_integer());
}

TEST(Gradescope, TestOutputIsMarkdownInWhichNoTextOfTheRunMarksAnythingUp) {
  const fs::path dir = scratch("gradescope_markdown");
  Grade g = sample();
  const std::string hostile = "returned [click](http://evil.example) ![x](y) <b>*bold*</b> `code` # head | cell _em_ ~s~ \\ & done";
  g.checks[1].runs[0].reason = hostile;
  g.checks[1].runs[0].hints = {"hint [a](b)"};
  ASSERT_TRUE(writeGradescope(g, dir / "results.json").ok());
  const std::string md = json::parse(readFile(dir / "results.json"))["tests"][1]["output"];
  const std::string line = md.substr(0, md.find('\n'));
  const std::string shown = line.substr(line.find("failed: ") + 8);
  // Every ASCII punctuation character of the reason is escaped (CommonMark's backslash escapes), so it reads as written.
  std::string unescaped;
  for (std::size_t i = 0; i < shown.size(); ++i) {
    if (shown[i] == '\\') {
      ASSERT_LT(i + 1, shown.size());
      ASSERT_TRUE(std::ispunct(static_cast<unsigned char>(shown[i + 1]))) << shown;
      unescaped += shown[++i];
    } else {
      ASSERT_FALSE(std::ispunct(static_cast<unsigned char>(shown[i]))) << "unescaped '" << shown[i] << "' in " << shown;
      unescaped += shown[i];
    }
  }
  EXPECT_EQ(unescaped, hostile);
  EXPECT_NE(md.find("  - hint: hint \\[a\\]\\(b\\)\n"), std::string::npos) << md;
}

TEST(Gradescope, ALeaderboardEntryForEachBoardTheSubmissionIsOn) {
  const fs::path dir = scratch("gradescope_leaderboard");
  Grade g = sample();
  g.leaderboard = {{.name = "Time to wp4 (s)", .value = 60.31449, .ascending = true},
                   {.name = "Missed", .value = std::nullopt},
                   {.name = "Spare (m)", .value = 0.25, .ascending = false}};
  ASSERT_TRUE(writeGradescope(g, dir / "results.json").ok());
  const json want = {{{"name", "Time to wp4 (s)"}, {"value", 60.314}, {"order", "asc"}}, {{"name", "Spare (m)"}, {"value", 0.25}, {"order", "desc"}}};
  EXPECT_EQ(json::parse(readFile(dir / "results.json"))["leaderboard"], want);
  ASSERT_TRUE(writeGradescope(sample(), dir / "none.json").ok());
  EXPECT_FALSE(json::parse(readFile(dir / "none.json")).contains("leaderboard"));  // no board, no key
}

TEST(Grade, ALeaderboardValueIsTheMeanOverTheChecksRunsAndNoneWhenOneMissed) {
  Grade g = sample();
  const auto verdict = [](bool passed, double value, double at) {
    return CriterionVerdict{.criterion = "goal", .passed = passed, .margin = Margin{.value = value, .unit = "s", .at = at}};
  };
  g.checks[0].runs[0].criteria = {verdict(true, 5.0, 55.0)};
  g.checks[0].runs[1].criteria = {verdict(true, 2.0, 58.0)};
  const LeaderboardMetric time{.name = "t", .check = "reaches the goal", .measure = LeaderboardMetric::Measure::Time, .ascending = true};
  const LeaderboardMetric spare{.name = "s", .check = "reaches the goal", .measure = LeaderboardMetric::Measure::Margin};
  EXPECT_EQ(leaderboardValue(time, g).value, 56.5);
  EXPECT_EQ(leaderboardValue(spare, g).value, 3.5);
  EXPECT_TRUE(leaderboardValue(time, g).ascending);
  g.checks[0].runs[1].criteria = {verdict(false, -2.0, 62.0)};
  EXPECT_FALSE(leaderboardValue(time, g).value);  // a run missed it: no place on the board
  LeaderboardMetric other = time;
  other.check = "no such check";
  EXPECT_FALSE(leaderboardValue(other, g).value);
}

TEST(Gradescope, CompileErrorIsTheOutputAndBadUtf8IsReplaced) {
  const fs::path dir = scratch("gradescope_compile");
  ASSERT_TRUE(writeGradescope(uncompiled("bob.cpp:1:1: error: unknown type name 'caf\xe9'\n"), dir / "results.json").ok());
  const json doc = json::parse(readFile(dir / "results.json"));  // would throw on malformed UTF-8
  EXPECT_EQ(doc["output"], "The submission did not compile, so every check scores 0:\n\nbob.cpp:1:1: error: unknown type name 'caf\xEF\xBF\xBD'\n");
  EXPECT_EQ(doc["score"], 0);
  EXPECT_EQ(doc["execution_time"], 0);
  EXPECT_EQ(doc["tests"][0]["status"], "failed");
}

TEST(Gradescope, FailuresNameTheFile) {
  EXPECT_EQ(writeGradescope(sample(), "/nonexistent/out/results.json").error(),
            "gradescope results: cannot write '/nonexistent/out/results.json': directory '/nonexistent/out' does not exist");
  const fs::path dir = scratch("gradescope_dir");
  EXPECT_EQ(writeGradescope(sample(), dir).error(), "gradescope results: cannot write '" + dir.string() + "': it is a directory");
}

TEST(Gradescope, ReplacesAnOldFileWhole) {
  const fs::path dir = scratch("gradescope_replace");
  writeFile(dir / "results.json", std::string(100000, 'x'));
  ASSERT_TRUE(writeGradescope(sample(), dir / "results.json").ok());
  EXPECT_NO_THROW((void)json::parse(readFile(dir / "results.json")));
  EXPECT_EQ(filesIn(dir), std::vector<std::string>{"results.json"});
}

// ---- PrairieLearn --------------------------------------------------------------------------------

TEST(PrairieLearn, ScoreIsAFractionAndHiddenChecksAreSummed) {
  const fs::path dir = scratch("prairielearn");
  ASSERT_TRUE(writePrairieLearn(sample(), dir / "results.json").ok());
  const std::string text = readFile(dir / "results.json");
  const json want = {
      {"gradable", true},
      {"score", 0.5},
      {"message",
       "1 of 2 visible checks passed: 2.5 / 3 points.\n1 more check is graded but not shown here.\n"
       "Note: the controller printed more than 1 MB; the rest was cut\n"},
      {"output", "Note: the controller printed more than 1 MB; the rest was cut\n"},
      {"tests",
       {{{"name", "reaches the goal"}, {"points", 2}, {"max_points", 2}, {"output", ""}, {"message", "2 of 2 runs passed"}},
        {{"name", "avoids walls"},
         {"points", 0.5},
         {"max_points", 1},
         {"output", "in maze, seed 3: touched a wall at 41.2 s at (3.1, 4.5)\n"},
         {"message", "1 of 2 runs passed"}},
        {{"name", "Hidden checks"}, {"points", 0}, {"max_points", 2}, {"output", ""}, {"message", "1 check whose result is not shown"}}}},
  };
  EXPECT_EQ(json::parse(text), want) << text;
  // PrairieLearn shows students every test: nothing of the hidden check may be in the file.
  EXPECT_EQ(text.find("secret worlds"), std::string::npos);
  EXPECT_EQ(text.find("rooms"), std::string::npos);
}

TEST(PrairieLearn, AVisibleChecksPictureIsOnItsTestAndNoHiddenOnesAnywhere) {
  const fs::path dir = scratch("prairielearn_images");
  const std::string png = std::string("\x89PNG\r\n\x1a\n", 8) + std::string(300, '\x07');
  writeFile(dir / "plot.png", png);
  const std::vector<CheckImage> images = {{.check = "avoids walls", .label = "the first failing run: maze, seed 3", .png = dir / "plot.png"},
                                          {.check = "secret worlds", .label = "hidden", .png = dir / "plot.png"}};
  ASSERT_TRUE(writePrairieLearn(sample(), dir / "results.json", images).ok());
  const std::string text = readFile(dir / "results.json");
  const json doc = json::parse(text);
  EXPECT_FALSE(doc["tests"][0].contains("images"));
  ASSERT_EQ(doc["tests"][1]["images"].size(), 1u);
  EXPECT_EQ(doc["tests"][1]["images"][0]["label"], "the first failing run: maze, seed 3");
  const std::string url = doc["tests"][1]["images"][0]["url"];
  const std::string prefix = "data:image/png;base64,";
  ASSERT_EQ(url.substr(0, prefix.size()), prefix);
  EXPECT_EQ(url.substr(prefix.size(), 12), "iVBORw0KGgoH");  // the PNG signature, then the first 0x07
  EXPECT_EQ(url.size(), prefix.size() + (png.size() + 2) / 3 * 4);
  EXPECT_FALSE(doc["tests"][2].contains("images"));
  EXPECT_EQ(text.find("hidden\""), std::string::npos);
  // A picture that would take the file past 1 MB is left out; the results stay whole.
  writeFile(dir / "big.png", std::string(800'000, 'x'));
  ASSERT_TRUE(writePrairieLearn(sample(), dir / "big.json", {{.check = "avoids walls", .label = "big", .png = dir / "big.png"}}).ok());
  const std::string big = readFile(dir / "big.json");
  EXPECT_LE(big.size(), 1'000'000u);
  EXPECT_FALSE(json::parse(big)["tests"][1].contains("images"));
  // The picture goes before any text is cut.
  Grade wordy = sample();
  wordy.notes = {std::string(600'000, 'n')};
  writeFile(dir / "mid.png", std::string(300'000, 'x'));
  ASSERT_TRUE(writePrairieLearn(wordy, dir / "wordy.json", {{.check = "avoids walls", .label = "mid", .png = dir / "mid.png"}}).ok());
  const json kept = json::parse(readFile(dir / "wordy.json"));
  EXPECT_FALSE(kept["tests"][1].contains("images"));
  EXPECT_EQ(kept["output"], "Note: " + wordy.notes[0] + "\n");
}

TEST(PrairieLearn, NotCompilingIsNotGradable) {
  const fs::path dir = scratch("prairielearn_compile");
  ASSERT_TRUE(writePrairieLearn(uncompiled("bob.cpp:3:1: error: expected ';'\n"), dir / "results.json").ok());
  const json want = {
      {"gradable", false},
      {"score", 0},
      {"message", "The submission did not compile; it was not graded and no attempt was used up."},
      {"output", "bob.cpp:3:1: error: expected ';'\n"},
      {"format_errors", "bob.cpp:3:1: error: expected ';'\n"},
      {"tests", json::array()},
  };
  EXPECT_EQ(json::parse(readFile(dir / "results.json")), want);
}

TEST(PrairieLearn, StaysUnderOneMegabyte) {
  const fs::path dir = scratch("prairielearn_big");
  std::string error;
  while (error.size() < 3'000'000) error += "bob.cpp:1:1: error: something long and repeated " + std::to_string(error.size()) + "\n";
  ASSERT_TRUE(writePrairieLearn(uncompiled(error), dir / "results.json").ok());
  const std::string text = readFile(dir / "results.json");
  EXPECT_LE(text.size(), 1'000'000u);
  EXPECT_GT(text.size(), 200'000u);  // cut, not dropped
  const json doc = json::parse(text);
  const std::string kept = doc["format_errors"];
  EXPECT_EQ(kept.substr(0, 60), error.substr(0, 60));
  EXPECT_NE(kept.find("more bytes cut]"), std::string::npos);
}

// ---- JUnit ---------------------------------------------------------------------------------------

TEST(JUnit, ReadsBackWithAStrictXmlParser) {
  const fs::path dir = scratch("junit");
  Grade g = sample();
  g.assignment = "go \"to\" <goal> & 'back'";
  g.checks[1].runs[0].reason = kHostile;
  g.checks[2].visibility = Visibility::Visible;
  g.checks[2].runs[0].reason = "two lines,\nkept\tapart\r\n";
  const Status s = writeJUnit(g, dir / "junit.xml");
  ASSERT_TRUE(s.ok()) << s.error();
  EXPECT_EQ(filesIn(dir), std::vector<std::string>{"junit.xml"});
  const std::string text = readFile(dir / "junit.xml");
  const Doc doc = parseXml(text);
  ASSERT_TRUE(doc) << "not well-formed XML 1.0:\n" << text;
  EXPECT_EQ(one(doc.get(), "/testsuite/@name"), g.assignment);
  EXPECT_EQ(one(doc.get(), "/testsuite/@tests"), "5");
  EXPECT_EQ(one(doc.get(), "/testsuite/@failures"), "2");
  EXPECT_EQ(one(doc.get(), "/testsuite/@errors"), "0");
  EXPECT_EQ(one(doc.get(), "/testsuite/@time"), "12.600");
  EXPECT_EQ(select(doc.get(), "/testsuite/testcase/@name"),
            (std::vector<std::string>{"reaches the goal / empty, seed 1", "reaches the goal / maze, seed 2", "avoids walls / maze, seed 3",
                                      "avoids walls / maze, seed 4", "secret worlds / rooms, seed 7"}));
  EXPECT_EQ(select(doc.get(), "/testsuite/testcase/@classname"), std::vector<std::string>(5, g.assignment));
  EXPECT_EQ(select(doc.get(), "//testcase[@name='avoids walls / maze, seed 3']/failure/@message"), std::vector<std::string>{kHostileRead});
  EXPECT_EQ(select(doc.get(), "//testcase[@name='avoids walls / maze, seed 3']/failure"), std::vector<std::string>{""});  // said once
  // Line breaks and tabs survive in attributes (a parser turns raw ones into spaces).
  EXPECT_EQ(select(doc.get(), "//testcase[@name='secret worlds / rooms, seed 7']/failure/@message"),
            std::vector<std::string>{"two lines,\nkept\tapart\r\n"});
  EXPECT_EQ(select(doc.get(), "//failure").size(), 2u);
  EXPECT_EQ(one(doc.get(), "/testsuite/system-out"), "the controller printed more than 1 MB; the rest was cut\n");
  EXPECT_EQ(text.find('\x01'), std::string::npos);
}

// A hidden run's length is never shown: a controller that sleeps within its pace, in proportion
// to what its sonar reads, would spell out a hidden world in its time. Its testcase takes 0 s, and
// the totals (the suite's, Gradescope's execution_time) leave the hidden runs out.
TEST(JUnit, AHiddenRunsLengthIsShownNowhere) {
  const fs::path dir = scratch("junit_hidden_time");
  Grade g = sample();
  g.wallSeconds = 20.0;
  g.checks[0].runs[0].wallSeconds = 1.5;
  g.checks[2].runs[0].wallSeconds = 7.875;
  ASSERT_TRUE(writeJUnit(g, dir / "junit.xml").ok());
  const Doc doc = parseXml(readFile(dir / "junit.xml"));
  EXPECT_EQ(one(doc.get(), "//testcase[@name='reaches the goal / empty, seed 1']/@time"), "1.500");
  EXPECT_EQ(one(doc.get(), "//testcase[@name='secret worlds / hidden world 1']/@time"), "0.000");
  EXPECT_EQ(one(doc.get(), "/testsuite/@time"), "12.125");
  ASSERT_TRUE(writeGradescope(g, dir / "results.json").ok());
  EXPECT_EQ(json::parse(readFile(dir / "results.json"))["execution_time"], 12);
  g.checks[2].visibility = Visibility::Visible;  // seen, its length is shown as it is
  EXPECT_EQ(g.shownSeconds(), 20.0);
}

// Why `text` is not valid against the Apache Ant JUnit schema; "" when it is.
std::string antSchemaErrors(const std::string& text) {
  std::string errors;
  xmlSchemaParserCtxt* parser = xmlSchemaNewParserCtxt(FROB_JUNIT_XSD);
  xmlSchema* schema = xmlSchemaParse(parser);
  xmlSchemaValidCtxt* valid = xmlSchemaNewValidCtxt(schema);
  xmlSchemaSetValidStructuredErrors(
      valid, [](void* out, xmlError* e) { *static_cast<std::string*>(out) += "line " + std::to_string(e->line) + ": " + e->message; }, &errors);
  const Doc doc = parseXml(text);
  if (schema == nullptr)
    errors = "cannot read the schema " FROB_JUNIT_XSD;
  else if (!doc)
    errors = "not well-formed";
  else if (xmlSchemaValidateDoc(valid, doc.get()) != 0 && errors.empty())
    errors = "invalid";
  xmlSchemaFreeValidCtxt(valid);
  xmlSchemaFree(schema);
  xmlSchemaFreeParserCtxt(parser);
  return errors;
}

// Strict JUnit readers (Ant's JUnitReport, and what follows its schema) take it: every required
// attribute and element, and each reason said once (the message), with the hints as the text.
TEST(JUnit, IsValidAgainstTheAntSchemaAndSaysEachReasonOnce) {
  const fs::path dir = scratch("junit_ant");
  Grade g = sample();
  g.startedAt = "2026-12-02T21:58:37";
  g.checks[1].runs[0].hints = {"it turned the wrong way"};
  g.checks[1].runs[0].wallSeconds = 1.25;
  ASSERT_TRUE(writeJUnit(g, dir / "junit.xml").ok());
  const std::string text = readFile(dir / "junit.xml");
  EXPECT_EQ(antSchemaErrors(text), "") << text;
  const Doc doc = parseXml(text);
  EXPECT_EQ(one(doc.get(), "/testsuite/@timestamp"), "2026-12-02T21:58:37");
  EXPECT_NE(one(doc.get(), "/testsuite/@hostname"), "");
  EXPECT_EQ(select(doc.get(), "/testsuite/properties/property/@name"), (std::vector<std::string>{"submission", "score", "max_score"}));
  EXPECT_EQ(one(doc.get(), "/testsuite/properties/property[@name='score']/@value"), "2.5");
  EXPECT_EQ(one(doc.get(), "//testcase[@name='avoids walls / maze, seed 3']/@time"), "1.250");
  EXPECT_EQ(one(doc.get(), "//testcase[@name='avoids walls / maze, seed 3']/failure/@type"), "check failed");
  EXPECT_EQ(one(doc.get(), "//testcase[@name='avoids walls / maze, seed 3']/failure"), "hint: it turned the wrong way\n");
  for (const std::string& body : select(doc.get(), "//failure")) {
    for (const std::string& message : select(doc.get(), "//failure/@message")) EXPECT_EQ(body.find(message), std::string::npos) << body;
  }
  EXPECT_NE(antSchemaErrors(std::string(text).replace(text.find("timestamp"), 9, "startedAt")), "");  // the check can fail
  ASSERT_TRUE(writeJUnit(uncompiled("bob.cpp:3:1: error: expected ';'\n"), dir / "compile.xml").ok());
  EXPECT_EQ(antSchemaErrors(readFile(dir / "compile.xml")), "") << readFile(dir / "compile.xml");
}

TEST(JUnit, CompileErrorIsAFailedTestcase) {
  const fs::path dir = scratch("junit_compile");
  ASSERT_TRUE(writeJUnit(uncompiled("bob.cpp:3:1: error: expected ';' before '}' & \x02\n"), dir / "junit.xml").ok());
  const Doc doc = parseXml(readFile(dir / "junit.xml"));
  ASSERT_TRUE(doc);
  EXPECT_EQ(one(doc.get(), "/testsuite/@tests"), "2");
  EXPECT_EQ(one(doc.get(), "/testsuite/@failures"), "2");
  EXPECT_EQ(one(doc.get(), "/testsuite/@time"), "0.400");
  EXPECT_EQ(one(doc.get(), "//testcase[@name='compile']/failure/@message"), "the submission did not compile");
  EXPECT_EQ(one(doc.get(), "//testcase[@name='compile']/failure"), "bob.cpp:3:1: error: expected ';' before '}' & \xEF\xBF\xBD\n");
  EXPECT_EQ(one(doc.get(), "//testcase[@name='reaches the goal / empty, seed 1']/failure/@message"), "the submission did not compile");
}

// ---- Gradebooks ----------------------------------------------------------------------------------

TEST(Gradebook, ExactBytesSortedAndQuoted) {
  const fs::path dir = scratch("gradebook");
  // A compile error, a crash and a weak run all score 0; the result column tells them apart.
  Grade crashed = scored("carl.cpp", 0, 0);
  crashed.checks[0].runs = {
      fail("empty", 1, "touched a wall at 3.0 s"),
      fail("maze", 2, "the controller failed: nomad: crashed with SIGSEGV (a bad pointer, or an index out of range?) at t = 1.01 s")};
  crashed.checks[1].runs = {fail("maze", 3, "the controller failed: nomad: its step took longer than 1 s")};
  Grade broken = uncompiled("could not compile 'dan.cpp' (the compiler's messages follow)\ndan.cpp:3:1: error: expected ';'\nmore\n");
  broken.submission = "dan.cpp";
  const Status s = writeGradebook(
      {scored("zed.cpp", 2, 1), scored("alice, \"the\" great.cpp", 2, 0.5), scored("bob.cpp", 0, 1.0 / 3.0), crashed, broken}, dir / "class.csv");
  ASSERT_TRUE(s.ok()) << s.error();
  EXPECT_EQ(readFile(dir / "class.csv"),
            "submission,score,max_score,result,reaches the goal,\"avoids walls, maze\"\r\n"
            "\"alice, \"\"the\"\" great.cpp\",2.5,3,graded,2,0.5\r\n"
            "bob.cpp,0.3333,3,graded,0,0.3333\r\n"
            "carl.cpp,0,3,\"failed at run time in 2 of 3 runs: nomad: crashed with SIGSEGV (a bad pointer, or an index out of range?) at t = "
            "1....\",0,0\r\n"
            "dan.cpp,0,2,did not compile: expected ';',0,\r\n"
            "zed.cpp,3,3,graded,2,1\r\n");
  EXPECT_EQ(filesIn(dir), std::vector<std::string>{"class.csv"});
}

TEST(Gradebook, ASubmissionGradedTwiceIsAnError) {
  const fs::path dir = scratch("gradebook_twice");
  EXPECT_EQ(writeGradebook({scored("bob.cpp", 0, 1), scored("bob.cpp", 2, 1)}, dir / "class.csv").error(),
            "gradebook: cannot write '" + (dir / "class.csv").string() + "': submission 'bob.cpp' is graded twice");
  EXPECT_TRUE(fs::is_empty(dir));
}

// A cell a spreadsheet would run as a formula is written as text (an apostrophe first, as an
// apostrophe first is too), numbers stay numbers, and control characters never reach the file; a
// merge reads each name back as it was.
TEST(Gradebook, NoCellIsAFormulaOrAControlCharacter) {
  const fs::path dir = scratch("gradebook_formulas");
  const std::vector<Grade> grades{scored("=HYPERLINK(\"http://evil.example\",\"x\").cpp", 2, 1), scored("@SUM(1).cpp", 0, 0),
                                  scored("'quoted.cpp", 1, 0), scored("-2+3.cpp", 1, 1)};
  ASSERT_TRUE(writeGradebook(grades, dir / "class.csv").ok());
  EXPECT_EQ(readFile(dir / "class.csv"),
            "submission,score,max_score,result,reaches the goal,\"avoids walls, maze\"\r\n"
            "''quoted.cpp,1,3,graded,1,0\r\n"
            "'-2+3.cpp,2,3,graded,1,1\r\n"
            "\"'=HYPERLINK(\"\"http://evil.example\"\",\"\"x\"\").cpp\",3,3,graded,2,1\r\n"
            "'@SUM(1).cpp,0,3,graded,0,0\r\n");
  const Result<std::vector<std::string>> merged = mergeGradebooks({dir / "class.csv"}, dir / "merged.csv");
  ASSERT_TRUE(merged.ok()) << merged.error();
  EXPECT_EQ(merged.value(), (std::vector<std::string>{"'quoted.cpp", "-2+3.cpp", "=HYPERLINK(\"http://evil.example\",\"x\").cpp", "@SUM(1).cpp"}));
  EXPECT_EQ(readFile(dir / "merged.csv"), readFile(dir / "class.csv"));
  ASSERT_TRUE(writeGradebook({scored("\x1b]0;owned\x07.cpp", 0, 1)}, dir / "escapes.csv").ok());
  EXPECT_EQ(readFile(dir / "escapes.csv"),
            "submission,score,max_score,result,reaches the goal,\"avoids walls, maze\"\r\n?]0;owned?.cpp,1,3,graded,0,1\r\n");
}

TEST(Gradebook, MergedShardsEqualOneGradebook) {
  const fs::path dir = scratch("merge");
  const std::vector<Grade> a{scored("zed.cpp", 2, 1), scored("alice, \"the\" great.cpp", 2, 0.5)};
  const std::vector<Grade> b{scored("bob.cpp", 0, 1.0 / 3.0), scored("new\nline.cpp", 1, 0)};
  ASSERT_TRUE(writeGradebook(a, dir / "a.csv").ok());
  ASSERT_TRUE(writeGradebook(b, dir / "b.csv").ok());
  std::vector<Grade> all = a;
  all.insert(all.end(), b.begin(), b.end());
  ASSERT_TRUE(writeGradebook(all, dir / "all.csv").ok());
  const Result<std::vector<std::string>> merged = mergeGradebooks({dir / "b.csv", dir / "a.csv"}, dir / "merged.csv");
  ASSERT_TRUE(merged.ok()) << merged.error();
  EXPECT_EQ(merged.value(), (std::vector<std::string>{"alice, \"the\" great.cpp", "bob.cpp", "new\nline.cpp", "zed.cpp"}));
  EXPECT_EQ(readFile(dir / "merged.csv"), readFile(dir / "all.csv"));
  EXPECT_EQ(filesIn(dir), (std::vector<std::string>{"a.csv", "all.csv", "b.csv", "merged.csv"}));
}

TEST(Gradebook, MergeAcceptsLineFeedsAlone) {
  const fs::path dir = scratch("merge_lf");
  writeFile(dir / "a.csv", "submission,score,max_score,x\nb.cpp,1,1,1\na.cpp,0,1,0\n");
  const Result<std::vector<std::string>> merged = mergeGradebooks({dir / "a.csv"}, dir / "merged.csv");
  ASSERT_TRUE(merged.ok()) << merged.error();
  EXPECT_EQ(readFile(dir / "merged.csv"), "submission,score,max_score,x\r\na.cpp,0,1,0\r\nb.cpp,1,1,1\r\n");
}

TEST(Gradebook, MergeErrorsNameTheFile) {
  const fs::path dir = scratch("merge_errors");
  ASSERT_TRUE(writeGradebook({scored("bob.cpp", 0, 1), scored("eve.cpp", 2, 1)}, dir / "a.csv").ok());
  ASSERT_TRUE(writeGradebook({scored("alice.cpp", 2, 1), scored("bob.cpp", 2, 0)}, dir / "b.csv").ok());
  Grade other = scored("carol.cpp", 2, 1);
  other.checks[1].name = "stops";
  ASSERT_TRUE(writeGradebook({other}, dir / "c.csv").ok());
  writeFile(dir / "open_quote.csv", "submission,score,max_score\r\n\"dan.cpp,1,1\r\n");
  writeFile(dir / "short.csv", "submission,score,max_score,reaches the goal\r\ndan.cpp,1\r\n");
  writeFile(dir / "after_quote.csv", "submission,score,max_score\r\n\"two\r\nlines\"x,1,1\r\n");
  writeFile(dir / "inner_quote.csv", "submission,score,max_score\r\nda\"n.cpp,1,1\r\n");
  const std::string a = (dir / "a.csv").string(), b = (dir / "b.csv").string(), c = (dir / "c.csv").string();
  const std::string out = (dir / "merged.csv").string();

  EXPECT_EQ(mergeGradebooks({a, b}, out).error(), "gradebook: submission 'bob.cpp' is in " + a + ":2 and in " + b + ":3");
  EXPECT_EQ(mergeGradebooks({a, c}, out).error(), "gradebook: " + c +
                                                      ":1: its header \"submission,score,max_score,result,reaches the goal,stops\" differs from "
                                                      "\"submission,score,max_score,result,reaches the goal,\"avoids walls, maze\"\" of " +
                                                      a + " (gradebooks of different rubrics?)");
  EXPECT_EQ(mergeGradebooks({dir / "open_quote.csv"}, out).error(),
            "gradebook: " + (dir / "open_quote.csv").string() + ":2: a quoted field is not closed");
  EXPECT_EQ(mergeGradebooks({dir / "short.csv"}, out).error(), "gradebook: " + (dir / "short.csv").string() + ":2: 2 fields where the header has 4");
  EXPECT_EQ(mergeGradebooks({dir / "after_quote.csv"}, out).error(),
            "gradebook: " + (dir / "after_quote.csv").string() + ":3: text after a closing quote");
  EXPECT_EQ(mergeGradebooks({dir / "inner_quote.csv"}, out).error(),
            "gradebook: " + (dir / "inner_quote.csv").string() + ":2: a quote inside an unquoted field");
  EXPECT_EQ(mergeGradebooks({dir / "missing.csv"}, out).error(),
            "gradebook: cannot read '" + (dir / "missing.csv").string() + "': No such file or directory");
  EXPECT_EQ(mergeGradebooks({}, out).error(), "gradebook: no gradebooks to merge into '" + out + "'");
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
}  // namespace frob::course
