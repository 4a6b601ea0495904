// The grade as a table for the terminal.

#include "frob/grade/grade_report.hpp"
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

}  // namespace frob::course
