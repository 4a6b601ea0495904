#pragma once
/// A class graded into one folder (`frob grade A class/ --out DIR`): DIR/gradebook.csv with a row per
/// student, and DIR/<student>/ with what grading found for each (grade.json beside the files the
/// student reads). Grading some students again replaces their rows and folders and keeps the others'.
///
///   const std::vector<std::string> names = studentNames(submissions);
///   Result<StudentFolder> f = StudentFolder::open(dir, names[k]);   // write into f->path(), then
///   f->commit();                                                     // it replaces DIR/<student> whole
///   updateClassGradebook(dir, checkNames, {{names[k], &grade}});

#include "frob/base/result.hpp"
#include "frob/grade/grade.hpp"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace frob::course {

/// How grading a submission ended: "graded"; "did not compile"; "timed out" (a run stopped at one of
/// the host's deadlines: an endless loop, a sleep); "failed at run time" (its controller failed in a
/// run); "autograder error" (frob or the machine failed: no score).
[[nodiscard]] std::string resultKind(const Grade& g);

/// Every reason `g` lost points, whole, for its instructor: the grader's failure, the compile error,
/// or a line per failed run ("check, place: reason"; hidden runs with their full reason).
[[nodiscard]] std::string reasonsOf(const Grade& g);

/// The name each submission's student goes by, which names their row and folder, one per student:
/// the file's stem or the folder's name; a file's whole name where another submission would have
/// the same (alice.cpp beside alice/); a number after a name still shared (~2); a control character
/// as its escape (\x1b), and '_' before a name that would be hidden or one of the class folder's own files.
[[nodiscard]] std::vector<std::string> studentNames(const std::vector<std::filesystem::path>& submissions);

/// A student of `dir`'s gradebook and their submission as graded, found by `path`: their submission
/// or a file in it (class/dana/controller.cpp: dana, class/dana). None without a gradebook or such a row.
struct KnownStudent {
  std::string student;
  std::filesystem::path submission;
};
[[nodiscard]] std::optional<KnownStudent> knownStudent(const std::filesystem::path& dir, const std::filesystem::path& path);

/// One student's grade.
struct StudentGrade {
  std::string student;
  const Grade* grade = nullptr;
};

/// Puts `graded` into `dir`/gradebook.csv (RFC 4180): student,score,max_score,result, a column per
/// name of `checks`, reasons (whole), submission; a row per student, sorted. Rows of other students
/// are kept; a gradebook with other columns (another rubric) is refused, naming them. Locked against
/// other frobs writing it at once (shards on a shared folder), and written whole.
[[nodiscard]] Status updateClassGradebook(const std::filesystem::path& dir, const std::vector<std::string>& checks,
                                          const std::vector<StudentGrade>& graded);

/// Whether `g` would change `student`'s row of `dir`'s gradebook (made for `checks`): its score, result,
/// a check's score or a reason; true where there is no such row.
[[nodiscard]] bool changesRow(const std::filesystem::path& dir, const std::vector<std::string>& checks, const std::string& student, const Grade& g);

/// Writes `g` whole as JSON: every check and run, with reasons, hints, times and trajectories, and
/// the code's `fingerprints` (codeFingerprints()), as the class summary reads it (summary.html).
[[nodiscard]] Status writeGradeJson(const Grade& g, const std::string& student, const std::vector<std::uint64_t>& fingerprints,
                                    const std::filesystem::path& path);

/// The fingerprints of a submission's code (its file, or its folder's C++ files), less `starter`'s.
[[nodiscard]] std::vector<std::uint64_t> submissionFingerprints(const std::filesystem::path& submission, const std::filesystem::path& starter);

/// Writes `dir`/summary.html, one self-contained page of the whole class from every student's
/// grade.json: the scores' histogram, each check's pass rate, the commonest reasons and diagnoses,
/// the failed compiles, the slowest runs, similar work (also in `dir`/similarity.csv:
/// student_a,student_b,kind,score,evidence; similarPairs()), and each student with a link to their report.
[[nodiscard]] Status writeClassSummary(const std::filesystem::path& dir, const std::string& assignment);

/// A student's folder, written beside its place (`dir`/.<student>.partial) and put there whole.
class StudentFolder {
 public:
  /// An empty folder to write the student's files into; fails when `dir` cannot hold it.
  [[nodiscard]] static Result<StudentFolder> open(const std::filesystem::path& dir, const std::string& student);
  /// Where to write.
  [[nodiscard]] const std::filesystem::path& path() const { return partial_; }
  /// Replaces `dir`/<student> (and whatever an earlier grading left there) with what was written.
  [[nodiscard]] Status commit();

 private:
  std::filesystem::path partial_, final_;
};

}  // namespace frob::course
