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

namespace {

// A cell a spreadsheet would take for a formula (=, +, -, @, a tab or a return first, unless it
// is a number), or one that begins with the apostrophe that marks such cells, starts with one more
// apostrophe, which parseCsv() takes off again: =HYPERLINK(...) as a student's name stays text.
bool formulaLike(std::string_view text) {
  if (text.empty() || std::string_view("=+-@\t\r'").find(text.front()) == std::string_view::npos) return false;
  double value = 0;
  const auto [end, ec] = std::from_chars(text.data() + (text.front() == '+' ? 1 : 0), text.data() + text.size(), value);
  return ec != std::errc() || end != text.data() + text.size();
}

void appendCsvField(std::string& line, std::string_view text) {
  std::string cell = formulaLike(text) ? "'" : "";
  for (char c : text) {  // no control characters but line breaks and tabs, which would act on a terminal that shows the file
    const auto u = static_cast<unsigned char>(c);
    cell += (u < 0x20 && c != '\n' && c != '\r' && c != '\t') || u == 0x7f ? '?' : c;
  }
  if (cell.find_first_of(",\"\r\n") == std::string::npos) {
    line += cell;
    return;
  }
  line += '"';
  for (char c : cell) {
    if (c == '"') line += '"';
    line += c;
  }
  line += '"';
}

}  // namespace

std::string csvRecord(const std::vector<std::string>& fields) {
  std::string line;
  for (std::size_t i = 0; i < fields.size(); ++i) {
    if (i > 0) line += ',';
    appendCsvField(line, fields[i]);
  }
  return line + "\r\n";
}

Result<std::vector<CsvRow>> parseCsv(std::string_view text, const std::string& file) {
  const auto endsRecord = [&](std::size_t k) { return text[k] == '\n' || (text[k] == '\r' && k + 1 < text.size() && text[k + 1] == '\n'); };
  const auto error = [&](int at, const std::string& what) { return Status::failure("gradebook: " + file + ":" + std::to_string(at) + ": " + what); };
  std::vector<CsvRow> rows;
  std::size_t i = 0;
  int line = 1;
  while (i < text.size()) {
    CsvRow& row = rows.emplace_back(CsvRow{.fields = {}, .line = line});
    for (;;) {  // one field
      std::string& field = row.fields.emplace_back();
      if (i < text.size() && text[i] == '"') {
        const int opened = line;
        for (++i;; ++i) {
          if (i >= text.size()) return error(opened, "a quoted field is not closed");
          if (text[i] == '"' && (i + 1 >= text.size() || text[i + 1] != '"')) break;  // the closing quote
          if (text[i] == '"') ++i;                                                    // "" is one quote
          if (text[i] == '\n') ++line;
          field += text[i];
        }
        ++i;
        if (i < text.size() && text[i] != ',' && !endsRecord(i)) return error(line, "text after a closing quote");
      } else {
        for (; i < text.size() && text[i] != ',' && !endsRecord(i); ++i) {
          if (text[i] == '"') return error(line, "a quote inside an unquoted field");
          field += text[i];
        }
      }
      if (field.size() > 1 && field.front() == '\'' && formulaLike(std::string_view(field).substr(1)))
        field.erase(0, 1);  // as appendCsvField wrote it
      if (i < text.size() && text[i] == ',') {
        ++i;
        continue;
      }
      if (i < text.size()) {  // the end of the record
        i += text[i] == '\r' ? 2 : 1;
        ++line;
      }
      break;
    }
  }
  return rows;
}

}  // namespace frob::course::detail
