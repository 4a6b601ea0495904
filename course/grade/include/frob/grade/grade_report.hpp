#pragma once
/// A grade written for people and for other programs: a text table for the terminal, Gradescope's
/// and PrairieLearn's results.json, JUnit XML, a class gradebook (CSV) and one self-contained HTML
/// page. Every file appears under its name only when complete (written as `<path>.partial`, renamed).
///
///   std::cout << scoreTable(g);
///   Status s = writeGradescope(g, "/autograder/results/results.json");

#include "frob/grade/grade.hpp"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace frob::course {

/// The grade as a person reads it in a terminal: one line per check (name, score / points,
/// PASS, FAIL or PARTIAL, "[hidden]" or "[after_due_date]" for checks students do not see), the
/// failed runs' reasons indented under it, the compile error, the total and the notes. Plain ASCII
/// columns; control characters in names and reasons are shown as visible escapes (terminalSafe()).
[[nodiscard]] std::string scoreTable(const Grade& grade);
/// The runs of `grade` (frob grade --practice: every check visible) as a table for the terminal: a
/// row per world and seed, PASS or FAIL, and each criterion's margin ("+2.4 s", "-0.12 m"); under a
/// failed run in a generated world, the commands that rebuild that world and rerun it into a run
/// viewer page, judged as the grade judged it.
[[nodiscard]] std::string practiceTable(const Grade& grade);

/// Writes Gradescope's autograder results.json: the score, the execution time (whole seconds), a
/// summary of the visible checks (the compile error when there is one), one test per check.
[[nodiscard]] Status writeGradescope(const Grade& grade, const std::filesystem::path& path);

/// A picture shown with a check's result: a PNG of one of its runs (a visible check's only).
struct CheckImage {
  std::string check;  ///< the check it belongs to
  std::string label;  ///< what it shows: "the first failing run: lounge, seed 3"
  std::filesystem::path png;
};

/// Writes PrairieLearn's external-grader results.json: score in [0, 1], one test per visible check
/// (hidden ones summed into one) with its `images` (data: URLs; left out when they would take the file
/// past PrairieLearn's 1 MB), and "gradable": false with the compile error when it did not compile.
[[nodiscard]] Status writePrairieLearn(const Grade& grade, const std::filesystem::path& path, const std::vector<CheckImage>& images = {});

/// Writes JUnit XML: one <testsuite> named after the assignment, one <testcase> per run of each
/// check ("check / world seed N"), a <failure> with the reason for each failed run.
[[nodiscard]] Status writeJUnit(const Grade& grade, const std::filesystem::path& path);

/// Writes a class gradebook (CSV, RFC 4180, CRLF line ends): submission,score,max_score,result, then
/// one column per check; one row per grade, sorted by submission. The result says "graded", "did not
/// compile: " with the compiler's first error, or "failed at run time in N of M runs: " with the
/// first such reason (each cut to its first 80 bytes); a submission frob failed to grade
/// (Grade::graderFailure) has no score at all and "NOT GRADED: " with why. Two grades of one submission fail.
[[nodiscard]] Status writeGradebook(const std::vector<Grade>& grades, const std::filesystem::path& path);

/// Merges gradebooks written by writeGradebook (one per shard of a class) into `out`: their headers
/// must be identical and no submission may appear twice. Returns the submissions written, in order.
[[nodiscard]] Result<std::vector<std::string>> mergeGradebooks(const std::vector<std::filesystem::path>& shards, const std::filesystem::path& out);

/// Media embedded in the HTML report; an empty path means none.
struct HtmlMedia {
  std::filesystem::path video;   ///< an MP4 (H.264) of a run, embedded as a data: URI
  std::filesystem::path plot;    ///< a PNG plot, embedded as a data: URI
  std::filesystem::path viewer;  ///< a run viewer page of the same run (RunOutputs::html), embedded in a sandboxed frame
  std::optional<double> openAt;  ///< the instant the viewer opens at (the failure's), seconds; unset: the start
  std::string caption;           ///< what they show ("the first failing run: maze, seed 3")
};

/// Writes one self-contained HTML page (no outside resources, and no script but the run viewer's
/// own, allowed by its hash, in a frame of its own): the total, the checks as a table with the
/// failed runs' reasons, the compile error and notes, and the media of `media`.
[[nodiscard]] Status writeHtmlReport(const Grade& grade, const HtmlMedia& media, const std::filesystem::path& path);

}  // namespace frob::course
