// What the grade's writers share: checks' outcomes, points as text, the students' summary, files.
#include "writers.hpp"

#include "frob/render/output_file.hpp"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>

namespace frob::course::detail {

namespace fs = std::filesystem;

std::size_t passedRuns(const CheckGrade& c) {
  return static_cast<std::size_t>(std::count_if(c.runs.begin(), c.runs.end(), [](const RunGrade& r) { return r.passed; }));
}

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

double rounded(double points) {
  const double r = std::round(points * 1e4) / 1e4;
  return r == 0.0 ? 0.0 : r;  // no "-0"
}

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

std::string jsonText(const Json& doc) { return doc.dump(2, ' ', false, Json::error_handler_t::replace) + "\n"; }

std::string number(double points) {
  char buf[32];
  return {buf, std::to_chars(buf, buf + sizeof buf, rounded(points)).ptr};
}

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

}  // namespace frob::course::detail
