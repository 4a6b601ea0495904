#pragma once
// Private: what the grade's writers share (one file per results format): checks' outcomes, points
// as text, the summary students see, and whole files.
#include "frob/base/result.hpp"
#include "frob/grade/grade.hpp"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace frob::course::detail {

using Json = nlohmann::ordered_json;

/// How a check did: PASS when every run passed, FAIL when none did, PARTIAL between.
enum class Outcome { Pass, Fail, Partial };

/// The runs of `c` that passed.
[[nodiscard]] std::size_t passedRuns(const CheckGrade& c);
/// The outcome of `c`; a check without runs (none was made) passes only if it has its points anyway.
[[nodiscard]] Outcome outcomeOf(const CheckGrade& c);
/// "PASS", "FAIL" or "PARTIAL".
[[nodiscard]] const char* toString(Outcome o);
/// `points` to 1e-4 of a point: 2/3 of a point is 0.6667, and sums do not show 0.30000000000000004.
[[nodiscard]] double rounded(double points);
/// `points` rounded, in the shortest text that reads back as the same double ("2", "0.5", "0.6667").
[[nodiscard]] std::string number(double points);
/// The lines of `text`, without their "\n" or "\r\n"; "" gives none.
[[nodiscard]] std::vector<std::string> linesOf(const std::string& text);
/// The summary both results.json files show students: the visible checks only (Gradescope hides the
/// total while some tests are hidden; a total that counts hidden checks would give them away).
[[nodiscard]] std::string summaryOf(const Grade& g);
/// `doc` as indented JSON; malformed UTF-8 (a compiler quoting a Latin-1 source) becomes U+FFFD.
[[nodiscard]] std::string jsonText(const Json& doc);

/// One CSV record (RFC 4180): fields with a comma, quote, CR or LF quoted, quotes doubled, ended by CRLF.
[[nodiscard]] std::string csvRecord(const std::vector<std::string>& fields);
/// A record read back, with the line where it starts.
struct CsvRow {
  std::vector<std::string> fields;
  int line = 0;
};
/// Reads RFC 4180 text (records ended by CRLF or LF; quoted fields may hold both); `file` names it in errors.
[[nodiscard]] Result<std::vector<CsvRow>> parseCsv(std::string_view text, const std::string& file);

/// Writes `bytes` to `<path>.partial` and renames it to `path`; `what` names the file in messages.
[[nodiscard]] Status writeWhole(const std::filesystem::path& path, const std::string& what, const std::string& bytes);
/// The whole of a file; `what` names it in messages.
[[nodiscard]] Result<std::string> readWhole(const std::filesystem::path& path, const std::string& what);

}  // namespace frob::course::detail
