// The grade's writers. Formats followed (checked against the published specifications):
// - Gradescope: https://gradescope-autograders.readthedocs.io/en/latest/specs/ (gradescope/autograder_samples,
//   docs/specs.md): "status" is "passed" or "failed", "visibility" one of "hidden", "after_due_date",
//   "after_published", "visible"; the top-level output defaults to "simple_format" (HTML), so we say "text".
// - PrairieLearn: https://prairielearn.readthedocs.io/en/latest/externalGrading/#grading-results: "score" in
//   [0, 1]; "gradable": false for a submission that could not be compiled (no attempt is used up) with
//   "format_errors"; the file must stay under 1 MB.
// - JUnit XML: the Jenkins/Surefire schema junit-10.xsd (<testsuite> needs name, tests, failures, errors;
//   time with at most three decimals); XML 1.0 forbids most control characters, even escaped.

#include "frob/grade/grade_report.hpp"

#include "frob/render/output_file.hpp"
#include "grade_files.hpp"
#include "markup.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <map>
#include <set>
#include <string_view>

namespace frob::course {

using detail::number;
using detail::readWhole;
using detail::writeWhole;

namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

// ---- Checks' outcomes and numbers ----------------------------------------------------------------

enum class Outcome { Pass, Fail, Partial };

std::size_t passedRuns(const CheckGrade& c) {
  return static_cast<std::size_t>(std::count_if(c.runs.begin(), c.runs.end(), [](const RunGrade& r) { return r.passed; }));
}

// PASS when every run passed, FAIL when none did, PARTIAL between. A check without runs (none was
// made) passes only if it has its points anyway.
Outcome outcomeOf(const CheckGrade& c) {
  if (c.runs.empty()) return c.score >= c.points ? Outcome::Pass : Outcome::Fail;
  const std::size_t passed = passedRuns(c);
  if (passed == c.runs.size()) return Outcome::Pass;
  return passed == 0 ? Outcome::Fail : Outcome::Partial;
}

const char* toString(Outcome o) {
  switch (o) {
    case Outcome::Pass:
      return "PASS";
    case Outcome::Fail:
      return "FAIL";
    case Outcome::Partial:
      return "PARTIAL";
  }
  return "FAIL";
}

// Points are reported to 1e-4 of a point: 2/3 of a point is 0.6667, and sums do not show 0.30000000000000004.
double rounded(double points) {
  const double r = std::round(points * 1e4) / 1e4;
  return r == 0.0 ? 0.0 : r;  // no "-0"
}

// The lines of `text`, without their "\n" or "\r\n"; "" gives none.
std::vector<std::string> linesOf(const std::string& text) {
  std::vector<std::string> lines;
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    std::string line = text.substr(start, end - start);
    if (!line.empty() && line.back() == '\r') line.pop_back();
    lines.push_back(std::move(line));
    start = end + 1;
  }
  return lines;
}

// The summary both results.json files show students: the visible checks only (Gradescope hides the
// total while some tests are hidden; a total that counts hidden checks would give them away).
std::string summaryOf(const Grade& g) {
  std::string s;
  if (!g.compileError.empty()) {
    s = "The submission did not compile, so every check scores 0:\n\n" + g.compileError;
    if (s.back() != '\n') s += '\n';
  } else {
    std::size_t visible = 0, passed = 0, unseen = 0;
    double score = 0.0, points = 0.0;
    for (const CheckGrade& c : g.checks) {
      if (c.visibility != Visibility::Visible) {
        ++unseen;
        continue;
      }
      ++visible;
      passed += outcomeOf(c) == Outcome::Pass ? 1 : 0;
      score += c.score;
      points += c.points;
    }
    s = std::to_string(passed) + " of " + std::to_string(visible) + (unseen > 0 ? " visible" : "") + (visible == 1 ? " check" : " checks") +
        " passed: " + number(score) + " / " + number(points) + " points.\n";
    if (unseen > 0) {
      s += std::to_string(unseen) + (unseen == 1 ? " more check is" : " more checks are") + " graded but not shown here.\n";
    }
  }
  for (const std::string& note : g.notes) s += "Note: " + note + "\n";
  return s;
}

// ---- Files -------------------------------------------------------------------------------------

std::string dump(const Json& doc) {
  // Malformed UTF-8 (a compiler quoting a Latin-1 source) becomes U+FFFD instead of an exception.
  return doc.dump(2, ' ', false, Json::error_handler_t::replace) + "\n";
}

// ---- PrairieLearn ------------------------------------------------------------------------------

// `text` cut to at most `limit` bytes (at a character boundary), saying how much was cut.
std::string clip(const std::string& text, std::size_t limit) {
  if (text.size() <= limit) return text;
  std::size_t end = limit;
  while (end > 0 && (static_cast<unsigned char>(text[end]) & 0xC0) == 0x80) --end;
  return text.substr(0, end) + "\n[... " + std::to_string(text.size() - end) + " more bytes cut]\n";
}

Json prairieLearnResults(const Grade& g, std::size_t limit) {
  Json doc;
  const bool gradable = g.compileError.empty();
  const double max = g.maxScore();
  double fraction = 0.0;
  if (gradable && max > 0.0) {
    fraction = std::clamp(g.score() / max, 0.0, 1.0);
  } else if (gradable) {  // nothing to earn: all or nothing on the checks' outcomes
    fraction = std::all_of(g.checks.begin(), g.checks.end(), [](const CheckGrade& c) { return outcomeOf(c) == Outcome::Pass; }) ? 1.0 : 0.0;
  }
  doc["gradable"] = gradable;
  doc["score"] = fraction;
  std::string notes;
  for (const std::string& note : g.notes) notes += "Note: " + note + "\n";
  if (!gradable) {
    doc["message"] = "The submission did not compile; it was not graded and no attempt was used up.";
    doc["output"] = clip(g.compileError, limit) + notes;
    doc["format_errors"] = clip(g.compileError, limit);
    doc["tests"] = Json::array();
    return doc;
  }
  doc["message"] = clip(summaryOf(g), limit);
  doc["output"] = notes;
  // PrairieLearn shows every test to the student: checks that are not visible are summed into one.
  Json tests = Json::array();
  double hiddenPoints = 0.0, hiddenMax = 0.0;
  std::size_t hidden = 0;
  for (const CheckGrade& c : g.checks) {
    if (c.visibility != Visibility::Visible) {
      ++hidden;
      hiddenPoints += c.score;
      hiddenMax += c.points;
      continue;
    }
    Json t;
    t["name"] = c.name;
    t["points"] = rounded(c.score);
    t["max_points"] = rounded(c.points);
    t["output"] = clip(c.output(), limit);
    t["message"] = c.runs.empty() ? std::string("not run") : std::to_string(passedRuns(c)) + " of " + std::to_string(c.runs.size()) + " runs passed";
    tests.push_back(std::move(t));
  }
  if (hidden > 0) {
    Json t;
    t["name"] = "Hidden checks";
    t["points"] = rounded(hiddenPoints);
    t["max_points"] = rounded(hiddenMax);
    t["output"] = "";
    t["message"] = std::to_string(hidden) + (hidden == 1 ? " check whose result is" : " checks whose results are") + " not shown";
    tests.push_back(std::move(t));
  }
  doc["tests"] = std::move(tests);
  return doc;
}

}  // namespace

namespace detail {

// `points` rounded, in the shortest text that reads back as the same double ("2", "0.5", "0.6667").
std::string number(double points) {
  char buf[32];
  return {buf, std::to_chars(buf, buf + sizeof buf, rounded(points)).ptr};
}

// Writes `bytes` to `<path>.partial` and renames it to `path`; `what` names the file in messages.
Status writeWhole(const fs::path& path, const std::string& what, const std::string& bytes) {
  const std::string name = path.string();
  if (Status s = render::checkWritable(name, what); !s) return s;
  const std::string partial = render::partialPath(name);
  {
    std::ofstream out(partial, std::ios::binary | std::ios::trunc);
    if (!out) return Status::failure(what + ": cannot write '" + partial + "': " + std::strerror(errno));
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    out.close();
    if (!out) {
      const std::string why = std::strerror(errno);
      render::discardPartial(name);
      return Status::failure(what + ": cannot write '" + partial + "': " + why);
    }
  }
  return render::commitPartial(name, what);
}

Result<std::string> readWhole(const fs::path& path, const std::string& what) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return Status::failure(what + ": cannot read '" + path.string() + "': " + std::strerror(errno));
  std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  if (in.bad()) return Status::failure(what + ": cannot read '" + path.string() + "': " + std::strerror(errno));
  return bytes;
}

}  // namespace detail

std::string scoreTable(const Grade& g) {
  struct Row {
    std::string name, score, points, result, marker;
    std::vector<std::string> reasons;
  };
  std::vector<Row> rows;
  for (const CheckGrade& c : g.checks) {
    Row r{.name = terminalSafe(c.name),
          .score = number(c.score),
          .points = number(c.points),
          .result = toString(outcomeOf(c)),
          .marker = c.visibility == Visibility::Visible ? "" : std::string("[") + course::toString(c.visibility) + "]",
          .reasons = {}};
    for (const std::string& line : linesOf(c.output())) r.reasons.push_back(terminalSafe(line));
    rows.push_back(std::move(r));
  }
  const Row total{.name = "Total", .score = number(g.score()), .points = number(g.maxScore()), .result = "", .marker = "", .reasons = {}};

  std::size_t nameW = std::max(widthOf("Check"), widthOf(total.name)), scoreW = total.score.size(), pointsW = total.points.size();
  for (const Row& r : rows) {
    nameW = std::max(nameW, widthOf(r.name));
    scoreW = std::max(scoreW, r.score.size());
    pointsW = std::max(pointsW, r.points.size());
  }
  const std::size_t fractionW = std::max<std::size_t>(scoreW + 3 + pointsW, widthOf("Score"));
  const std::size_t resultW = widthOf("PARTIAL");

  auto pad = [](std::string s, std::size_t w) { return s + std::string(w - std::min(w, widthOf(s)), ' '); };
  auto rtrim = [](std::string s) {
    while (!s.empty() && s.back() == ' ') s.pop_back();
    return s + "\n";
  };
  auto line = [&](const Row& r) {
    std::string fraction = std::string(scoreW - r.score.size(), ' ') + r.score + " / " + r.points;
    return rtrim(pad(r.name, nameW) + "  " + pad(fraction, fractionW) + "  " + pad(r.result, resultW) + "  " + r.marker);
  };
  const std::string rule = std::string(nameW, '-') + "  " + std::string(fractionW, '-') + "  " + std::string(resultW, '-') + "\n";

  std::string out = terminalSafe(g.assignment) + ": " + terminalSafe(g.submission) + "\n";
  out += rtrim(pad("Check", nameW) + "  " + pad("Score", fractionW) + "  Result");
  out += rule;
  for (const Row& r : rows) {
    out += line(r);
    for (const std::string& reason : r.reasons) out += rtrim("    " + reason);
  }
  if (!g.compileError.empty()) {
    out += "The submission did not compile:\n";
    for (const std::string& l : linesOf(g.compileError)) out += rtrim("    " + terminalSafe(l));
  }
  out += rule;
  out += line(total);
  for (const std::string& note : g.notes) out += rtrim("Note: " + terminalSafe(note));
  return out;
}

Status writeGradescope(const Grade& g, const fs::path& path) {
  Json doc;
  doc["score"] = rounded(g.score());
  doc["execution_time"] = std::llround(std::max(0.0, g.wallSeconds));
  doc["output"] = summaryOf(g);
  doc["output_format"] = "text";
  Json tests = Json::array();
  for (const CheckGrade& c : g.checks) {
    Json t;
    t["name"] = c.name;
    t["score"] = rounded(c.score);
    t["max_score"] = rounded(c.points);
    t["status"] = outcomeOf(c) == Outcome::Pass ? "passed" : "failed";
    t["output"] = c.output();
    t["visibility"] = toString(c.visibility);
    Json tags = Json::array();
    std::set<std::string> seen;
    for (const RunGrade& r : c.runs) {
      if (seen.insert(r.world).second) tags.push_back(r.world);
    }
    t["tags"] = std::move(tags);
    tests.push_back(std::move(t));
  }
  doc["tests"] = std::move(tests);
  return writeWhole(path, "gradescope results", dump(doc));
}

Status writePrairieLearn(const Grade& g, const fs::path& path) {
  // PrairieLearn rejects results over 1 MB: long texts are cut until the file fits.
  constexpr std::size_t kMaxBytes = 1'000'000;
  std::size_t limit = kMaxBytes;
  std::string text = dump(prairieLearnResults(g, limit));
  while (text.size() > kMaxBytes && limit > 1000) {
    limit /= 2;
    text = dump(prairieLearnResults(g, limit));
  }
  if (text.size() > kMaxBytes) {
    return Status::failure("prairielearn results: cannot write '" + path.string() + "': the results take " + std::to_string(text.size()) +
                           " bytes, more than PrairieLearn's 1 MB");
  }
  return writeWhole(path, "prairielearn results", text);
}

Status writeJUnit(const Grade& g, const fs::path& path) {
  const std::string suite = markupEscape(g.assignment, true);
  std::string cases;
  int tests = 0, failures = 0;
  auto testcase = [&](const std::string& name, const std::string* failure, const std::string& message) {
    ++tests;
    cases += "  <testcase name=\"" + markupEscape(name, true) + "\" classname=\"" + suite + "\"";
    if (failure == nullptr) {
      cases += "/>\n";
      return;
    }
    ++failures;
    cases += ">\n    <failure message=\"" + markupEscape(message, true) + "\">" + markupEscape(*failure) + "</failure>\n  </testcase>\n";
  };
  if (!g.compileError.empty()) testcase("compile", &g.compileError, "the submission did not compile");
  for (const CheckGrade& c : g.checks) {
    if (c.runs.empty()) {
      const std::string why = g.compileError.empty() ? "not run" : "not run: the submission did not compile";
      testcase(c.name, outcomeOf(c) == Outcome::Pass ? nullptr : &why, why);
      continue;
    }
    for (const RunGrade& r : c.runs) {
      testcase(c.name + " / " + r.world + " seed " + std::to_string(r.seed), r.passed ? nullptr : &r.reason, r.reason);
    }
  }
  char buf[32];
  const std::string seconds(buf, std::to_chars(buf, buf + sizeof buf, std::max(0.0, g.wallSeconds), std::chars_format::fixed, 3).ptr);
  std::string xml = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  xml += "<testsuite name=\"" + suite + "\" tests=\"" + std::to_string(tests) + "\" failures=\"" + std::to_string(failures) +
         "\" errors=\"0\" skipped=\"0\" time=\"" + seconds + "\">\n";
  xml += cases;
  if (!g.notes.empty()) {
    std::string notes;
    for (const std::string& note : g.notes) notes += note + "\n";
    xml += "  <system-out>" + markupEscape(notes) + "</system-out>\n";
  }
  xml += "</testsuite>\n";
  return writeWhole(path, "junit report", xml);
}

Status writeHtmlReport(const Grade& g, const HtmlMedia& media, const fs::path& path) {
  // The media first: a missing or wrong file is reported before anything is written.
  std::string video, plot;
  if (!media.video.empty()) {
    Result<std::string> bytes = readWhole(media.video, "html report");
    if (!bytes) return bytes.status();
    if (bytes.value().size() < 12 || bytes.value().compare(4, 4, "ftyp") != 0) {
      return Status::failure("html report: '" + media.video.string() + "' is not an MP4 video (it has no ftyp box)");
    }
    video = base64(bytes.value());
  }
  if (!media.plot.empty()) {
    Result<std::string> bytes = readWhole(media.plot, "html report");
    if (!bytes) return bytes.status();
    if (bytes.value().compare(0, 8, "\x89PNG\r\n\x1a\n") != 0) {
      return Status::failure("html report: '" + media.plot.string() + "' is not a PNG image");
    }
    plot = base64(bytes.value());
  }

  const std::string title = markupEscape(g.assignment + ": " + g.submission);
  std::string html =
      "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
      // Nothing from elsewhere and no scripts, even if something slipped past the escaping.
      "<meta http-equiv=\"Content-Security-Policy\" content=\"default-src 'none'; img-src data:; media-src data:; "
      "style-src 'unsafe-inline'\">\n"
      "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
      "<title>" +
      title +
      "</title>\n"
      "<style>\n"
      "body { font-family: sans-serif; margin: 1.5em; color: #222; }\n"
      "table { border-collapse: collapse; }\n"
      "th, td { border: 1px solid #bbb; padding: 0.3em 0.6em; text-align: left; vertical-align: top; }\n"
      "td.num { text-align: right; font-variant-numeric: tabular-nums; }\n"
      "tr.PASS td.status { color: #146c2e; } tr.FAIL td.status { color: #b3261e; } tr.PARTIAL td.status { color: #8a5a00; }\n"
      ".visibility { color: #666; font-size: 0.85em; }\n"
      "pre { background: #f4f4f4; padding: 0.8em; overflow-x: auto; }\n"
      "figure { margin: 1.5em 0; } video, img { display: block; max-width: 100%; margin-bottom: 0.5em; }\n"
      "</style>\n</head>\n<body>\n";
  html += "<h1>" + title + "</h1>\n";
  html += "<p class=\"total\">Total: <strong>" + number(g.score()) + " / " + number(g.maxScore()) + "</strong> points</p>\n";
  html += "<table>\n<thead><tr><th>Check</th><th>Score</th><th>Points</th><th>Status</th><th>Reasons</th></tr></thead>\n<tbody>\n";
  for (const CheckGrade& c : g.checks) {
    const char* status = toString(outcomeOf(c));
    html += "<tr class=\"" + std::string(status) + "\"><td>" + markupEscape(c.name);
    if (c.visibility != Visibility::Visible) {
      html += " <span class=\"visibility\">(" + std::string(course::toString(c.visibility)) + ")</span>";
    }
    html += "</td><td class=\"num\">" + number(c.score) + "</td><td class=\"num\">" + number(c.points) + "</td><td class=\"status\">" + status +
            "</td><td>";
    const std::vector<std::string> reasons = linesOf(c.output());
    for (std::size_t i = 0; i < reasons.size(); ++i) html += (i > 0 ? "<br>" : "") + markupEscape(reasons[i]);
    html += "</td></tr>\n";
  }
  html += "</tbody>\n</table>\n";
  if (!g.compileError.empty()) {
    html += "<h2>The submission did not compile</h2>\n<pre class=\"compile-error\">" + markupEscape(g.compileError) + "</pre>\n";
  }
  if (!g.notes.empty()) {
    html += "<h2>Notes</h2>\n<ul class=\"notes\">\n";
    for (const std::string& note : g.notes) html += "<li>" + markupEscape(note) + "</li>\n";
    html += "</ul>\n";
  }
  if (!video.empty() || !plot.empty()) {
    html += "<figure>\n";
    if (!video.empty()) html += "<video controls src=\"data:video/mp4;base64," + video + "\"></video>\n";
    if (!plot.empty()) html += "<img src=\"data:image/png;base64," + plot + "\" alt=\"plot of the run\">\n";
    if (!media.caption.empty()) html += "<figcaption>" + markupEscape(media.caption) + "</figcaption>\n";
    html += "</figure>\n";
  }
  html += "</body>\n</html>\n";
  return writeWhole(path, "html report", html);
}

}  // namespace frob::course
