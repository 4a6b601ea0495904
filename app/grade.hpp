#pragma once
// frob grade's arguments and command (see grade.cpp).
#include <string>
#include <vector>

namespace frob::app {

struct GradeArgs {
  std::string assignment, submission;
  std::string results, prairielearn, junit, report, videos, logs, gradebook, secret, shard, replay, gradescopeZip;
  std::vector<std::string> merge;
  bool visibleOnly = false;
  int jobs = 1;
};

// Runs `frob grade`; 0 whenever it graded, whatever the score.
int gradeCommand(const GradeArgs& args);

}  // namespace frob::app
