// The class gradebook: RFC 4180 CSV (fields with a comma, quote, CR or LF quoted, quotes doubled,
// records ended by CRLF), one row per submission; and the merge of the shards' gradebooks.
#include "frob/grade/grade_report.hpp"
#include "writers.hpp"

#include <algorithm>
#include <map>
#include <set>
#include <string_view>

namespace frob::course {

namespace fs = std::filesystem;
using detail::csvRecord;
using detail::CsvRow;
using detail::number;
using detail::parseCsv;
using detail::readWhole;
using detail::writeWhole;

namespace {

// `text` cut to its first line and `most` bytes.
std::string firstWords(std::string_view text, std::size_t most) {
  text = text.substr(0, text.find('\n'));
  return text.size() <= most ? std::string(text) : std::string(text.substr(0, most)) + "...";
}

// How grading went, for an instructor scanning the class: a compile failure, a hang and a weak run
// all score 0, and this tells them apart.
std::string resultOf(const Grade& g) {
  constexpr std::size_t kWords = 80;
  if (!g.graderFailure.empty()) return "NOT GRADED: " + firstWords(g.graderFailure, kWords);
  if (!g.compileError.empty()) {
    const std::size_t error = g.compileError.find("error: ");  // the compiler's first error, else the reason
    return "did not compile: " +
           firstWords(error == std::string::npos ? std::string_view(g.compileError) : std::string_view(g.compileError).substr(error + 7), kWords);
  }
  constexpr std::string_view kFailed = "the controller failed: ";
  std::size_t failed = 0, runs = 0;
  std::string first;
  for (const CheckGrade& c : g.checks) {
    for (const RunGrade& r : c.runs) {
      ++runs;
      if (!r.reason.starts_with(kFailed)) continue;
      if (failed++ == 0) first = firstWords(std::string_view(r.reason).substr(kFailed.size()), kWords);
    }
  }
  if (failed == 0) return "graded";
  return "failed at run time in " + std::to_string(failed) + " of " + std::to_string(runs) + " runs: " + first;
}

}  // namespace

Status writeGradebook(const std::vector<Grade>& grades, const fs::path& path) {
  std::vector<const Grade*> sorted;
  for (const Grade& g : grades) sorted.push_back(&g);
  std::stable_sort(sorted.begin(), sorted.end(), [](const Grade* a, const Grade* b) { return a->submission < b->submission; });
  for (std::size_t i = 1; i < sorted.size(); ++i) {
    if (sorted[i]->submission == sorted[i - 1]->submission) {
      return Status::failure("gradebook: cannot write '" + path.string() + "': submission '" + sorted[i]->submission + "' is graded twice");
    }
  }
  // The checks' columns: every check of every grade, in the order they first appear.
  std::vector<std::string> header{"submission", "score", "max_score", "result"};
  std::set<std::string> known;
  for (const Grade* g : sorted) {
    for (const CheckGrade& c : g->checks) {
      if (known.insert(c.name).second) header.push_back(c.name);
    }
  }
  std::string csv = csvRecord(header);
  for (const Grade* g : sorted) {
    // A submission frob failed to grade has no score, nor any check's (never 0), nor a maximum (its
    // checks, made or not when frob failed, are not its grade's).
    const bool graded = g->graderFailure.empty();
    std::vector<std::string> row{g->submission, graded ? number(g->score()) : "", graded ? number(g->maxScore()) : "", resultOf(*g)};
    for (std::size_t k = 4; k < header.size(); ++k) {
      const auto c = std::find_if(g->checks.begin(), g->checks.end(), [&](const CheckGrade& x) { return x.name == header[k]; });
      row.push_back(c == g->checks.end() || !graded ? std::string() : number(c->score));  // empty: not graded
    }
    csv += csvRecord(row);
  }
  return writeWhole(path, "gradebook", csv);
}

Result<std::vector<std::string>> mergeGradebooks(const std::vector<fs::path>& shards, const fs::path& out) {
  if (shards.empty()) return Status::failure("gradebook: no gradebooks to merge into '" + out.string() + "'");
  std::vector<std::string> header;
  fs::path headerFile;
  struct Source {
    std::vector<std::string> fields;
    std::string where;  // file:line
  };
  std::map<std::string, Source> rows;  // by submission, sorted
  for (const fs::path& shard : shards) {
    Result<std::string> text = readWhole(shard, "gradebook");
    if (!text) return text.status();
    Result<std::vector<CsvRow>> parsed = parseCsv(text.value(), shard.string());
    if (!parsed) return parsed.status();
    const std::vector<CsvRow>& records = parsed.value();
    if (records.empty()) return Status::failure("gradebook: " + shard.string() + " is empty (no header)");
    if (records[0].fields.size() < 3 || records[0].fields[0] != "submission") {
      return Status::failure("gradebook: " + shard.string() + ":1: not a gradebook (the header must start with submission,score,max_score)");
    }
    if (header.empty()) {
      header = records[0].fields;
      headerFile = shard;
    } else if (records[0].fields != header) {
      std::string got = csvRecord(records[0].fields), want = csvRecord(header);
      got.resize(got.size() - 2);
      want.resize(want.size() - 2);
      return Status::failure("gradebook: " + shard.string() + ":1: its header \"" + got + "\" differs from \"" + want + "\" of " +
                             headerFile.string() + " (gradebooks of different rubrics?)");
    }
    for (std::size_t i = 1; i < records.size(); ++i) {
      const CsvRow& r = records[i];
      const std::string where = shard.string() + ":" + std::to_string(r.line);
      if (r.fields.size() != header.size()) {
        return Status::failure("gradebook: " + where + ": " + std::to_string(r.fields.size()) + " fields where the header has " +
                               std::to_string(header.size()));
      }
      const auto [it, added] = rows.try_emplace(r.fields[0], Source{.fields = r.fields, .where = where});
      if (!added) {
        return Status::failure("gradebook: submission '" + r.fields[0] + "' is in " + it->second.where + " and in " + where);
      }
    }
  }
  std::string csv = csvRecord(header);
  std::vector<std::string> submissions;
  for (const auto& [submission, source] : rows) {
    csv += csvRecord(source.fields);
    submissions.push_back(submission);
  }
  if (Status s = writeWhole(out, "gradebook", csv); !s) return s;
  return submissions;
}

}  // namespace frob::course
