// A class graded into one folder: the students' names, the gradebook's rows, each student's folder.
#include "frob/grade/class_folder.hpp"

#include "frob/grade/similarity.hpp"
#include "frob/run/format.hpp"
#include "frob/sandbox/fd.hpp"
#include "writers.hpp"

#include <fcntl.h>
#include <sys/file.h>

#include <algorithm>
#include <cerrno>
#include <cinttypes>
#include <cstring>
#include <map>
#include <set>

namespace frob::course {

namespace fs = std::filesystem;
using detail::csvRecord;
using detail::CsvRow;
using detail::Json;
using detail::number;

namespace {

// A spreadsheet's cell holds at most 32767 characters: longer reasons end with where the rest is.
constexpr std::size_t kCellBytes = 30000;

// The class folder's own files, which no student's folder may take the name of.
const std::set<std::string>& reservedNames() {
  static const std::set<std::string> names{"gradebook.csv", "summary.html", "similarity.csv"};
  return names;
}

// Whether a controller's failure is one of the host's deadlines (course/run/src/host_impl.hpp).
bool timedOut(std::string_view reason) {
  for (std::string_view mark : {"an endless loop?", "waited or slept", "of wall-clock time", "of CPU in the run"}) {
    if (reason.find(mark) != std::string_view::npos) return true;
  }
  return false;
}

constexpr std::string_view kFailed = "the controller failed: ";

}  // namespace

std::string resultKind(const Grade& g) {
  if (!g.graderFailure.empty()) return "autograder error";
  if (!g.compileError.empty()) return "did not compile";
  bool failed = false;
  for (const CheckGrade& c : g.checks) {
    for (const RunGrade& r : c.runs) {
      if (!r.reason.starts_with(kFailed)) continue;
      if (timedOut(r.reason)) return "timed out";
      failed = true;
    }
  }
  return failed ? "failed at run time" : "graded";
}

std::string reasonsOf(const Grade& g) {
  std::string text;
  if (!g.graderFailure.empty()) {
    text = g.graderFailure;
  } else if (!g.compileError.empty()) {
    text = g.compileError;
  } else {
    for (const CheckGrade& c : g.checks) {
      for (std::size_t k = 0; k < c.runs.size(); ++k) {
        if (!c.runs[k].passed) text += c.name + ", " + c.place(k) + ": " + c.runs[k].reason + "\n";
      }
    }
  }
  while (!text.empty() && text.back() == '\n') text.pop_back();
  if (text.size() > kCellBytes) text = text.substr(0, kCellBytes) + "\n[... cut: the whole is in the student's grade.json]";
  return text;
}

std::vector<std::string> studentNames(const std::vector<fs::path>& submissions) {
  const auto usable = [](const std::string& file) {
    std::string name;  // a control character, which would act on a terminal, as its escape: a\x1b
    for (const char c : file)
      name += static_cast<unsigned char>(c) < 0x20 || c == 0x7f ? format("\\x%02x", static_cast<unsigned char>(c)) : std::string(1, c);
    return name.empty() || name.front() == '.' || reservedNames().contains(name) ? "_" + name : name;
  };
  // A folder is named by its name; a file by its stem, or its whole name where another submission
  // would have the same name (alice.cpp beside alice/, dana.v2.cpp beside dana.v2/); a name still
  // shared gets a number (~2), so that no two students ever share a row or a folder.
  std::vector<std::string> names;
  std::map<std::string, int> uses;
  for (const fs::path& s : submissions) ++uses[names.emplace_back(usable(s.extension() == ".cpp" ? s.stem().string() : s.filename().string()))];
  std::set<std::string> taken;
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (uses[names[i]] > 1 && submissions[i].extension() == ".cpp") names[i] = usable(submissions[i].filename().string());
    const std::string base = names[i];
    for (int k = 2; !taken.insert(names[i]).second; ++k) names[i] = base + "~" + std::to_string(k);
  }
  return names;
}

std::optional<KnownStudent> knownStudent(const fs::path& dir, const fs::path& path) {
  Result<std::string> text = detail::readWhole(dir / "gradebook.csv", "gradebook");
  if (!text) return std::nullopt;
  Result<std::vector<CsvRow>> rows = detail::parseCsv(text.value(), (dir / "gradebook.csv").string());
  if (!rows || rows.value().empty() || rows.value()[0].fields.empty() || rows.value()[0].fields[0] != "student") return std::nullopt;
  std::error_code ec;
  const fs::path wanted = fs::weakly_canonical(path, ec);
  for (std::size_t i = 1; i < rows.value().size(); ++i) {
    const CsvRow& r = rows.value()[i];
    const fs::path submission = fs::weakly_canonical(r.fields.back(), ec);
    if (submission == wanted || submission == wanted.parent_path()) return KnownStudent{r.fields.front(), r.fields.back()};
  }
  return std::nullopt;
}

namespace {

// A student's gradebook row: student, score, max_score, result, a score per check, reasons, submission.
std::vector<std::string> gradebookRow(const std::string& student, const Grade& g, const std::vector<std::string>& checks) {
  const bool scored = g.graderFailure.empty();  // no score at all, never 0, nor a maximum (gradebook.cpp)
  std::vector<std::string> row{student, scored ? number(g.score()) : "", scored ? number(g.maxScore()) : "", resultKind(g)};
  for (const std::string& name : checks) {
    const auto c = std::find_if(g.checks.begin(), g.checks.end(), [&](const CheckGrade& x) { return x.name == name; });
    row.push_back(c == g.checks.end() || !scored ? std::string() : number(c->score));
  }
  row.push_back(reasonsOf(g));
  row.push_back(g.submission);
  return row;
}

}  // namespace

bool changesRow(const fs::path& dir, const std::vector<std::string>& checks, const std::string& student, const Grade& g) {
  Result<std::string> text = detail::readWhole(dir / "gradebook.csv", "gradebook");
  if (!text) return true;
  Result<std::vector<CsvRow>> rows = detail::parseCsv(text.value(), (dir / "gradebook.csv").string());
  if (!rows) return true;
  const std::vector<std::string> row = gradebookRow(student, g, checks);
  return std::none_of(rows.value().begin(), rows.value().end(), [&](const CsvRow& r) { return r.fields == row; });
}

Status updateClassGradebook(const fs::path& dir, const std::vector<std::string>& checks, const std::vector<StudentGrade>& graded) {
  const fs::path file = dir / "gradebook.csv";
  std::error_code ec;
  fs::create_directories(dir, ec);
  // One frob at a time reads, changes and writes it (shards of a class on a shared folder).
  const sandbox::Fd lock(::open((dir / ".gradebook.lock").c_str(), O_RDWR | O_CREAT | O_NOFOLLOW | O_CLOEXEC, 0644));
  if (!lock.valid() || ::flock(lock.get(), LOCK_EX) != 0) {
    return Status::failure("gradebook: cannot lock '" + (dir / ".gradebook.lock").string() + "': " + std::strerror(errno));
  }
  std::vector<std::string> header{"student", "score", "max_score", "result"};
  header.insert(header.end(), checks.begin(), checks.end());
  header.insert(header.end(), {"reasons", "submission"});
  std::map<std::string, std::vector<std::string>> rows;
  if (fs::exists(fs::symlink_status(file, ec))) {
    Result<std::string> text = detail::readWhole(file, "gradebook");
    if (!text) return text.status();
    Result<std::vector<CsvRow>> parsed = detail::parseCsv(text.value(), file.string());
    if (!parsed) return parsed.status();
    if (parsed.value().empty() || parsed.value()[0].fields != header) {
      std::string want = csvRecord(header);
      want.resize(want.size() - 2);
      return Status::failure("gradebook: " + file.string() + ":1: written for other checks than this rubric's (" + want +
                             "): grade the class into a new folder");
    }
    for (std::size_t i = 1; i < parsed.value().size(); ++i) {
      const CsvRow& r = parsed.value()[i];
      if (r.fields.size() != header.size()) {
        return Status::failure("gradebook: " + file.string() + ":" + std::to_string(r.line) + ": " + std::to_string(r.fields.size()) +
                               " fields where the header has " + std::to_string(header.size()));
      }
      rows[r.fields[0]] = r.fields;
    }
  }
  for (const StudentGrade& s : graded) rows[s.student] = gradebookRow(s.student, *s.grade, checks);
  std::string csv = csvRecord(header);
  for (const auto& [student, row] : rows) csv += csvRecord(row);
  return detail::writeWhole(file, "gradebook", csv);
}

std::vector<std::uint64_t> submissionFingerprints(const fs::path& submission, const fs::path& starter) {
  std::vector<fs::path> files{submission};
  std::error_code ec;
  if (fs::is_directory(fs::symlink_status(submission, ec))) {
    files.clear();
    for (const fs::directory_entry& e : fs::directory_iterator(submission, ec)) {
      const std::string ext = e.path().extension().string();
      if (e.is_regular_file(ec) && !e.is_symlink(ec) && (ext == ".cpp" || ext == ".hpp" || ext == ".h")) files.push_back(e.path());
    }
    std::sort(files.begin(), files.end());
  }
  std::string text;
  for (const fs::path& f : files) {
    if (!fs::is_regular_file(fs::symlink_status(f, ec))) continue;  // links are never followed
    if (Result<std::string> t = detail::readWhole(f, "fingerprints")) text += t.value() + "\n";
  }
  std::vector<std::uint64_t> mine = codeFingerprints(text);
  if (starter.empty() || !fs::is_regular_file(starter, ec)) return mine;
  const Result<std::string> given = detail::readWhole(starter, "fingerprints");
  const std::vector<std::uint64_t> handedOut = given ? codeFingerprints(given.value()) : std::vector<std::uint64_t>{};
  std::vector<std::uint64_t> own;
  std::set_difference(mine.begin(), mine.end(), handedOut.begin(), handedOut.end(), std::back_inserter(own));
  return own;
}

Status writeGradeJson(const Grade& g, const std::string& student, const std::vector<std::uint64_t>& fingerprints, const fs::path& path) {
  Json checks = Json::array();
  for (const CheckGrade& c : g.checks) {
    Json runs = Json::array();
    for (std::size_t k = 0; k < c.runs.size(); ++k) {
      const RunGrade& r = c.runs[k];
      Json margins = Json::array();
      for (const CriterionVerdict& v : r.criteria) {
        if (!v.margin) continue;
        margins.push_back({{"criterion", v.criterion},
                           {"passed", v.passed},
                           {"value", v.margin->value},
                           {"unit", v.margin->unit},
                           {"text", v.margin->text},
                           {"at", v.margin->at ? Json(*v.margin->at) : Json(nullptr)}});
      }
      runs.push_back({{"place", c.place(k)},
                      {"world", r.world},
                      {"seed", r.seed},
                      {"passed", r.passed},
                      {"reason", r.reason},
                      {"hints", r.hints},
                      {"margins", margins},
                      {"seconds", r.wallSeconds},
                      {"trajectory", format("%016" PRIx64, r.trajectoryHash)}});
    }
    checks.push_back({{"name", c.name}, {"points", c.points}, {"score", c.score}, {"visibility", toString(c.visibility)}, {"runs", runs}});
  }
  Json hexes = Json::array();
  for (std::uint64_t f : fingerprints) hexes.push_back(format("%016" PRIx64, f));
  const Json doc{{"student", student},
                 {"submission", g.submission},
                 {"sha256", g.submissionHash},
                 {"score", g.graderFailure.empty() ? Json(detail::rounded(g.score())) : Json(nullptr)},
                 {"max_score", detail::rounded(g.maxScore())},
                 {"result", resultKind(g)},
                 {"compile_error", g.compileError},
                 {"grader_failure", g.graderFailure},
                 {"seconds", g.wallSeconds},
                 {"started_at", g.startedAt},
                 {"checks", checks},
                 {"fingerprints", hexes}};
  return detail::writeWhole(path, "grade", detail::jsonText(doc));
}

Result<StudentFolder> StudentFolder::open(const fs::path& dir, const std::string& student) {
  StudentFolder f;
  f.final_ = dir / student;
  f.partial_ = dir / ("." + student + ".partial");
  std::error_code ec;
  fs::remove_all(f.partial_, ec);  // left by a frob that was stopped
  if (!fs::create_directories(f.partial_, ec)) {
    return Status::failure("class folder: cannot make '" + f.partial_.string() + "': " + (ec ? ec.message() : "it is there already"));
  }
  return f;
}

Status StudentFolder::commit() {
  std::error_code ec;
  const fs::path old = final_.parent_path() / ("." + final_.filename().string() + ".old");
  fs::remove_all(old, ec);
  const bool earlier = fs::exists(fs::symlink_status(final_, ec));
  ec.clear();
  if (earlier) fs::rename(final_, old, ec);
  if (!ec) fs::rename(partial_, final_, ec);
  if (ec) return Status::failure("class folder: cannot put '" + final_.string() + "' in place: " + ec.message());
  fs::remove_all(old, ec);
  return {};
}

}  // namespace frob::course
