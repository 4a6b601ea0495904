// The grade as a table for the terminal.

#include "frob/grade/grade_report.hpp"
#include "frob/run/format.hpp"
#include "markup.hpp"
#include "writers.hpp"

#include <algorithm>

namespace frob::course {

using namespace detail;

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

std::string practiceTable(const Grade& g) {
  std::vector<std::string> criteria;  // the columns, in the order the checks name them
  std::vector<std::vector<std::string>> rows;
  std::vector<std::string> notes;   // after each row: why nothing was judged, or ""
  std::vector<std::string> reruns;  // under each row: its commands, or ""
  std::size_t passed = 0;
  for (const CheckGrade& c : g.checks) {
    for (std::size_t k = 0; k < c.runs.size(); ++k) {
      const RunGrade& r = c.runs[k];
      passed += r.passed;
      std::vector<std::string> row{terminalSafe(c.place(k)), r.passed ? "PASS" : "FAIL"};
      for (const CriterionVerdict& v : r.criteria) {
        const auto at = std::find(criteria.begin(), criteria.end(), v.criterion) - criteria.begin();
        if (at == static_cast<std::ptrdiff_t>(criteria.size())) criteria.push_back(v.criterion);
        if (row.size() < static_cast<std::size_t>(at) + 3) row.resize(static_cast<std::size_t>(at) + 3);
        row[static_cast<std::size_t>(at) + 2] = v.margin ? (v.margin->value < 0 ? "-" : "+") + v.margin->amount() : (v.passed ? "ok" : "failed");
      }
      rows.push_back(std::move(row));
      notes.push_back(r.criteria.empty() && !r.passed ? terminalSafe(r.reason) : "");  // nothing was judged: the controller failed
      std::string rerun;
      if (!r.passed && !r.generator.empty()) {
        const std::size_t cut = r.generator.find(" --seed ");  // "lounge --seed 42": lounge-42.toml, lounge-42.html
        const std::string file = r.generator.substr(0, cut) + "-" + r.generator.substr(cut + 8);
        rerun = terminalSafe("frob world generate " + r.generator + " --out " + file + ".toml && frob run " + g.submission + " --world " + file +
                             ".toml --seed " + std::to_string(r.seed) + " --assignment " + g.assignment + " --html " + file + ".html");
      }
      reruns.push_back(std::move(rerun));
    }
  }
  std::vector<std::string> header{"World", "Result"};
  for (const std::string& c : criteria) header.push_back(terminalSafe(c));
  std::vector<std::size_t> widths(header.size(), 0);
  for (std::size_t i = 0; i < header.size(); ++i) widths[i] = widthOf(header[i]);
  for (const auto& r : rows) {
    for (std::size_t i = 0; i < r.size() && i < widths.size(); ++i) widths[i] = std::max(widths[i], widthOf(r[i]));
  }
  const auto line = [&](const std::vector<std::string>& cells) {
    std::string out;
    for (std::size_t i = 0; i < cells.size(); ++i) {
      out += cells[i];
      if (i + 1 < cells.size()) out += std::string(widths[i] - std::min(widths[i], widthOf(cells[i])) + 2, ' ');
    }
    while (!out.empty() && out.back() == ' ') out.pop_back();
    return out + "\n";
  };
  std::string out =
      format("Practice: %zu of %zu runs passed; margins are by how much each criterion was met (+) or missed (-)\n", passed, rows.size());
  out += line(header);
  for (std::size_t k = 0; k < rows.size(); ++k) {
    out += line(rows[k]);
    if (!notes[k].empty()) out.insert(out.size() - 1, "  " + notes[k]);
    if (!reruns[k].empty()) out += "    to watch it: " + reruns[k] + "\n";
  }
  return out;
}

}  // namespace frob::course
