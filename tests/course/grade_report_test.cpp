// The grade's writers: the terminal table and the CSV byte for byte, the results.json files field by
// field, the JUnit XML read back by libxml2, and the HTML report rendered by Debian's headless
// Chromium (a screenshot, its DOM, and the video's state once the page has loaded).
#include "frob/course/grade_report.hpp"

#include "frob/render/image.hpp"
#include "frob/render/video.hpp"

#include <nlohmann/json.hpp>

#include <fcntl.h>
#include <gtest/gtest.h>
#include <libxml/HTMLparser.h>
#include <libxml/parser.h>
#include <libxml/tree.h>
#include <libxml/xpath.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

extern char** environ;

namespace frob::course {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// ---- Grades written by hand ----------------------------------------------------------------------

RunGrade pass(std::string world, std::uint64_t seed) { return {.world = std::move(world), .seed = seed, .passed = true}; }

RunGrade fail(std::string world, std::uint64_t seed, std::string reason) {
  return {.world = std::move(world), .seed = seed, .passed = false, .reason = std::move(reason)};
}

// Markup, both quotes, an ampersand and a control character XML 1.0 forbids even as a reference.
const std::string kHostile = "bumped <script>alert(1)</script> & \"double\" 'single' \x01 here";
// What XML and HTML readers get back: the control character replaced by U+FFFD.
const std::string kHostileRead = "bumped <script>alert(1)</script> & \"double\" 'single' \xEF\xBF\xBD here";

Grade sample() {
  Grade g;
  g.assignment = "go_to_goal";
  g.submission = "students/alice.cpp";
  g.wallSeconds = 12.6;
  g.checks = {
      {.name = "reaches the goal", .points = 2, .score = 2, .runs = {pass("empty", 1), pass("maze", 2)}},
      {.name = "avoids walls", .points = 1, .score = 0.5, .runs = {fail("maze", 3, "touched a wall at 41.2 s at (3.1, 4.5)"), pass("maze", 4)}},
      {.name = "secret worlds",
       .points = 2,
       .score = 0,
       .visibility = Visibility::Hidden,
       .runs = {fail("rooms", 7, "not within 0.3 m of goal by 60 s")}},
  };
  g.notes = {"the controller printed more than 1 MB; the rest was cut"};
  return g;
}

// As grade() gives it when the file did not compile: every run failed for that reason.
Grade uncompiled(std::string compileError) {
  Grade g;
  g.assignment = "go_to_goal";
  g.submission = "students/bob.cpp";
  g.compileError = std::move(compileError);
  g.wallSeconds = 0.4;
  g.checks = {{.name = "reaches the goal", .points = 2, .score = 0, .runs = {fail("empty", 1, "the submission did not compile")}}};
  return g;
}

// One grade of the gradebook: checks "reaches the goal" (2 points) and "avoids walls, maze" (1 point).
Grade scored(std::string submission, double reach, double walls) {
  Grade g;
  g.assignment = "go_to_goal";
  g.submission = std::move(submission);
  g.checks = {{.name = "reaches the goal", .points = 2, .score = reach}, {.name = "avoids walls, maze", .points = 1, .score = walls}};
  return g;
}

// ---- Files ---------------------------------------------------------------------------------------

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::path(::testing::TempDir()) / "grade_report_test" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string readFile(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

void writeFile(const fs::path& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary);
  out << bytes;
}

std::vector<std::string> filesIn(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

// ---- XML and HTML read back with libxml2 --------------------------------------------------------

struct DocFree {
  void operator()(xmlDoc* d) const { xmlFreeDoc(d); }
};
using Doc = std::unique_ptr<xmlDoc, DocFree>;

// A strict XML 1.0 parse: any well-formedness error (a bad character, a bad escape) gives null.
Doc parseXml(const std::string& text) {
  return Doc(
      xmlReadMemory(text.data(), static_cast<int>(text.size()), "report.xml", "UTF-8", XML_PARSE_NONET | XML_PARSE_NOERROR | XML_PARSE_NOWARNING));
}

// An HTML parse, as lenient as a browser's (for Chromium's serialized DOM).
Doc parseHtml(const std::string& text) {
  return Doc(htmlReadMemory(text.data(), static_cast<int>(text.size()), "page.html", "UTF-8",
                            HTML_PARSE_NONET | HTML_PARSE_NOERROR | HTML_PARSE_NOWARNING | HTML_PARSE_NOBLANKS));
}

// The string values of the nodes `xpath` selects (attributes' values, elements' text).
std::vector<std::string> select(xmlDoc* doc, const std::string& xpath) {
  std::vector<std::string> values;
  xmlXPathContext* ctx = xmlXPathNewContext(doc);
  xmlXPathObject* found = xmlXPathEvalExpression(reinterpret_cast<const xmlChar*>(xpath.c_str()), ctx);
  if (found != nullptr && found->nodesetval != nullptr) {
    for (int i = 0; i < found->nodesetval->nodeNr; ++i) {
      xmlChar* text = xmlNodeGetContent(found->nodesetval->nodeTab[i]);
      values.emplace_back(text != nullptr ? reinterpret_cast<const char*>(text) : "");
      xmlFree(text);
    }
  }
  xmlXPathFreeObject(found);
  xmlXPathFreeContext(ctx);
  return values;
}

std::string one(xmlDoc* doc, const std::string& xpath) {
  const std::vector<std::string> v = select(doc, xpath);
  EXPECT_EQ(v.size(), 1u) << xpath;
  return v.empty() ? std::string("<none>") : v[0];
}

std::string unbase64(std::string_view text) {
  std::string out;
  std::uint32_t acc = 0;
  int bits = 0;
  for (char c : text) {
    int v = -1;
    if (c >= 'A' && c <= 'Z') v = c - 'A';
    if (c >= 'a' && c <= 'z') v = c - 'a' + 26;
    if (c >= '0' && c <= '9') v = c - '0' + 52;
    if (c == '+') v = 62;
    if (c == '/') v = 63;
    if (c == '=') break;
    if (v < 0) return "<not base64>";
    acc = (acc << 6) | static_cast<std::uint32_t>(v);
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      out += static_cast<char>((acc >> bits) & 0xFF);
    }
  }
  return out;
}

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
            "    in rooms, seed 7: not within 0.3 m of goal by 60 s\n"
            "----------------  -------  -------\n"
            "Total             2.5 / 5\n"
            "Note: the controller printed more than 1 MB; the rest was cut\n");
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
            "esc?[2J                0 / 2  FAIL\n"
            "    in empty, seed 1: the submission did not compile\n"
            "third of a point  0.3333 / 1  PARTIAL  [after_due_date]\n"
            "    in maze, seed 2: bad ? bell\n"
            "    in maze, seed 3: x\n"
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
         {"output", ""},
         {"visibility", "visible"},
         {"tags", {"empty", "maze"}}},
        {{"name", "avoids walls"},
         {"score", 0.5},
         {"max_score", 1},
         {"status", "failed"},
         {"output", "in maze, seed 3: touched a wall at 41.2 s at (3.1, 4.5)\n"},
         {"visibility", "visible"},
         {"tags", {"maze"}}},
        {{"name", "secret worlds"},
         {"score", 0},
         {"max_score", 2},
         {"status", "failed"},
         {"output", "in rooms, seed 7: not within 0.3 m of goal by 60 s\n"},
         {"visibility", "hidden"},
         {"tags", {"rooms"}}}}},
  };
  EXPECT_EQ(doc, want) << doc.dump(2);
  EXPECT_TRUE(doc["execution_time"].is_number_integer());
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
            (std::vector<std::string>{"reaches the goal / empty seed 1", "reaches the goal / maze seed 2", "avoids walls / maze seed 3",
                                      "avoids walls / maze seed 4", "secret worlds / rooms seed 7"}));
  EXPECT_EQ(select(doc.get(), "/testsuite/testcase/@classname"), std::vector<std::string>(5, g.assignment));
  EXPECT_EQ(select(doc.get(), "//testcase[@name='avoids walls / maze seed 3']/failure/@message"), std::vector<std::string>{kHostileRead});
  EXPECT_EQ(select(doc.get(), "//testcase[@name='avoids walls / maze seed 3']/failure"), std::vector<std::string>{kHostileRead});
  // Line breaks and tabs survive in attributes (a parser turns raw ones into spaces).
  EXPECT_EQ(select(doc.get(), "//testcase[@name='secret worlds / rooms seed 7']/failure/@message"),
            std::vector<std::string>{"two lines,\nkept\tapart\r\n"});
  EXPECT_EQ(select(doc.get(), "//failure").size(), 2u);
  EXPECT_EQ(one(doc.get(), "/testsuite/system-out"), "the controller printed more than 1 MB; the rest was cut\n");
  EXPECT_EQ(text.find('\x01'), std::string::npos);
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
  EXPECT_EQ(one(doc.get(), "//testcase[@name='reaches the goal / empty seed 1']/failure/@message"), "the submission did not compile");
}

// ---- Gradebooks ----------------------------------------------------------------------------------

TEST(Gradebook, ExactBytesSortedAndQuoted) {
  const fs::path dir = scratch("gradebook");
  const Status s =
      writeGradebook({scored("zed.cpp", 2, 1), scored("alice, \"the\" great.cpp", 2, 0.5), scored("bob.cpp", 0, 1.0 / 3.0)}, dir / "class.csv");
  ASSERT_TRUE(s.ok()) << s.error();
  EXPECT_EQ(readFile(dir / "class.csv"),
            "submission,score,max_score,reaches the goal,\"avoids walls, maze\"\r\n"
            "\"alice, \"\"the\"\" great.cpp\",2.5,3,2,0.5\r\n"
            "bob.cpp,0.3333,3,0,0.3333\r\n"
            "zed.cpp,3,3,2,1\r\n");
  EXPECT_EQ(filesIn(dir), std::vector<std::string>{"class.csv"});
}

TEST(Gradebook, ASubmissionGradedTwiceIsAnError) {
  const fs::path dir = scratch("gradebook_twice");
  EXPECT_EQ(writeGradebook({scored("bob.cpp", 0, 1), scored("bob.cpp", 2, 1)}, dir / "class.csv").error(),
            "gradebook: cannot write '" + (dir / "class.csv").string() + "': submission 'bob.cpp' is graded twice");
  EXPECT_TRUE(fs::is_empty(dir));
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
                                                      ":1: its header \"submission,score,max_score,reaches the goal,stops\" differs from "
                                                      "\"submission,score,max_score,reaches the goal,\"avoids walls, maze\"\" of " +
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

// ---- The HTML report, as written ----------------------------------------------------------------

// A grade whose failed run has a hostile reason, with a short MP4 and a PNG plot of distinct colours.
struct Report {
  fs::path dir, html, video, plot;
  Grade grade;
};

constexpr std::uint8_t kVideoColour[3] = {220, 40, 200};  // magenta
constexpr std::uint8_t kPlotColour[3] = {40, 200, 220};   // cyan
constexpr int kVideoW = 160, kVideoH = 96, kVideoFrames = 15, kFps = 30;
constexpr int kPlotW = 120, kPlotH = 80;

render::Image solid(int w, int h, const std::uint8_t (&rgb)[3]) {
  render::Image img{.width = w, .height = h, .rgba = {}};
  for (int i = 0; i < w * h; ++i) img.rgba.insert(img.rgba.end(), {rgb[0], rgb[1], rgb[2], 255});
  return img;
}

Report writeReport(const std::string& name) {
  Report r{.dir = scratch(name), .html = {}, .video = {}, .plot = {}, .grade = sample()};
  r.html = r.dir / "report.html";
  r.video = r.dir / "run.mp4";
  r.plot = r.dir / "plot.png";
  r.grade.checks[1].runs[0].reason = kHostile;
  Result<render::VideoWriter> v = render::VideoWriter::open({.path = r.video.string(), .width = kVideoW, .height = kVideoH, .fps = kFps});
  EXPECT_TRUE(v.ok()) << v.error();
  for (int i = 0; i < kVideoFrames && v.ok(); ++i) EXPECT_TRUE(v.value().write(solid(kVideoW, kVideoH, kVideoColour)).ok());
  if (v.ok()) EXPECT_TRUE(v.value().close().ok());
  EXPECT_TRUE(render::writePng(r.plot.string(), solid(kPlotW, kPlotH, kPlotColour)).ok());
  const Status s = writeHtmlReport(r.grade, {.video = r.video, .plot = r.plot, .caption = "the first failing run: maze, seed 3 <&>"}, r.html);
  EXPECT_TRUE(s.ok()) << s.error();
  return r;
}

TEST(HtmlReport, SelfContainedAndEscaped) {
  const Report r = writeReport("html_text");
  const std::string page = readFile(r.html);
  EXPECT_NE(page.find("bumped &lt;script&gt;alert(1)&lt;/script&gt; &amp; &quot;double&quot; &#39;single&#39; \xEF\xBF\xBD here"), std::string::npos);
  EXPECT_EQ(page.find("<script"), std::string::npos);
  EXPECT_EQ(page.find("http:"), std::string::npos);
  EXPECT_EQ(page.find("https:"), std::string::npos);
  // Every src is a data: URI (no file, no protocol-relative URL); CSS loads nothing either.
  std::size_t srcs = 0;
  for (std::size_t at = page.find("src=\""); at != std::string::npos; at = page.find("src=\"", at + 1)) {
    ++srcs;
    EXPECT_EQ(page.compare(at, 10, "src=\"data:"), 0) << page.substr(at, 40);
  }
  EXPECT_EQ(srcs, 2u);
  EXPECT_EQ(page.find("url("), std::string::npos);
  EXPECT_EQ(page.find("@import"), std::string::npos);
  EXPECT_EQ(page.find("<link"), std::string::npos);
  EXPECT_EQ(page.find('\x01'), std::string::npos);
  EXPECT_NE(page.find("<video controls src=\"data:video/mp4;base64,"), std::string::npos);
  EXPECT_NE(page.find("<img src=\"data:image/png;base64,"), std::string::npos);
  EXPECT_NE(page.find("<figcaption>the first failing run: maze, seed 3 &lt;&amp;&gt;</figcaption>"), std::string::npos);
  EXPECT_EQ(filesIn(r.dir), (std::vector<std::string>{"plot.png", "report.html", "run.mp4"}));
}

TEST(HtmlReport, CompileErrorInPreAndNoMedia) {
  const fs::path dir = scratch("html_compile");
  ASSERT_TRUE(writeHtmlReport(uncompiled("bob.cpp:3:1: error: expected '>' in <vector<int>\n"), {}, dir / "r.html").ok());
  const std::string page = readFile(dir / "r.html");
  EXPECT_NE(page.find("<pre class=\"compile-error\">bob.cpp:3:1: error: expected &#39;&gt;&#39; in &lt;vector&lt;int&gt;\n</pre>"),
            std::string::npos);
  EXPECT_EQ(page.find("<figure>"), std::string::npos);
}

TEST(HtmlReport, Base64OfEveryLength) {
  const fs::path dir = scratch("html_base64");
  const std::string signature = "\x89PNG\r\n\x1a\n";
  const std::vector<std::pair<std::string, std::string>> cases{
      {"", "iVBORw0KGgo="}, {"a", "iVBORw0KGgph"}, {"ab", "iVBORw0KGgphYg=="}, {"abc", "iVBORw0KGgphYmM="}};
  for (const auto& [tail, encoded] : cases) {
    writeFile(dir / "p.png", signature + tail);
    ASSERT_TRUE(writeHtmlReport(sample(), {.plot = dir / "p.png"}, dir / "r.html").ok());
    EXPECT_NE(readFile(dir / "r.html").find("src=\"data:image/png;base64," + encoded + "\""), std::string::npos) << tail;
  }
}

TEST(HtmlReport, BadMediaAreNamedAndNothingIsWritten) {
  const fs::path dir = scratch("html_bad_media");
  writeFile(dir / "text.mp4", "not a video at all");
  writeFile(dir / "text.png", "not a png");
  const fs::path out = dir / "r.html";
  EXPECT_EQ(writeHtmlReport(sample(), {.video = dir / "none.mp4"}, out).error(),
            "html report: cannot read '" + (dir / "none.mp4").string() + "': No such file or directory");
  EXPECT_EQ(writeHtmlReport(sample(), {.video = dir / "text.mp4"}, out).error(),
            "html report: '" + (dir / "text.mp4").string() + "' is not an MP4 video (it has no ftyp box)");
  EXPECT_EQ(writeHtmlReport(sample(), {.plot = dir / "text.png"}, out).error(),
            "html report: '" + (dir / "text.png").string() + "' is not a PNG image");
  EXPECT_FALSE(fs::exists(out));
  EXPECT_EQ(writeHtmlReport(sample(), {}, "/nonexistent/r.html").error(),
            "html report: cannot write '/nonexistent/r.html': directory '/nonexistent' does not exist");
}

// ---- The HTML report in Chromium ----------------------------------------------------------------

constexpr const char* kChromium = "/usr/bin/chromium";

struct Ran {
  int status = -1;
  std::string err;
};

// Runs headless Chromium on `page` with `flags`, stdout to `out`, at most 60 s (then it and its
// children are killed by timeout(1), which gives them a process group of their own).
Ran chromium(const fs::path& dir, const std::vector<std::string>& flags, const fs::path& page, const fs::path& out) {
  std::vector<std::string> all{"/usr/bin/timeout",
                               "-k",
                               "10",
                               "60",
                               kChromium,
                               "--headless",
                               "--no-sandbox",
                               "--disable-gpu",
                               "--no-first-run",
                               "--user-data-dir=" + (dir / "profile").string()};
  all.insert(all.end(), flags.begin(), flags.end());
  all.push_back("file://" + fs::absolute(page).string());
  std::vector<char*> argv;
  for (std::string& a : all) argv.push_back(a.data());
  argv.push_back(nullptr);
  const std::string err = (dir / "chromium_stderr.txt").string();
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  pid_t pid = 0;
  Ran r;
  if (posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ) == 0) {
    int status = 0;
    waitpid(pid, &status, 0);
    r.status = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  }
  posix_spawn_file_actions_destroy(&actions);
  r.err = readFile(err);
  return r;
}

// Fails (never skips) when Chromium is missing: the report's rendering would go untested.
void requireChromium() {
  ASSERT_TRUE(fs::exists(kChromium)) << kChromium << " is missing: the HTML report is tested in headless Chromium; "
                                     << "install it with `apt-get install chromium` (cmake/install-deps.sh lists it)";
}

// Pixels of `img` within 40 of `rgb` in every channel.
int pixelsNear(const render::Image& img, const std::uint8_t (&rgb)[3]) {
  int n = 0;
  for (int y = 0; y < img.height; ++y) {
    for (int x = 0; x < img.width; ++x) {
      const std::uint8_t* p = img.pixel(x, y);
      if (std::abs(p[0] - rgb[0]) <= 40 && std::abs(p[1] - rgb[1]) <= 40 && std::abs(p[2] - rgb[2]) <= 40) ++n;
    }
  }
  return n;
}

TEST(HtmlReportInChromium, ScreenshotShowsTheTableTheVideoAndThePlot) {
  requireChromium();
  const Report r = writeReport("chromium_screenshot");
  const fs::path shot = r.dir / "shot.png";
  const Ran ran = chromium(r.dir, {"--screenshot=" + shot.string(), "--window-size=1000,800", "--hide-scrollbars"}, r.html, r.dir / "stdout.txt");
  ASSERT_EQ(ran.status, 0) << ran.err;
  const Result<render::Image> img = render::readPng(shot.string());
  ASSERT_TRUE(img.ok()) << img.error() << "\n" << ran.err;
  ASSERT_EQ(img.value().width, 1000);
  ASSERT_EQ(img.value().height, 800);
  // Not blank: much of the page differs from its background, the top left pixel.
  const std::uint8_t* bg = img.value().pixel(0, 0);
  const std::uint8_t background[3] = {bg[0], bg[1], bg[2]};
  EXPECT_LT(pixelsNear(img.value(), background), 1000 * 800 * 98 / 100);
  EXPECT_GT(1000 * 800 - pixelsNear(img.value(), background), 5000);
  // The plot is drawn whole, and the video's first frame is drawn: its controls shade most of it
  // (about a fifth keeps its colour), but an undecoded video would show none of it.
  EXPECT_GE(pixelsNear(img.value(), kVideoColour), kVideoW * kVideoH / 10);
  EXPECT_GE(pixelsNear(img.value(), kPlotColour), kPlotW * kPlotH * 9 / 10);
}

TEST(HtmlReportInChromium, DomHasTheRowsTheTextAndTheDataUris) {
  requireChromium();
  const Report r = writeReport("chromium_dom");
  const Ran ran = chromium(r.dir, {"--dump-dom"}, r.html, r.dir / "dom.html");
  ASSERT_EQ(ran.status, 0) << ran.err;
  const Doc dom = parseHtml(readFile(r.dir / "dom.html"));
  ASSERT_TRUE(dom);
  EXPECT_EQ(one(dom.get(), "//title"), "go_to_goal: students/alice.cpp");
  EXPECT_EQ(one(dom.get(), "//p[@class='total']"), "Total: 2.5 / 5 points");
  EXPECT_EQ(select(dom.get(), "//table/thead/tr/th"), (std::vector<std::string>{"Check", "Score", "Points", "Status", "Reasons"}));
  EXPECT_EQ(select(dom.get(), "//table/tbody/tr/td[1]"), (std::vector<std::string>{"reaches the goal", "avoids walls", "secret worlds (hidden)"}));
  EXPECT_EQ(select(dom.get(), "//table/tbody/tr/td[2]"), (std::vector<std::string>{"2", "0.5", "0"}));
  EXPECT_EQ(select(dom.get(), "//table/tbody/tr/td[3]"), (std::vector<std::string>{"2", "1", "2"}));
  EXPECT_EQ(select(dom.get(), "//table/tbody/tr/td[4]"), (std::vector<std::string>{"PASS", "PARTIAL", "FAIL"}));
  // The hostile reason is text in its cell, not markup: the browser made no <script> of it.
  EXPECT_EQ(select(dom.get(), "//table/tbody/tr/td[5]"),
            (std::vector<std::string>{"", "in maze, seed 3: " + kHostileRead, "in rooms, seed 7: not within 0.3 m of goal by 60 s"}));
  EXPECT_TRUE(select(dom.get(), "//script").empty());
  EXPECT_EQ(select(dom.get(), "//ul[@class='notes']/li"), std::vector<std::string>{"the controller printed more than 1 MB; the rest was cut"});
  // The media are data: URIs holding exactly the files' bytes.
  const std::string video = one(dom.get(), "//video/@src"), plot = one(dom.get(), "//img/@src");
  const std::string videoPrefix = "data:video/mp4;base64,", plotPrefix = "data:image/png;base64,";
  ASSERT_EQ(video.substr(0, videoPrefix.size()), videoPrefix);
  ASSERT_EQ(plot.substr(0, plotPrefix.size()), plotPrefix);
  EXPECT_TRUE(unbase64(std::string_view(video).substr(videoPrefix.size())) == readFile(r.video)) << "the video's data URI is not the MP4";
  EXPECT_TRUE(unbase64(std::string_view(plot).substr(plotPrefix.size())) == readFile(r.plot)) << "the plot's data URI is not the PNG";
  EXPECT_EQ(select(dom.get(), "//video/@controls").size(), 1u);
  EXPECT_EQ(one(dom.get(), "//figcaption"), "the first failing run: maze, seed 3 <&>");
}

// The page has no scripts (its Content-Security-Policy forbids them). A test copy adds one that, at
// the load event, writes the video's and the plot's state into the DOM. A media element delays the
// load event until its first frame is decoded (HTML: "delaying the load event"), and --dump-dom
// serializes after that event, so what the script reads does not depend on timing.
TEST(HtmlReportInChromium, VideoDecodesInTheBrowser) {
  requireChromium();
  const Report r = writeReport("chromium_video");
  std::string page = readFile(r.html);
  const std::string policy = "style-src 'unsafe-inline'";
  const std::size_t at = page.find(policy);
  ASSERT_NE(at, std::string::npos);
  page.insert(at + policy.size(), "; script-src 'unsafe-inline'");
  const std::string probe = R"(<script>
window.addEventListener('load', () => {
  const v = document.querySelector('video'), img = document.querySelector('img');
  const out = document.createElement('pre');
  out.id = 'probe';
  out.textContent = JSON.stringify({readyState: v.readyState, duration: v.duration, width: v.videoWidth, height: v.videoHeight,
                                    error: v.error ? v.error.code : 0, plotWidth: img.naturalWidth, plotHeight: img.naturalHeight});
  document.body.appendChild(out);
});
</script>
)";
  const std::size_t end = page.rfind("</body>");
  ASSERT_NE(end, std::string::npos);
  page.insert(end, probe);
  const fs::path copy = r.dir / "probe.html";
  writeFile(copy, page);
  const Ran ran = chromium(r.dir, {"--dump-dom"}, copy, r.dir / "dom.html");
  ASSERT_EQ(ran.status, 0) << ran.err;
  const Doc dom = parseHtml(readFile(r.dir / "dom.html"));
  ASSERT_TRUE(dom);
  const json state = json::parse(one(dom.get(), "//pre[@id='probe']"), nullptr, false);
  ASSERT_TRUE(state.is_object()) << readFile(r.dir / "dom.html").substr(0, 2000);
  EXPECT_EQ(state["error"], 0) << state.dump();
  EXPECT_GE(state["readyState"], 2) << "HAVE_CURRENT_DATA: the first frame is decoded; " << state.dump();
  ASSERT_TRUE(state["duration"].is_number()) << state.dump();
  EXPECT_NEAR(state["duration"].get<double>(), static_cast<double>(kVideoFrames) / kFps, 0.05) << state.dump();
  EXPECT_EQ(state["width"], kVideoW);
  EXPECT_EQ(state["height"], kVideoH);
  EXPECT_EQ(state["plotWidth"], kPlotW);
  EXPECT_EQ(state["plotHeight"], kPlotH);
}

}  // namespace
}  // namespace frob::course
