#pragma once
// Grades written by hand for the grade's writers' tests, the files they write, and what libxml2
// reads back from them: shared by grade_report_test.cpp and html_report_test.cpp.
#include "../../support/dom.hpp"
#include "frob/grade/grade_report.hpp"

#include <gtest/gtest.h>
#include <libxml/xmlschemas.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

namespace frob::course::testing {

namespace fs = std::filesystem;
using support::Doc, support::one, support::parseHtml, support::parseXml, support::select;

// ---- Grades written by hand ----------------------------------------------------------------------

inline RunGrade pass(std::string world, std::uint64_t seed) { return {.world = std::move(world), .seed = seed, .passed = true}; }

// `kind`: what a check that is not visible shows of it; by default the reason itself.
inline RunGrade fail(std::string world, std::uint64_t seed, std::string reason, std::string kind = "") {
  if (kind.empty()) kind = reason;
  return {.world = std::move(world), .seed = seed, .passed = false, .reason = std::move(reason), .kind = std::move(kind)};
}

// What a check that is not visible adds to what failed.
inline const std::string kNoDetails = " (hidden worlds give no details: practise with frob grade --practice)";

// Markup, both quotes, an ampersand and a control character XML 1.0 forbids even as a reference.
inline const std::string kHostile = "bumped <script>alert(1)</script> & \"double\" 'single' \x01 here";
// What XML and HTML readers get back: the control character replaced by U+FFFD.
inline const std::string kHostileRead = "bumped <script>alert(1)</script> & \"double\" 'single' \xEF\xBF\xBD here";

inline Grade sample() {
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
       .runs = {fail("rooms", 7, "not within 0.3 m of goal by 60 s", "it failed the rubric's \"goal\" criterion")}},
  };
  g.notes = {"the controller printed more than 1 MB; the rest was cut"};
  g.submissionHash = "5ca1ab1e";
  for (CheckGrade& c : g.checks) {
    for (RunGrade& r : c.runs) r.trajectoryHash = 0x10 + r.seed;
  }
  return g;
}

// As grade() gives it when the file did not compile: every run failed for that reason.
inline Grade uncompiled(std::string compileError) {
  Grade g;
  g.assignment = "go_to_goal";
  g.submission = "students/bob.cpp";
  g.compileError = std::move(compileError);
  g.wallSeconds = 0.4;
  g.checks = {{.name = "reaches the goal", .points = 2, .score = 0, .runs = {fail("empty", 1, "the submission did not compile")}}};
  return g;
}

// One grade of the gradebook: checks "reaches the goal" (2 points) and "avoids walls, maze" (1 point).
inline Grade scored(std::string submission, double reach, double walls) {
  Grade g;
  g.assignment = "go_to_goal";
  g.submission = std::move(submission);
  g.checks = {{.name = "reaches the goal", .points = 2, .score = reach}, {.name = "avoids walls, maze", .points = 1, .score = walls}};
  return g;
}

// ---- Files ---------------------------------------------------------------------------------------

inline fs::path scratch(const std::string& name) {
  const fs::path dir = fs::path(::testing::TempDir()) / "grade_report_test" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

inline std::string readFile(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

inline void writeFile(const fs::path& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary);
  out << bytes;
}

inline std::vector<std::string> filesIn(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

// ---- Data read back -------------------------------------------------------------------------------

inline std::string unbase64(std::string_view text) {
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

}  // namespace frob::course::testing
