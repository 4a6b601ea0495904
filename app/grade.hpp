#pragma once
// frob grade's arguments and command (see grade.cpp).
#include <cstdint>
#include <string>
#include <vector>

namespace frob::app {

struct GradeArgs {
  std::string assignment, submission;
  std::string results, prairielearn, junit, report, videos, logs, gradebook, secret, shard, replay, gradescopeZip, student;
  std::string out;                 // the class folder: a gradebook row and a folder per student, and the class's summary
  std::string submissionMetadata;  // Gradescope's submission_metadata.json: how late it came
  std::vector<std::string> merge;
  bool visibleOnly = false;
  bool changed = false;  // with --out: grade again only those whose result the rubric as it now is changes
  int jobs = 1;
  int practice = 0;                // grade the hidden checks' criteria in this many worlds of their families instead
  std::uint64_t practiceSeed = 1;  // the student's own seed for them
};

// Runs `frob grade`; 0 whenever it graded, whatever the score.
int gradeCommand(const GradeArgs& args);

}  // namespace frob::app
