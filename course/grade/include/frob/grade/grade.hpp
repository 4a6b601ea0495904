#pragma once
/// Grading a submission against an assignment's rubric. Every score comes from the trusted
/// simulation of the true trajectory: the controller runs in a sandboxed host and only its wheel
/// commands come back. Each run's commands can be logged and replayed to the same metrics.
///
///   Result<Rubric> rubric = loadRubric("assignments/go_to_goal/rubric.toml");
///   Grade g = grade({.rubric = *rubric, .assignment = "go_to_goal"}, "student.cpp");
///   g.score() / g.maxScore()

#include "frob/grade/judge.hpp"
#include "frob/grade/rubric.hpp"
#include "frob/grade/wheel_log.hpp"
#include "frob/run/host.hpp"
#include "frob/run/run_cores.hpp"
#include "frob/run/session.hpp"

#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace frob::course {

/// How to grade.
struct GradeDef {
  Rubric rubric;
  std::string assignment;          ///< its name, for reports
  std::string secret;              ///< the instructor's secret for hidden seeds; "" when none is given
  bool visibleOnly = false;        ///< grade only the visible checks (a student checking locally)
  HostDef host;                    ///< the controller host's limits
  std::filesystem::path logs;      ///< a folder for each run's wheel log (for --replay); empty: none
  std::string student;             ///< who submitted, where known, named in the logs; "" when not
  std::optional<double> daysLate;  ///< how long after its due date it was submitted, days (submissionLateness()); unset: not known
  CompilerSetup compiler = compilerSetup();
  std::optional<KeptWorlds> kept;  ///< the secret's hidden worlds to grade in; unset: those of fairHiddenWorlds()
  /// The cores the runs of a class share, a core each (gradeAll sets it when runs cannot have two
  /// cores each: see run_cores.hpp); compiles are not limited. Unset: runs go anywhere, any number.
  std::shared_ptr<RunCores> runCores;
};

/// The hidden worlds no student can find unfair: for each check that draws worlds from the secret,
/// the first `GeneratedWorlds::secret` draws in which the rubric's reference solution meets every
/// criterion and its starter (when it names one) fails one, so that no hidden world is passed
/// without the skill (at most ten times as many are tried). Computed once per rubric, secret,
/// reference and starter source and simulation, and kept in the controller cache (where a reference
/// solution is absent, as in a Gradescope zip, what the cache holds is used). None without a
/// secret, a reference, or a cache. A failure of frob or the machine is a graderFailure(), and then
/// no grade stands (grade() sets Grade::graderFailure).
[[nodiscard]] Result<KeptWorlds> fairHiddenWorlds(const GradeDef& def);
/// Where fairHiddenWorlds keeps what it found for `def`'s rubric and secret, under the controller cache.
[[nodiscard]] std::filesystem::path keptWorldsFile(const GradeDef& def);

/// One run of a check: a world with a seed.
struct RunGrade {
  std::string world;  ///< as the rubric names it
  std::uint64_t seed = 0;
  std::string generator;  ///< a generated world's kind and seed, as `frob world generate` takes them ("lounge --seed 42"); "" otherwise
  bool passed = false;
  std::string reason;                      ///< why it failed, in words a student can act on; "" when it passed
  std::string kind;                        ///< what failed, as a check that is not visible says it: nothing the controller chose
  std::vector<std::string> hints;          ///< what common mistake the run shows, naming the fix (course/diagnose.hpp)
  std::vector<CriterionVerdict> criteria;  ///< each criterion's verdict and margin; none when the controller failed
  std::uint64_t trajectoryHash = 0;        ///< of every true pose (replays must match it)
  std::filesystem::path log;               ///< its wheel log, when logs are kept
  double wallSeconds = 0.0;  ///< how long the run took, or judging an earlier check's same run (a timing field, like Grade::wallSeconds)
};

/// One check's outcome: the fraction of its runs that passed, times its points.
struct CheckGrade {
  std::string name;
  double points = 0.0;  ///< at most
  double score = 0.0;   ///< points × passed runs / runs
  Visibility visibility = Visibility::Visible;
  std::vector<RunGrade> runs;
  /// Where run k took place, as a student may read it: "maze, seed 3"; for a check that is not
  /// visible, "hidden world 2" (nothing to rebuild the world from).
  [[nodiscard]] std::string place(std::size_t k) const;
  /// Why run k failed, as a student may read it: for a check that is not visible, only what failed
  /// (no measure, place, time or text the controller could have chosen to read out a hidden world).
  [[nodiscard]] std::string reasonShown(std::size_t k) const;
  /// The hints of run k, as a student may read them: none for a check that is not visible.
  [[nodiscard]] std::vector<std::string> hintsShown(std::size_t k) const;
  /// How near the edge run k met or missed each criterion, one line ("goal passed by 2.4 s (reached
  /// goal at 7.6 s of 75 s); collisions passed by 1 collision (...)"), as a student may read it: ""
  /// for a check that is not visible (a margin is a number the controller could choose).
  [[nodiscard]] std::string marginsShown(std::size_t k) const;
  /// The reasons of the failed runs, one line each ("in maze, seed 3: touched a wall at 41.2 s at (3.1, 4.5)";
  /// "in hidden world 2: touched a wall at 41.2 s"), each followed by its hints ("  hint: ..."); for a
  /// visible check, every run's margins too ("in maze, seed 3: margins: ...").
  [[nodiscard]] std::string output() const;
};

/// A submission's place on one of the rubric's leaderboards (LeaderboardMetric).
struct LeaderboardValue {
  std::string name;
  std::optional<double> value;  ///< the mean over the check's runs; unset when a run missed the criterion (no place on the board)
  bool ascending = false;
};

/// A submission's grade.
struct Grade {
  std::string assignment;
  std::string submission;      ///< the file or folder, as given
  std::string submissionHash;  ///< SHA-256 of its files, in hex (submissionHash()), as its logs name it
  std::string compileError;    ///< the compiler's complaint when it did not compile (then every check scores 0)
  std::string graderFailure;   ///< why frob or the machine could not grade it (kGraderFailure): then it has no grade at all, not 0
  std::vector<CheckGrade> checks;
  double latePenalty = 0.0;                   ///< points taken for lateness (Rubric::latePerDay), already out of score()
  std::vector<LeaderboardValue> leaderboard;  ///< one per Rubric::leaderboard entry
  std::vector<std::string> notes;             ///< e.g. output that was cut
  std::string sandboxMissing;                 ///< the sandbox's layers this machine could not apply, one per line; for the instructor only
  double wallSeconds = 0.0;  ///< how long grading took (with the runs' and startedAt, the only fields that differ between two gradings)
  std::string startedAt;     ///< when grading began, UTC, as 2026-12-02T21:58:37
  [[nodiscard]] double score() const;
  [[nodiscard]] double maxScore() const;
  /// How long grading took, shown to students: wallSeconds less the runs of checks they do not see,
  /// whose lengths a controller could stretch (sleeping within its pace) to spell out a hidden world.
  [[nodiscard]] double shownSeconds() const;
};

/// Where `grade` stands on `metric`'s board: the mean of the criterion's measure over the check's
/// runs (Margin::at for a time, Margin::value for a margin); none when a run missed the criterion.
[[nodiscard]] LeaderboardValue leaderboardValue(const LeaderboardMetric& metric, const Grade& grade);

/// How many days after its due date a submission came, from Gradescope's submission_metadata.json
/// (`created_at` against `assignment.due_date`, ISO 8601 with offsets); negative when early.
[[nodiscard]] Result<double> submissionLateness(const std::filesystem::path& metadata);

/// Compiles and grades `submission`, a .cpp file or a folder of several (see compileSubmission()). Never fails on the submission's account: a compile
/// error, a crash or a hang scores 0 in the checks it touched, with the reason. A failure of frob or the machine (a host that cannot
/// start, a full disk) stops it with Grade::graderFailure set: no score stands.
[[nodiscard]] Grade grade(const GradeDef& def, const std::filesystem::path& submission);

/// The grade `submission` would get from `def` (a rubric since fixed), judged again from the wheel logs
/// in `logs` of an earlier grading with the same secret, without compiling or running it. Nothing when
/// some run `def` makes has no such log (another world, seed or length, or none) or the simulator now
/// strays from a logged trajectory: then only grading it again can tell.
[[nodiscard]] std::optional<Grade> rejudge(const GradeDef& def, const std::filesystem::path& submission, const std::filesystem::path& logs);

/// What gradeAll does for each submission besides grading it, in the job that grades it.
struct ClassHooks {
  std::function<std::filesystem::path(std::size_t k)> logs;   ///< submission k's folder of wheel logs; unset: GradeDef::logs
  std::function<void(std::size_t k, const Grade& g)> graded;  ///< told each grade once made (its files written side by side)
};

/// Grades each of `submissions` (a class), `jobs` at a time, in their order; `progress(done, total)`
/// is told after each. When runs cannot have two cores each, each takes one of its own, where its
/// controller hosts sleep while the grader simulates, rather than spin.
[[nodiscard]] std::vector<Grade> gradeAll(GradeDef def, const std::vector<std::filesystem::path>& submissions, int jobs,
                                          const std::function<void(std::size_t done, std::size_t total)>& progress = {},
                                          const ClassHooks& hooks = {});

/// The submissions in `dir`, sorted: each .cpp file in it, compiled alone, and each subfolder that holds
/// .cpp files, a submission of several files; links and special files too, which compiling refuses
/// (never followed: one could name the secret, /etc/shadow or a classmate's file).
[[nodiscard]] std::vector<std::filesystem::path> submissionsIn(const std::filesystem::path& dir);
/// What to grade for controller file `file`: its folder when the file is the folder's one controller
/// and other .cpp files lie beside it (a submission of several files), else the file alone.
[[nodiscard]] std::filesystem::path submissionOf(const std::filesystem::path& file);
/// Shard `i` of `n` (1-based) of `all`: every n-th from the i-th, the same on every machine.
[[nodiscard]] std::vector<std::filesystem::path> shardOf(const std::vector<std::filesystem::path>& all, int i, int n);

/// One of the course's assignments (a folder of assignments/ with a rubric.toml).
struct Assignment {
  std::string name;   ///< its folder's name
  std::string title;  ///< the rubric's title, or why the rubric cannot be read
  std::filesystem::path rubric;
};
/// The course's assignments, by name.
[[nodiscard]] std::vector<Assignment> assignments();

/// An assignment's rubric: `name` under the course's assignments/ folder, a folder holding a
/// rubric.toml, or a rubric file.
[[nodiscard]] Result<std::filesystem::path> findRubric(const std::string& name);

/// Runs `run` of check `check` again with a video and plots of it (`outputs`), for a report, and
/// gives the film's trajectory hash. The controller sees the same in a filmed run as in a graded one,
/// so the film is the graded run again; one whose trajectory differs from the graded run's is refused.
[[nodiscard]] Result<std::uint64_t> filmRun(const GradeDef& def, const std::filesystem::path& submission, const std::string& check,
                                            const RunGrade& run, const RunOutputs& outputs);

/// What replaying a wheel log gives: the run's verdict and trajectory, recomputed.
struct Replay {
  std::string check;
  std::string submission;      ///< whose run it was, as the log names it
  std::string submissionHash;  ///< SHA-256 of that submission's files
  std::string student;         ///< who submitted it, where the grading knew; "" otherwise
  RunGrade run;
};

/// Replays `log` (written by a grading with GradeDef::logs) in the trusted simulator and judges it
/// again; the verdict, reason and trajectory hash are those of the original run, bit for bit. A log
/// is signed with the secret it was graded with (HMAC-SHA256 over its text); one that is unsigned,
/// edited, or signed with another secret is refused, and so is one whose replay strays from the
/// graded trajectory. A log names the submission it was graded for: given `submission`, one of any
/// other submission (another SHA-256 of its files) is refused.
[[nodiscard]] Result<Replay> replay(const std::filesystem::path& log, const std::string& secret, const std::filesystem::path& submission = {});

}  // namespace frob::course
