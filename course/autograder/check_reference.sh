#!/usr/bin/env bash
# Grades an assignment's reference solution as a submission is graded, and fails, saying what it
# lost, unless it gets every point: the Gradescope autograder's setup.sh runs it, so that a build that
# grades otherwise (another compiler, C library, Box2D or linker) fails at setup, with the reason,
# and not on the first student.
#
# Usage: check_reference.sh ASSIGNMENT REFERENCE
#   ASSIGNMENT  an assignment's name (frob list), or its folder or rubric.toml
#   REFERENCE   its reference solution
# Environment: FROB, the frob to run (default: frob on PATH); FROB_GRADE_SECRET, the instructor's
# secret; FROB_CACHE_DIR, frob's controller cache.
# Exit status: 0 with full marks; 1 otherwise; 2 when it is called wrongly.
set -u
(($# == 2)) || {
  echo "usage: $(basename "$0") ASSIGNMENT REFERENCE" >&2
  exit 2
}
frob=${FROB:-frob}
scratch=$(mktemp -d) || exit 1
trap 'rm -rf "$scratch"' EXIT
if ! "$frob" grade "$1" "$2" --results "$scratch/results.json"; then
  echo "$(basename "$0"): frob could not grade the reference solution $2 (its message is above): this build cannot grade." >&2
  exit 1
fi
if grep -q '"status": "failed"' "$scratch/results.json"; then
  echo "$(basename "$0"): the reference solution $2 lost points here (the checks above): this build grades otherwise than the one the rubric was written with." >&2
  exit 1
fi
echo "$(basename "$0"): the reference solution $2 gets full marks: this build grades as it should."
