// frob grade: one submission or a class against an assignment's rubric, with the files that
// Gradescope, PrairieLearn, CI systems and people read; and replays of a run's wheel log.
#include "grade.hpp"

#include "frob/grade/class_folder.hpp"
#include "frob/grade/grade.hpp"
#include "frob/grade/grade_report.hpp"
#include "frob/grade/gradescope.hpp"
#include "frob/run/format.hpp"
#include "frob/run/scratch.hpp"
#include "frob/run/terminal_text.hpp"
#include "progress.hpp"

#include <unistd.h>

#include <cinttypes>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <optional>

namespace frob::app {

namespace {

namespace fs = std::filesystem;

int fail(const std::string& message, int status = 1) {
  std::cerr << "frob: " << course::terminalSafe(message, true) << "\n";
  return status;
}

// The sandbox's layers this machine could not apply, said once to the instructor (on stderr, which
// Gradescope and PrairieLearn show to staff only), never in what a student reads.
void warnOfMissingLayers(const std::vector<course::Grade>& grades) {
  for (const course::Grade& g : grades) {
    if (g.sandboxMissing.empty()) continue;
    std::cerr << "frob: the controllers ran with parts of their sandbox missing on this machine:\n" << g.sandboxMissing;
    return;
  }
}

// The instructor's secret: the file's first line, else $FROB_GRADE_SECRET.
Result<std::string> readSecret(const std::string& file) {
  if (file.empty()) {
    const char* env = std::getenv("FROB_GRADE_SECRET");
    return std::string(env != nullptr ? env : "");
  }
  std::ifstream in(file);
  std::string secret;
  if (!in || !std::getline(in, secret) || secret.empty()) return Status::failure("--secret " + file + ": cannot read a secret from it");
  return secret;
}

// The first failed run of a visible check, as (check, run): what a report may show a student.
const course::RunGrade* firstFailure(const course::Grade& g, std::string& check) {
  for (const course::CheckGrade& c : g.checks) {
    if (c.visibility != course::Visibility::Visible) continue;
    for (const course::RunGrade& r : c.runs) {
      if (!r.passed) return check = c.name, &r;
    }
  }
  return nullptr;
}

// The report's film fits in this, whatever the run's length, so that a report stays small enough to mail or upload (~3 MB).
constexpr std::uint64_t kReportVideoBytes = 2'000'000;

// Writes each file asked for (making their folders); the first that cannot be written is the error.
// The report, the videos and PrairieLearn's results show the first failing run (refilmed): the report
// films it unless `film` is false (a class's reports: the viewer and the plot); PrairieLearn's show its plot.
Status writeOutputs(const GradeArgs& a, const course::GradeDef& def, const course::Grade& g, bool film = true) {
  for (const std::string& file : {a.results, a.prairielearn, a.junit, a.report}) {
    std::error_code ec;
    if (!file.empty() && fs::path(file).has_parent_path()) fs::create_directories(fs::path(file).parent_path(), ec);
  }
  if (!a.results.empty()) {
    if (Status s = course::writeGradescope(g, a.results); !s) return s;
  }
  if (!a.junit.empty()) {
    if (Status s = course::writeJUnit(g, a.junit); !s) return s;
  }
  course::HtmlMedia media;
  std::vector<course::CheckImage> images;
  std::string check;
  const course::RunGrade* run = firstFailure(g, check);
  const bool pages = !a.report.empty() || !a.videos.empty();
  std::error_code ec;
  fs::path dir;
  course::Scratch films;  // the film's folder unless --videos keeps it: removed when done, and swept when a killed frob left it
  if (run != nullptr && g.compileError.empty() && (pages || !a.prairielearn.empty())) {
    if (a.videos.empty()) {
      const fs::path temp = fs::temp_directory_path();
      course::removeStale(temp, "frob-report");
      Result<course::Scratch> made = course::Scratch::make(temp, "frob-report");
      if (!made) return made.status();
      films = std::move(made.value());
    }
    dir = a.videos.empty() ? films.path() : fs::path(a.videos);
    fs::create_directories(dir, ec);
    const std::string stem = (dir / fs::path(run->log.empty() ? "first_failure" : run->log.stem().string())).string();
    course::RunOutputs out{
        .video = film && pages ? stem + ".mp4" : "", .videoBytes = kReportVideoBytes, .plot = stem + ".png", .html = pages ? stem + ".html" : ""};
    media.caption = "The first failing run: " + check + ", in " + run->world + " with seed " + std::to_string(run->seed) + ": " + run->reason;
    for (const course::CriterionVerdict& v : run->criteria) {
      if (!v.passed && v.margin && v.margin->at && !media.openAt) media.openAt = v.margin->at;
    }
    if (media.openAt) media.caption += course::format(" The viewer opens at %.1f s, where the check was decided.", *media.openAt);
    if (Result<std::uint64_t> shown = course::filmRun(def, g.submission, check, *run, out)) {
      media.video = out.video, media.plot = out.plot, media.viewer = out.html;
      media.caption += course::format(" The run shown is the graded run: its trajectory hash, %016" PRIx64 ", is the graded run's, %016" PRIx64 ".",
                                      shown.value(), run->trajectoryHash);
      images.push_back(
          {.check = check, .label = "The first failing run, " + run->world + " with seed " + std::to_string(run->seed), .png = out.plot});
    } else {
      media.caption += " (" + shown.error() + ")";
    }
  }
  Status s;
  if (!a.prairielearn.empty()) s = course::writePrairieLearn(g, a.prairielearn, images);
  if (s && !a.report.empty()) s = course::writeHtmlReport(g, media, a.report);
  return s;
}

// A submission frob could not grade through its own or the machine's fault: said loudly, no results
// written (Gradescope and PrairieLearn then report the autograder's failure, never a score), not 0.
int notGraded(const course::Grade& g) {
  return fail("could not grade " + course::terminalSafe(g.submission) + ": " + g.graderFailure +
              "\nThis is no fault of the submission: no results were written and no score stands; grade it again once fixed.");
}

// Grades `submissions` of `students` into the class folder `a.out`: each student's folder (their
// results.json, junit.xml, grade.json, wheel logs, and report.html when they lost points), their rows
// of its gradebook, then its summary. The other students' rows and folders stay.
// With --changed, of `submissions`, those whose row of the class folder's gradebook (made for `checks`)
// the rubric as it now is changes, judged again from their logs; and those it cannot tell of without
// grading them again (no row, no logs, other runs, another simulator).
void keepChanged(const course::GradeDef& def, const fs::path& dir, const std::vector<std::string>& checks, std::vector<fs::path>& submissions,
                 std::vector<std::string>& students) {
  std::vector<fs::path> again;
  std::vector<std::string> who;
  std::size_t changed = 0, unlogged = 0;
  for (std::size_t k = 0; k < submissions.size(); ++k) {
    const std::optional<course::Grade> now = course::rejudge(def, submissions[k], dir / students[k] / "logs");
    if (now && !course::changesRow(dir, checks, students[k], *now)) continue;
    ++(now ? changed : unlogged);
    again.push_back(submissions[k]), who.push_back(students[k]);
  }
  std::string names;
  for (const std::string& s : who) names += (names.empty() ? ": grading again " : ", ") + course::terminalSafe(s);
  std::fprintf(stderr, "frob: of %zu students, %zu unchanged, %zu changed by the rubric as it now is, %zu without logs of the runs it now makes%s\n",
               submissions.size(), submissions.size() - who.size(), changed, unlogged, names.c_str());
  submissions = std::move(again), students = std::move(who);
}

int gradeIntoFolder(const GradeArgs& a, const course::GradeDef& def, std::vector<fs::path> submissions, std::vector<std::string> students) {
  const fs::path dir = a.out;
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (!fs::is_directory(dir)) return fail("--out " + a.out + ": cannot make that folder: " + ec.message(), 2);
  std::vector<std::string> checks;
  for (const course::Check& c : def.rubric.checks) {
    if (!def.visibleOnly || c.visibility == course::Visibility::Visible) checks.push_back(c.name);
  }
  if (a.changed) keepChanged(def, dir, checks, submissions, students);
  std::vector<std::optional<course::StudentFolder>> folders(submissions.size());
  std::vector<std::string> problems(submissions.size());
  const course::ClassHooks hooks{.logs =
                                     [&](std::size_t k) {
                                       Result<course::StudentFolder> f = course::StudentFolder::open(dir, students[k]);
                                       if (!f) return problems[k] = f.error(), fs::path();
                                       folders[k].emplace(std::move(f.value()));
                                       return folders[k]->path() / "logs";
                                     },
                                 .graded =
                                     [&](std::size_t k, const course::Grade& g) {
                                       if (!folders[k]) return;
                                       const fs::path in = folders[k]->path();
                                       // An autograder error is written too, with no score and no results: a row and
                                       // folder are always of the student's file as it now is, never an older grade.
                                       Status s;
                                       if (g.graderFailure.empty()) {
                                         GradeArgs each{.results = (in / "results.json").string(), .junit = (in / "junit.xml").string()};
                                         if (g.score() < g.maxScore()) each.report = (in / "report.html").string();
                                         s = writeOutputs(each, def, g, false);
                                       }
                                       if (s)
                                         s = course::writeGradeJson(
                                             g, students[k], course::submissionFingerprints(submissions[k], def.rubric.starter), in / "grade.json");
                                       if (s) s = folders[k]->commit();
                                       if (s) s = course::updateClassGradebook(dir, checks, {{students[k], &g}});
                                       if (!s) problems[k] = s.error();
                                     }};
  ProgressBar bar(stderr, ::isatty(STDERR_FILENO) == 1, "frob: grading " + def.assignment);
  char detail[48];
  const std::vector<course::Grade> grades = course::gradeAll(
      def, submissions, a.jobs,
      [&](std::size_t done, std::size_t total) {
        std::snprintf(detail, sizeof detail, "%zu / %zu submissions", done, total);
        bar.show(static_cast<double>(done) / static_cast<double>(total), detail);
      },
      hooks);
  bar.finish();
  warnOfMissingLayers(grades);
  std::size_t failed = 0;
  for (std::size_t k = 0; k < grades.size(); ++k) {
    const course::Grade& g = grades[k];
    const std::string who = course::terminalSafe(students[k]);
    if (!g.graderFailure.empty() || !problems[k].empty()) {
      ++failed;
      std::printf("%-24s NOT GRADED: %s\n", who.c_str(), course::terminalSafe(g.graderFailure.empty() ? problems[k] : g.graderFailure).c_str());
      continue;
    }
    std::printf("%-24s %6.2f / %.2f  %s\n", who.c_str(), g.score(), g.maxScore(), course::resultKind(g).c_str());
  }
  if (Status s = course::writeClassSummary(dir, def.assignment); !s) return fail(s.error());
  std::printf("wrote %s and %s\n", (dir / "gradebook.csv").c_str(), (dir / "summary.html").c_str());
  if (failed > 0) {
    return fail(std::to_string(failed) +
                " submissions were NOT GRADED: frob or this machine failed (above); their rows say so, with no score; grade them again");
  }
  return 0;
}

int replayCommand(const std::string& log, const std::string& secretFile, const std::string& submission) {
  Result<std::string> secret = readSecret(secretFile);
  if (!secret) return fail(secret.error(), 2);
  Result<course::Replay> r = course::replay(log, secret.value(), submission);
  if (!r) return fail(r.error());
  const course::RunGrade& run = r.value().run;
  std::printf("the log of %s (SHA-256 %s%s%s)\n", course::terminalSafe(r.value().submission).c_str(), r.value().submissionHash.c_str(),
              r.value().student.empty() ? "" : ", submitted by ", course::terminalSafe(r.value().student).c_str());
  std::printf("check %s, world %s, seed %llu: %s%s\ntrajectory %016llx\n", course::terminalSafe(r.value().check).c_str(),
              course::terminalSafe(run.world).c_str(), static_cast<unsigned long long>(run.seed),
              run.passed ? "passed" : "FAILED: ", course::terminalSafe(run.reason).c_str(), static_cast<unsigned long long>(run.trajectoryHash));
  return 0;
}

int mergeCommand(const GradeArgs& a) {
  if (a.gradebook.empty()) return fail("--merge needs --gradebook OUT.csv to write the merged gradebook to", 2);
  std::vector<fs::path> shards(a.merge.begin(), a.merge.end());
  Result<std::vector<std::string>> merged = course::mergeGradebooks(shards, a.gradebook);
  if (!merged) return fail(merged.error());
  std::printf("merged %zu submissions into %s\n", merged.value().size(), a.gradebook.c_str());
  return 0;
}

}  // namespace

int gradeCommand(const GradeArgs& a) {
  if (!a.replay.empty()) return replayCommand(a.replay, a.secret, a.submission.empty() ? a.assignment : a.submission);
  if (!a.merge.empty()) return mergeCommand(a);
  if (a.assignment.empty()) return fail("which assignment? frob grade ASSIGNMENT SUBMISSION (see frob grade --help)", 2);
  Result<fs::path> rubricFile = course::findRubric(a.assignment);
  if (!rubricFile) return fail(rubricFile.error(), 2);
  Result<course::Rubric> rubric = course::loadRubric(rubricFile.value());
  if (!rubric) return fail(rubric.error(), 2);
  if (a.practice > 0) {
    rubric = course::practiceRubric(rubric.value(), a.practice, a.practiceSeed);
    if (rubric.value().checks.empty()) return fail("this assignment's hidden checks draw no worlds to practise on", 2);
  }
  Result<std::string> secret = a.practice > 0 ? Result<std::string>(std::string()) : readSecret(a.secret);
  if (!secret) return fail(secret.error(), 2);
  if (rubric.value().needsSecret() && secret.value().empty() && !a.visibleOnly) {
    return fail(
        "this rubric draws hidden seeds from the instructor's secret: give --secret FILE or set FROB_GRADE_SECRET "
        "(or grade only the visible checks with --visible-only)",
        2);
  }
  if (!a.gradescopeZip.empty()) {
    // The hidden worlds are checked against the reference solution here, once, and shipped found.
    const course::GradeDef check{.rubric = rubric.value(), .secret = secret.value()};
    if (Result<course::KeptWorlds> fair = course::fairHiddenWorlds(check); !fair)
      return fail(fair.error(), course::isGraderFailure(fair.status()) ? 1 : 2);
    if (Status s = course::writeGradescopeZip({.rubric = rubricFile.value(),
                                               .assignment = fs::path(rubricFile.value()).parent_path().filename().string(),
                                               .secret = secret.value(),
                                               .reference = rubric.value().reference,
                                               .keptWorlds = course::keptWorldsFile(check)},
                                              a.gradescopeZip);
        !s) {
      return fail(s.error());
    }
    std::printf("wrote %s: upload it as the assignment's autograder on Gradescope\n", a.gradescopeZip.c_str());
    return 0;
  }
  if (a.submission.empty()) return fail("which submission? frob grade ASSIGNMENT SUBMISSION.cpp (or a folder of them)", 2);
  course::GradeDef def{.rubric = std::move(rubric.value()),
                       .assignment = fs::path(a.assignment).filename().string(),
                       .secret = secret.value(),
                       .visibleOnly = a.visibleOnly,
                       .logs = a.logs,
                       .student = a.student};
  if (def.assignment == "rubric.toml") def.assignment = fs::path(a.assignment).parent_path().filename().string();
  if (!a.submissionMetadata.empty() && def.rubric.latePerDay > 0) {  // read only where lateness costs points
    Result<double> late = course::submissionLateness(a.submissionMetadata);
    if (!late) return fail(late.error(), 2);
    def.daysLate = late.value();
  }
  if (!def.visibleOnly) {  // no student meets a hidden world the reference solution fails
    Result<course::KeptWorlds> fair = course::fairHiddenWorlds(def);
    if (!fair) return fail(fair.error(), course::isGraderFailure(fair.status()) ? 1 : 2);  // 1: the grader failed
    def.kept = fair.value();
    // Told to staff (stderr: the job's log on Gradescope and PrairieLearn), never to students.
    const course::Rubric& r = def.rubric;
    if (r.needsSecret() && !def.secret.empty() && def.kept->empty() && !r.reference.empty() && !fs::is_regular_file(r.reference)) {
      std::cerr << "frob: warning: the hidden checks run in the first worlds drawn from the secret, unchecked: the reference solution "
                << r.reference.string() << " is not here, and the controller cache holds no hidden worlds found fair for this rubric and secret "
                << "(copy them in: course/grading.md, \"On PrairieLearn\")\n";
    }
  }

  if (!a.out.empty()) {
    if (!fs::exists(fs::symlink_status(a.submission))) return fail("no submission '" + a.submission + "'", 2);
    // One student, found in the folder's gradebook by their submission or a file of it, or named
    // afresh; else a class (or this machine's shard of it).
    if (const std::optional<course::KnownStudent> known = course::knownStudent(a.out, a.submission)) {
      return gradeIntoFolder(a, def, {known->submission}, {known->student});
    }
    if (!fs::is_directory(a.submission)) {
      const fs::path one = course::submissionOf(a.submission);
      return gradeIntoFolder(a, def, {one}, course::studentNames({one}));
    }
    const std::vector<fs::path> all = course::submissionsIn(a.submission);
    if (all.empty())
      return fail("no submissions in '" + a.submission + "' (a .cpp file each, or a folder each holding one controller and its helpers)", 2);
    const std::vector<std::string> names = course::studentNames(all);
    int shard = 1, shards = 1;
    if (!a.shard.empty() && (std::sscanf(a.shard.c_str(), "%d/%d", &shard, &shards) != 2 || shards < 1 || shard < 1 || shard > shards)) {
      return fail("--shard must look like 2/8 (the second of eight), not '" + a.shard + "'", 2);
    }
    std::vector<fs::path> mine;
    std::vector<std::string> theirs;
    for (std::size_t k = static_cast<std::size_t>(shard - 1); k < all.size(); k += static_cast<std::size_t>(shards)) {
      mine.push_back(all[k]), theirs.push_back(names[k]);
    }
    return gradeIntoFolder(a, def, mine, theirs);
  }

  if (!fs::is_directory(a.submission)) {
    if (!fs::exists(a.submission)) return fail("no submission '" + a.submission + "'", 2);
    const course::Grade g = course::grade(def, course::submissionOf(a.submission));
    if (!g.graderFailure.empty()) return notGraded(g);
    warnOfMissingLayers({g});
    std::cout << course::scoreTable(g);
    if (a.practice > 0) std::cout << "\n" << course::practiceTable(g);
    if (Status s = writeOutputs(a, def, g); !s) return fail(s.error());
    return 0;
  }

  // A class: every submission of the folder, or this machine's shard of them.
  if (!a.results.empty() || !a.prairielearn.empty() || !a.junit.empty() || !a.report.empty()) {
    return fail(
        "--results, --prairielearn, --junit and --report are for one submission; a class gets --out DIR (a folder per student) or --gradebook", 2);
  }
  std::vector<fs::path> all = course::submissionsIn(a.submission);
  if (all.empty())
    return fail("no submissions in '" + a.submission + "' (a .cpp file each, or a folder each holding one controller and its helpers)", 2);
  int shard = 1, shards = 1;
  if (!a.shard.empty() && (std::sscanf(a.shard.c_str(), "%d/%d", &shard, &shards) != 2 || shards < 1 || shard < 1 || shard > shards)) {
    return fail("--shard must look like 2/8 (the second of eight), not '" + a.shard + "'", 2);
  }
  const std::vector<fs::path> mine = course::shardOf(all, shard, shards);
  ProgressBar bar(stderr, ::isatty(STDERR_FILENO) == 1, "frob: grading " + def.assignment);
  char detail[48];
  const std::vector<course::Grade> grades = course::gradeAll(def, mine, a.jobs, [&](std::size_t done, std::size_t total) {
    std::snprintf(detail, sizeof detail, "%zu / %zu submissions", done, total);
    bar.show(static_cast<double>(done) / static_cast<double>(total), detail);
  });
  bar.finish();
  warnOfMissingLayers(grades);
  std::size_t failed = 0;
  for (const course::Grade& g : grades) {
    if (!g.graderFailure.empty()) {
      ++failed;
      std::printf("%-40s NOT GRADED: %s\n", course::terminalSafe(g.submission).c_str(), course::terminalSafe(g.graderFailure).c_str());
      continue;
    }
    std::printf("%-40s %6.2f / %.2f%s\n", course::terminalSafe(g.submission).c_str(), g.score(), g.maxScore(),
                g.compileError.empty() ? "" : "  (did not compile)");
  }
  if (!a.gradebook.empty()) {
    if (Status s = course::writeGradebook(grades, a.gradebook); !s) return fail(s.error());
  }
  if (failed > 0) return fail(std::to_string(failed) + " submissions were NOT GRADED: frob or this machine failed (above); grade them again");
  return 0;
}

}  // namespace frob::app
