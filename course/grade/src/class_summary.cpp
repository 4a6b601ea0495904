// The class folder's summary page: made from every student's grade.json, so that it covers the whole
// class however many times some students were graded again.
#include "frob/grade/class_folder.hpp"
#include "frob/grade/similarity.hpp"
#include "markup.hpp"
#include "writers.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <map>

namespace frob::course {

namespace fs = std::filesystem;
using detail::Json;

namespace {

struct Student {
  std::string name;
  Json grade;
  bool report = false;  // report.html beside it
};

// Every student's grade.json in `dir`, by name.
std::vector<Student> studentsIn(const fs::path& dir) {
  std::vector<Student> all;
  std::error_code ec;
  for (const fs::directory_entry& e : fs::directory_iterator(dir, ec)) {
    const std::string name = e.path().filename().string();
    if (name.starts_with('.') || !e.is_directory(ec) || e.is_symlink(ec)) continue;
    Result<std::string> text = detail::readWhole(e.path() / "grade.json", "summary");
    if (!text) continue;
    Json grade = Json::parse(text.value(), nullptr, false);
    if (grade.is_discarded() || !grade.is_object()) continue;
    all.push_back({name, std::move(grade), fs::is_regular_file(e.path() / "report.html", ec)});
  }
  std::sort(all.begin(), all.end(), [](const Student& a, const Student& b) { return a.name < b.name; });
  return all;
}

// A reason with its numbers as '#', so that "came within 1.20 m" and "came within 0.87 m" count as one.
std::string shapeOf(std::string_view text) {
  std::string shape;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const bool digit = std::isdigit(static_cast<unsigned char>(text[i])) != 0;
    if (!digit) {
      shape += text[i];
      continue;
    }
    shape += '#';
    while (i + 1 < text.size() && (std::isdigit(static_cast<unsigned char>(text[i + 1])) != 0 || text[i + 1] == '.')) ++i;
  }
  return shape;
}

// A path segment of a link: every byte but unreserved ones percent-encoded.
std::string linkTo(std::string_view segment) {
  static constexpr char kHex[] = "0123456789ABCDEF";
  std::string out;
  for (unsigned char c : segment) {
    if (std::isalnum(c) != 0 || c == '-' || c == '_' || c == '.' || c == '~') {
      out += static_cast<char>(c);
    } else {
      out += '%', out += kHex[c >> 4], out += kHex[c & 15];
    }
  }
  return out;
}

std::string cell(std::string_view text) { return "<td>" + markupEscape(text) + "</td>"; }
std::string cellNumber(double v) { return "<td class=\"n\">" + detail::number(v) + "</td>"; }

// The `most` commonest of `counts` (shape -> students, runs), commonest first, as table rows.
std::string commonest(const std::map<std::string, std::pair<std::size_t, std::size_t>>& counts, std::size_t most) {
  std::vector<std::pair<std::string, std::pair<std::size_t, std::size_t>>> sorted(counts.begin(), counts.end());
  std::stable_sort(sorted.begin(), sorted.end(), [](const auto& a, const auto& b) { return a.second.first > b.second.first; });
  std::string rows;
  for (std::size_t k = 0; k < std::min(most, sorted.size()); ++k) {
    rows += "<tr>" + cell(sorted[k].first) + cellNumber(static_cast<double>(sorted[k].second.first)) +
            cellNumber(static_cast<double>(sorted[k].second.second)) + "</tr>\n";
  }
  return rows;
}

// What similarPairs compares of each student, from their grade.json.
std::vector<StudentWork> workOf(const std::vector<Student>& students) {
  const auto hex = [](const Json& j) {
    std::uint64_t v = 0;
    const std::string text = j.is_string() ? j.get<std::string>() : std::string();
    std::from_chars(text.data(), text.data() + text.size(), v, 16);
    return v;
  };
  std::vector<StudentWork> work;
  for (const Student& s : students) {
    StudentWork w{.student = s.name, .fingerprints = {}, .trajectories = {}};
    for (const Json& f : s.grade.value("fingerprints", Json::array())) w.fingerprints.push_back(hex(f));
    std::sort(w.fingerprints.begin(), w.fingerprints.end());
    for (const Json& c : s.grade.value("checks", Json::array())) {
      for (const Json& r : c.value("runs", Json::array())) w.trajectories.push_back(hex(r.value("trajectory", Json())));
    }
    work.push_back(std::move(w));
  }
  return work;
}

}  // namespace

Status writeClassSummary(const fs::path& dir, const std::string& assignment) {
  const std::vector<Student> students = studentsIn(dir);
  // Shares of full marks in eleven bins: 0-9 %, ..., 90-99 %, and full marks.
  std::vector<std::size_t> bins(11, 0);
  struct CheckTally {
    double points = 0.0, sum = 0.0;
    std::size_t full = 0, graded = 0;
  };
  std::vector<std::string> checkOrder;
  std::map<std::string, CheckTally> checks;
  std::map<std::string, std::pair<std::size_t, std::size_t>> reasons, hints;  // shape -> (students, runs)
  struct Slow {
    double seconds;
    std::string student, check, place;
  };
  std::vector<Slow> slow;
  std::string compiles, table;
  double total = 0.0;
  std::size_t scored = 0;
  for (const Student& s : students) {
    const Json& g = s.grade;
    const double max = g.value("max_score", 0.0);
    const bool hasScore = g.contains("score") && g["score"].is_number();
    const double score = hasScore ? g["score"].get<double>() : 0.0;
    if (hasScore && max > 0) {
      const double share = score / max;
      bins[share >= 1.0 - 1e-9 ? 10 : std::min<std::size_t>(9, static_cast<std::size_t>(share * 10.0))]++;
      total += share, ++scored;
    }
    const std::string result = g.value("result", "");
    if (result == "did not compile") {
      const std::string error = g.value("compile_error", "");
      const std::size_t at = error.find("error: ");
      const std::string first =
          error.substr(at == std::string::npos ? 0 : at, error.find('\n', at == std::string::npos ? 0 : at) - (at == std::string::npos ? 0 : at));
      compiles += "<tr>" + cell(s.name) + cell(first) + "</tr>\n";
    }
    std::map<std::string, bool> seenReason, seenHint;
    for (const Json& c : g.value("checks", Json::array())) {
      const std::string name = c.value("name", "");
      if (!checks.contains(name)) checkOrder.push_back(name);
      CheckTally& t = checks[name];
      t.points = c.value("points", 0.0);
      t.sum += c.value("score", 0.0);
      t.full += c.value("score", 0.0) >= t.points - 1e-9 ? 1 : 0;
      ++t.graded;
      for (const Json& r : c.value("runs", Json::array())) {
        slow.push_back({r.value("seconds", 0.0), s.name, name, r.value("place", "")});
        if (r.value("passed", true)) continue;
        const std::string shape = shapeOf(r.value("reason", ""));
        auto& [who, runs] = reasons[shape];
        who += seenReason[shape] ? 0 : 1, ++runs, seenReason[shape] = true;
        for (const Json& h : r.value("hints", Json::array())) {
          if (!h.is_string()) continue;
          const std::string hint = shapeOf(h.get<std::string>());
          auto& [hw, hr] = hints[hint];
          hw += seenHint[hint] ? 0 : 1, ++hr, seenHint[hint] = true;
        }
      }
    }
    const std::string link = linkTo(s.name) + (s.report ? "/report.html" : "/grade.json");
    table += "<tr><td><a href=\"" + markupEscape(link, true) + "\">" + markupEscape(s.name) + "</a></td>" +
             (hasScore ? cellNumber(score) : std::string("<td></td>")) + cellNumber(max) + cell(result) + "</tr>\n";
  }
  std::sort(slow.begin(), slow.end(), [](const Slow& a, const Slow& b) { return a.seconds > b.seconds; });
  slow.resize(std::min<std::size_t>(slow.size(), 10));

  const std::string title = markupEscape(assignment + ": the class");
  std::string html =
      "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
      "<meta http-equiv=\"Content-Security-Policy\" content=\"default-src 'none'; style-src 'unsafe-inline'\">\n"
      "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n<title>" +
      title +
      "</title>\n<style>\n"
      "body { font-family: sans-serif; margin: 1.5em; color: #222; }\n"
      "table { border-collapse: collapse; margin-bottom: 1.5em; }\n"
      "th, td { border: 1px solid #bbb; padding: 0.3em 0.6em; text-align: left; vertical-align: top; }\n"
      "td.n { text-align: right; } .bar { background: #4a7bd0; height: 1em; }\n"
      "</style>\n</head>\n<body>\n<h1>" +
      title + "</h1>\n";
  html += "<p class=\"total\">" + std::to_string(students.size()) + " students" +
          (scored > 0 ? ", on average " + detail::number(100.0 * total / static_cast<double>(scored)) + "% of the points" : std::string()) + "</p>\n";
  html += "<h2>Scores</h2>\n<table class=\"histogram\"><thead><tr><th>Share of the points</th><th>Students</th><th></th></tr></thead><tbody>\n";
  const std::size_t most = std::max<std::size_t>(1, *std::max_element(bins.begin(), bins.end()));
  for (std::size_t b = 0; b < bins.size(); ++b) {
    const std::string label = b == 10 ? "full marks" : std::to_string(10 * b) + "-" + std::to_string(10 * b + 9) + "%";
    html += "<tr>" + cell(label) + cellNumber(static_cast<double>(bins[b])) +
            "<td><div class=\"bar\" style=\"width: " + std::to_string(20 * bins[b] / most) + "em\"></div></td></tr>\n";
  }
  html +=
      "</tbody></table>\n<h2>Checks</h2>\n<table class=\"checks\"><thead><tr><th>Check</th><th>Points</th><th>Full "
      "points</th><th>Average</th></tr></thead><tbody>\n";
  for (const std::string& name : checkOrder) {
    const CheckTally& t = checks[name];
    html += "<tr>" + cell(name) + cellNumber(t.points) + "<td class=\"n\">" + std::to_string(t.full) + " of " + std::to_string(t.graded) + "</td>" +
            cellNumber(t.graded > 0 ? t.sum / static_cast<double>(t.graded) : 0.0) + "</tr>\n";
  }
  html +=
      "</tbody></table>\n<h2>Commonest reasons</h2>\n<table class=\"reasons\"><thead><tr><th>Reason (numbers as "
      "#)</th><th>Students</th><th>Runs</th></tr></thead><tbody>\n" +
      commonest(reasons, 10) + "</tbody></table>\n";
  html += "<h2>Commonest diagnoses</h2>\n<table class=\"hints\"><thead><tr><th>Hint</th><th>Students</th><th>Runs</th></tr></thead><tbody>\n" +
          commonest(hints, 10) + "</tbody></table>\n";
  html += "<h2>Did not compile</h2>\n<table class=\"compiles\"><thead><tr><th>Student</th><th>First error</th></tr></thead><tbody>\n" + compiles +
          "</tbody></table>\n";
  html +=
      "<h2>Slowest runs</h2>\n<table class=\"slowest\"><thead><tr><th>Student</th><th>Check</th><th>Where</th><th>Seconds</th></tr></thead><tbody>\n";
  for (const Slow& s : slow)
    html += "<tr>" + cell(s.student) + cell(s.check) + cell(s.place) + cellNumber(std::round(s.seconds * 100) / 100) + "</tr>\n";
  const std::vector<SimilarPair> similar = similarPairs(workOf(students));
  std::string csv = detail::csvRecord({"student_a", "student_b", "kind", "score", "evidence"});
  html +=
      "</tbody></table>\n<h2>Similar work</h2>\n<table class=\"similar\"><thead><tr><th>Student</th><th>Student</th><th>Alike in</th>"
      "<th>Score</th><th>Evidence</th></tr></thead><tbody>\n";
  for (const SimilarPair& p : similar) {
    csv += detail::csvRecord({p.a, p.b, p.kind, detail::number(p.score), p.evidence});
    html += "<tr>" + cell(p.a) + cell(p.b) + cell(p.kind) + cellNumber(p.score) + cell(p.evidence) + "</tr>\n";
  }
  if (Status st = detail::writeWhole(dir / "similarity.csv", "similarity", csv); !st) return st;
  html +=
      "</tbody></table>\n<h2>Students</h2>\n<table "
      "class=\"students\"><thead><tr><th>Student</th><th>Score</th><th>Points</th><th>Result</th></tr></thead><tbody>\n" +
      table + "</tbody></table>\n</body>\n</html>\n";
  return detail::writeWhole(dir / "summary.html", "summary", html);
}

}  // namespace frob::course
