#!/usr/bin/env bash
# PrairieLearn's external grader, course/prairielearn/entrypoint.sh, run as PrairieLearn runs it in
# its container (course/grading.md, "On PrairieLearn"): each case makes a fake /grade tree (the
# go_to_goal question's tests/, the course's serverFilesCourse/frob/, data/data.json, the
# student's files, a space in every path), runs the entrypoint on it with the frob given, and
# checks the results.json it writes with check_results.py: PrairieLearn's shape, then the grade.
# The hidden check's worlds come from a test secret, the one tests/assignments uses, so its scores
# are tests/assignments/go_to_goal_test.cpp's.
# Usage: entrypoint_test.sh FROB SOURCE_DIR PYTHON CASE...   (each CASE a function below)
set -euo pipefail
frob=$1 source=$2 python=$3
shift 3
here=$(cd "$(dirname "$0")" && pwd)
entrypoint=$source/course/prairielearn/entrypoint.sh
assignment=$source/assignments/go_to_goal
wrong=$source/tests/assignments/go_to_goal

work=$(mktemp -d "${TMPDIR:-/tmp}/frob-prairielearn-test-XXXXXX")
trap 'rm -rf "$work"' EXIT
chmod 755 "$work"                  # run as root, frob compiles and runs controllers as users of their own
export FROB_CACHE_DIR="$work/cache"  # shared by the cases: the hidden worlds are checked once
unset FROB_GRADE_SECRET

fail() {
  echo "FAILED: $case: $*" >&2
  exit 1
}

# question: a fresh fake /grade tree at $grade for the go_to_goal question, with the secret in the
# course's serverFilesCourse/frob/, and what PrairieLearn writes to data/data.json (unread).
question() {
  grade="$work/$case/grade root"
  mkdir -p "$grade/tests" "$grade/student" "$grade/data" "$grade/serverFilesCourse/frob"
  echo go_to_goal > "$grade/tests/assignment.txt"
  echo ci-test-secret > "$grade/serverFilesCourse/frob/secret.txt"
  cat > "$grade/data/data.json" << 'JSON'
{"params": {}, "correct_answers": {}, "submitted_answers": {"_files": []}, "format_errors": {}, "partial_scores": {}, "score": 0, "feedback": {}, "variant_seed": 1, "options": {}, "raw_submitted_answers": {}, "gradable": true}
JSON
}

# grade CHECK...: runs the entrypoint on $grade, then checks its results.json against CHECK... (check_results.py's options).
grade() {
  local log="$work/$case/entrypoint.log" start=$SECONDS status=0
  FROB_GRADE_ROOT="$grade" FROB="$frob" bash "$entrypoint" > "$log" 2>&1 || status=$?
  if ((status != 0)); then cat "$log" >&2; fail "the entrypoint exited with status $status"; fi
  [ -f "$grade/results/results.json" ] || { cat "$log" >&2; fail "no $grade/results/results.json"; }
  "$python" "$here/check_results.py" "$grade/results/results.json" "$@" || { cat "$log" >&2; fail "results.json is not as expected"; }
  [ -z "$(find "$grade/results" -name '*.json.*')" ] || fail "a partial results file was left behind"
  echo "$case: passed ($((SECONDS - start)) s)"
}

visible=("--test" "visits the waypoints in order=3/3" "--test" "within the time limit=2/2"
  "--test" "goes round the sofa without touching anything=2/2")

# The reference solution: full marks, the hidden check included.
solution() {
  question
  cp "$assignment/solution.cpp" "$grade/student/go to goal.cpp"
  grade --gradable true --score 1 "${visible[@]}" --test "Hidden checks=3/3"
}

# A route worked out by hand round the lounge: the visible checks pass, and of the two hidden lounges
# drawn for this file it gets round one (a blind route earns at most a third of the hidden points over
# many draws: tests/assignments/blind_adversary_test.cpp).
# The question's own secret (tests/secret.txt) stands before the course's (here an empty line, which
# frob would refuse).
wrong_submission() {
  question
  echo ci-test-secret > "$grade/tests/secret.txt"
  echo > "$grade/serverFilesCourse/frob/secret.txt"
  cp "$wrong/hard_coded_route.cpp" "$grade/student/my controller.cpp"
  grade --gradable true --score 0.85 "${visible[@]}" --test "Hidden checks=1.5/3" --message-has "not shown"
}

# A controller that does not compile: not gradable (no attempt used up), the compiler's message shown.
# The assignment here is a rubric folder the question ships in its tests/, without the reference
# solution, as course/grading.md advises: its hidden worlds are those the solution case found fair.
compile_error() {
  question
  cp -r "$assignment" "$grade/tests/go to goal"
  rm "$grade/tests/go to goal/solution.cpp"
  echo "go to goal" > "$grade/tests/assignment.txt"
  { cat "$assignment/starter.cpp" && echo "int broken = ;"; } > "$grade/student/controller.cpp"
  grade --gradable false --output-has "expected expression" --format-errors-has "expected expression" --no-tests
}

# No .cpp file has a FROB_CONTROLLER(...) line: not gradable, and the student is told why.
no_controller() {
  question
  printf 'double half(double x) { return x / 2; }\n' > "$grade/student/helpers.cpp"
  sed 's/^FROB_CONTROLLER/\/\/ FROB_CONTROLLER/' "$assignment/starter.cpp" > "$grade/student/controller.cpp"
  local why="None of the submitted .cpp files has a FROB_CONTROLLER(...) line: submit the file that holds your controller."
  grade --gradable false --message "$why" --format-errors-has "$why" --no-tests
}

# Two files with a FROB_CONTROLLER(...) line: which one is the controller? The student is told.
two_controllers() {
  question
  mkdir "$grade/student/old version"
  cp "$assignment/starter.cpp" "$grade/student/controller.cpp"
  cp "$assignment/starter.cpp" "$grade/student/old version/controller.cpp"
  local why="2 of the submitted .cpp files have a FROB_CONTROLLER(...) line: submit one controller."
  grade --gradable false --message "$why" --format-errors-has "$why" --no-tests
}

# Nothing submitted.
no_files() {
  question
  grade --gradable false --message "No .cpp file was submitted: submit your controller file." --no-tests
}

# The solution split in two: a function moved from the controller to helpers.cpp, declared in
# helpers.hpp. The other .cpp files beside the controller compile with it: full marks.
helper_beside_controller() {
  question
  local student="$grade/student"
  awk -v helpers="$student/helpers.cpp" '
    /^double distanceToLine\(/ { moving = 1; print "#include \"helpers.hpp\"" }
    moving { print > helpers; if ($0 ~ /^}/) moving = 0; next }
    { print }' "$assignment/solution.cpp" > "$student/go to goal.cpp.body"
  grep -q '^double distanceToLine(' "$student/helpers.cpp" 2> /dev/null || fail "the solution has no distanceToLine to move"
  printf '#pragma once\n#include <frob/frob.hpp>\n\ndouble distanceToLine(const frob::Point2& p, const frob::Point2& a, const frob::Point2& b);\n' \
    > "$student/helpers.hpp"
  { printf '#include "helpers.hpp"\n\nusing namespace frob;\n\n' && cat "$student/helpers.cpp"; } > "$student/helpers.cpp.new"
  mv "$student/helpers.cpp.new" "$student/helpers.cpp"
  mv "$student/go to goal.cpp.body" "$student/go to goal.cpp"
  grade --gradable true --score 1 "${visible[@]}" --test "Hidden checks=3/3"
}

# The question ships its rubric folder without the reference solution and with no copy of the hidden
# worlds: grading goes on in the worlds first drawn, and the job's log says so to staff.
no_hidden_worlds() {
  question
  mkdir -p "$grade/tests/go_to_goal"
  cp -r "$assignment/rubric.toml" "$assignment/worlds" "$assignment/starter.cpp" "$grade/tests/go_to_goal/"
  echo go_to_goal > "$grade/tests/assignment.txt"
  cp "$assignment/solution.cpp" "$grade/student/controller.cpp"
  FROB_CACHE_DIR="$work/$case/cache" grade --gradable true
  grep -q "frob: warning: the hidden checks run in the first worlds drawn from the secret, unchecked" "$work/$case/entrypoint.log" ||
    { cat "$work/$case/entrypoint.log" >&2; fail "no warning that the hidden worlds are unchecked"; }
}

(($# > 0)) || { echo "usage: $0 FROB SOURCE_DIR PYTHON CASE..." >&2; exit 2; }
for case in "$@"; do "$case"; done
