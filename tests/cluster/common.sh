# Shared by the cluster tests: a class of 20 graded on one machine, the gradebook to compare with.
set -euo pipefail

fail() { echo "FAILED: $*" >&2; exit 1; }
# skip WHY: the test cannot run here (CMake's SKIP_RETURN_CODE).
skip() { echo "SKIPPED: $*" >&2; exit 77; }

# make_work: $work, a new folder removed at the end, after the test's cleanup function if it has one.
make_work() {
  work=$(mktemp -d "${TMPDIR:-/tmp}/frob-cluster-test-XXXXXX")
  trap 'status=$?; trap - EXIT; stop_child; if declare -F cleanup > /dev/null; then cleanup; fi; rm -rf "$work"; exit $status' EXIT
  trap 'exit 143' TERM INT HUP  # through the EXIT trap
  chmod 755 "$work"  # run as root, the controller host runs as a user of its own
  # Compiled controllers, shared by every machine as on a cluster's filesystem: each file compiles once.
  export FROB_CACHE_DIR="$work/cache"
}

# interruptible CMD...: runs CMD in the background and waits for it, so that a signal to the test
# (^C, a timeout) stops it at once, through the EXIT trap; CMD's exit status.
child=
interruptible() {
  local status=0
  "$@" &
  child=$!
  wait "$child" || status=$?
  child=
  return "$status"
}
stop_child() { [ -z "$child" ] || { kill "$child" 2> /dev/null; wait "$child" 2> /dev/null; } || true; }

# make_class SOURCE_DIR: $work/class, 20 submissions of 6 distinct files (one does not compile):
# 16 folders holding a controller.cpp, then 4 .cpp files; and $work/secret.txt. The compile cache
# names a module after its file: identical files compile once if of the same name (here 8 compiles).
make_class() {
  local source=$1 i
  local sources=("$source/assignments/go_to_goal/solution.cpp" "$source/assignments/go_to_goal/starter.cpp"
                 "$source/tests/assignments/go_to_goal/too_slow.cpp" "$source/tests/assignments/go_to_goal/wrong_order.cpp"
                 "$source/tests/assignments/go_to_goal/copied_example.cpp" "$work/broken.cpp")
  printf '#include <frob/frob.hpp>\nthis does not compile;\n' > "$work/broken.cpp"
  for i in $(seq -w 1 16); do mkdir -p "$work/class/student$i" && cp "${sources[$((10#$i % 6))]}" "$work/class/student$i/controller.cpp"; done
  for i in 17 18 19 20; do cp "${sources[$((i % 6))]}" "$work/class/student$i.cpp"; done
  echo "the instructor's secret of the cluster tests" > "$work/secret.txt"
}

# grade_one_machine: the class graded here, from $work, into $work/one-machine.csv (and the cache).
grade_one_machine() {
  local start=$SECONDS
  interruptible timeout 300 env -C "$work" "$frob" grade go_to_goal class/ --jobs 2 --gradebook one-machine.csv --visible-only \
    --secret secret.txt > "$work/one-machine.log" 2>&1 || { cat "$work/one-machine.log" >&2; fail "grading the class on one machine"; }
  [ "$(wc -l < "$work/one-machine.csv")" = 21 ] || { cat "$work/one-machine.csv" >&2; fail "the one-machine gradebook has not 20 submissions"; }
  echo "graded the class on one machine in $((SECONDS - start)) s (compiles included)"
}

# check_shards PREFIX N: PREFIX-1.csv .. PREFIX-N.csv, 20 / N submissions each, merged into
# PREFIX.csv, which must equal the one-machine gradebook. The gradebook has no timing column
# (submission, score, max_score, a score per check): the files are compared whole.
check_shards() {
  local prefix=$1 n=$2 i rows
  for i in $(seq "$n"); do
    [ -f "$prefix-$i.csv" ] || fail "no gradebook $prefix-$i.csv from shard $i/$n"
    rows=$(($(wc -l < "$prefix-$i.csv") - 1))
    [ "$rows" = $((20 / n)) ] || { cat "$prefix-$i.csv" >&2; fail "shard $i/$n graded $rows submissions, not $((20 / n))"; }
  done
  [ "$(ls "$prefix"-*.csv | wc -l)" = "$n" ] || fail "gradebooks other than the $n shards': $(ls "$prefix"-*.csv)"
  "$frob" grade --merge "$prefix"-*.csv --gradebook "$prefix.csv" > "$prefix-merge.log" 2>&1 || { cat "$prefix-merge.log" >&2; fail "merging the shards"; }
  diff -u "$work/one-machine.csv" "$prefix.csv" >&2 || fail "the merged gradebook $prefix.csv differs from the one-machine gradebook (diff above)"
}
