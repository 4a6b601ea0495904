#!/usr/bin/env bash
# PrairieLearn's external grader: grades the controller in /grade/student with frob and writes
# /grade/results/results.json (course/grading.md, "On PrairieLearn"). What the question gives it:
#   /grade/tests/assignment.txt   its first line: an assignment's name (frob list), or the path of a
#                                 rubric folder or rubric.toml in the question's tests/ folder
#   /grade/tests/secret.txt       the instructor's secret (first line); where the question has none,
#                                 /grade/serverFilesCourse/frob/secret.txt, else $FROB_GRADE_SECRET
#   .../frob/hidden-worlds/*.txt  the hidden worlds found fair for the secret (frob's controller
#                                 cache), from serverFilesCourse/frob/ and from tests/
# FROB_GRADE_ROOT (default /grade), FROB (default frob on PATH) and FROB_CACHE_DIR (default
# $TMPDIR/frob-cache) let a test run it on a fake /grade tree.
set -u
root=${FROB_GRADE_ROOT:-/grade}
here=$(cd -- "$(dirname -- "$0")" && pwd)
grade_submission=$here/grade_submission.sh                                          # in the image
[ -f "$grade_submission" ] || grade_submission=$here/../autograder/grade_submission.sh  # in the source tree
tests=$root/tests course=$root/serverFilesCourse/frob

fail() {  # the question is set up wrongly: PrairieLearn reports the grading as failed, with this in its log
  echo "frob entrypoint: $*" >&2
  exit 1
}

[ -f "$tests/assignment.txt" ] || fail "$tests/assignment.txt is missing: the question's tests/assignment.txt names the assignment"
IFS= read -r assignment < "$tests/assignment.txt" || [ -n "$assignment" ] || fail "$tests/assignment.txt is empty"
assignment=${assignment%$'\r'}
[ -n "$assignment" ] || fail "$tests/assignment.txt: its first line is empty"
if [ -e "$tests/$assignment" ]; then assignment=$tests/$assignment; fi  # shipped with the question; else a name

for secret in "$tests/secret.txt" "$course/secret.txt"; do
  if [ -f "$secret" ]; then
    FROB_GRADE_SECRET=$(head -n 1 -- "$secret")
    export FROB_GRADE_SECRET
    break
  fi
done

export FROB_CACHE_DIR=${FROB_CACHE_DIR:-${TMPDIR:-/tmp}/frob-cache}
for kept in "$course/hidden-worlds" "$tests/hidden-worlds"; do
  if [ -d "$kept" ]; then
    mkdir -p "$FROB_CACHE_DIR/hidden-worlds" && cp -- "$kept"/*.txt "$FROB_CACHE_DIR/hidden-worlds/" 2> /dev/null
  fi
done

mkdir -p "$root/student" "$root/results" || fail "cannot make $root/results"
exec bash "$grade_submission" prairielearn "$assignment" "$root/student" "$root/results/results.json"
