#!/usr/bin/env bash
# Gradescope, from nothing: the go_to_goal autograder zip (made by the frob built here, with the
# test secret tests/assignments uses) is unpacked into a fresh Debian root of SUITE (bookworm,
# Debian 12, or trixie, Debian 13: mmdebstrap --variant=minbase, from the Debian archive) as
# Gradescope lays out /autograder; setup.sh runs there as root, as on Gradescope's base image,
# builds frob with the newest clang the suite has, and proves the build: the reference solution gets
# full marks (it is then gone from the root). A reference run there gives the trajectory hash it
# gives here. Then run_autograder grades, each in a fresh instance of that image (an overlay on it):
#   the reference solution               full marks, 10 / 10
#   hard_coded_route.cpp (typical wrong) the grade the host's frob gives it: its hidden rooms are its
#                                        own, drawn from the secret and its hash, the same here
#   a controller that does not compile   0, and the compiler's message
#   the solution in two .cpp and a .hpp  full marks
# Each results.json is checked against the fields Gradescope documents (check_results.py). The time
# mmdebstrap, setup.sh and each grade take is printed.
#
# Like a container, and unlike a chroot, the root is entered with pivot_root in mount and PID
# namespaces of its own (the kernel refuses user namespaces, which frob's sandbox makes, inside a
# chroot), with /proc, the host's /dev and the host's resolv.conf; the namespaces die with their
# processes, so no mount is ever left on the host, even if the test is killed.
#
# What it cannot cover: Gradescope's own image (Ubuntu 22.04 by default: its package names and
# versions, what its base image holds beyond a minimal install), its harness (how it unpacks the
# zip, its environment, its limits: 768 MB of memory, half a CPU), and Docker's seccomp profile and
# capabilities, under which frob's sandbox may apply fewer layers than here.
#
# Needs root, mmdebstrap (tests/gradescope/packages.txt), overlayfs and the Debian archive
# (FROB_DEBIAN_MIRROR, default http://deb.debian.org/debian), else exits 77 (skipped), saying why.
# Usage: fresh_root_test.sh FROB SOURCE_DIR PYTHON DEADLINE_SECONDS [SUITE]
set -euo pipefail
frob=$1 source=$2 python=$3 deadline=$((SECONDS + $4)) suite=${5:-bookworm}
here=$(cd "$(dirname "$0")" && pwd)
mirror=${FROB_DEBIAN_MIRROR:-http://deb.debian.org/debian}
security=${FROB_DEBIAN_SECURITY_MIRROR:-http://deb.debian.org/debian-security}
assignment=$source/assignments/go_to_goal
wrong=$source/tests/assignments/go_to_goal
secret=ci-test-secret  # tests/assignments/grade_assignment.hpp's, whose hidden worlds go_to_goal_test.cpp's scores are for

fail() { echo "FAILED: $*" >&2; exit 1; }
# skip WHY: the test cannot run here (CMake's SKIP_RETURN_CODE).
skip() { echo "SKIPPED: $*" >&2; exit 77; }

[ "$(id -u)" = 0 ] || skip "not root: mmdebstrap, mounts and setup.sh need root"
for program in mmdebstrap unshare pivot_root; do
  command -v "$program" > /dev/null || skip "no $program: apt-get install --no-install-recommends mmdebstrap (tests/gradescope/packages.txt)"
done
unshare --mount --propagation private true 2> /dev/null || skip "cannot make a mount namespace here (unshare --mount)"
grep -qw overlay /proc/filesystems || modprobe overlay 2> /dev/null || grep -qw overlay /proc/filesystems ||
  skip "no overlayfs in this kernel: each grade runs on an overlay of the image"

# interruptible LIMIT CMD...: CMD in the background, stopped after LIMIT seconds or the test's
# deadline, whichever comes first; a signal to the test stops it at once, through the EXIT trap.
# A PID namespace's first process ignores SIGTERM: timeout's SIGKILL 10 s later ends unshare, and
# with it (--kill-child) every process of the namespace.
child=
interruptible() {
  local limit=$1 left=$((deadline - SECONDS)) status=0
  shift
  ((left < limit)) && limit=$left
  ((limit > 0)) || fail "the test's deadline passed before: $*"
  timeout --kill-after=10 "$limit" "$@" &
  child=$!
  wait "$child" || status=$?
  child=
  ((status != 124 && status != 137)) || echo "stopped after $limit s, its limit or the test's deadline" >&2
  return "$status"
}
stop_child() { [ -z "$child" ] || { kill "$child" 2> /dev/null; wait "$child" 2> /dev/null; } || true; }

# $work, removed at the end, even on a signal (not SIGKILL: the deadline comes before CTest's
# TIMEOUT). Only processes of the namespaces ever mounted anything below it; if a mount is seen there
# anyway, nothing is removed, and the test says so.
work=$(mktemp -d "${TMPDIR:-/tmp}/frob-gradescope-test-XXXXXX")
cleanup() {
  stop_child
  if awk -v w="$work/" 'index($5 "/", w) == 1 { found = 1 } END { exit !found }' /proc/self/mountinfo; then
    echo "$work: something is still mounted below it; not removed" >&2
    return
  fi
  rm -rf --one-file-system "$work"
}
trap 'status=$?; trap - EXIT; cleanup; exit $status' EXIT
trap 'exit 143' TERM INT HUP  # through the EXIT trap
chmod 755 "$work"
export FROB_CACHE_DIR=$work/host-cache  # the host's frob's compiled controllers
timeout 60 /usr/lib/apt/apt-helper download-file "$mirror/dists/$suite/InRelease" "$work/InRelease" > /dev/null 2>&1 ||
  skip "no network: cannot reach the Debian archive at $mirror"
root=$work/root
needed_gb=4  # the root is some 1.7 GB once setup.sh has run
free_gb=$(($(df --output=avail -k "$work" | tail -n 1) / 1024 / 1024))
((free_gb >= needed_gb)) || skip "$free_gb GB free in $work, $needed_gb GB needed (TMPDIR elsewhere?)"

# What runs inside the namespaces (enter ROOT LAYER COMMAND...): the root (or, when LAYER is given,
# an overlay of LAYER/upper on it) made a mount point with /proc, /dev and resolv.conf, pivoted into,
# the host's tree unmounted; COMMAND runs there with a container's environment.
enter() {
  set -euo pipefail
  local root=$1 layer=$2
  shift 2
  if [ -n "$layer" ]; then
    mkdir -p "$layer/upper" "$layer/work" "$layer/merged"
    mount -t overlay overlay -o "lowerdir=$root,upperdir=$layer/upper,workdir=$layer/work" "$layer/merged"
    root=$layer/merged
  else
    mount --bind "$root" "$root"
  fi
  mount -t proc proc "$root/proc"
  mount --rbind /dev "$root/dev"
  [ ! -f "$root/etc/resolv.conf" ] || mount --bind /etc/resolv.conf "$root/etc/resolv.conf"
  cd "$root"
  pivot_root . mnt
  cd /
  umount -l /mnt
  exec env -i PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin HOME=/root "$@"
}
# in_root LIMIT LAYER COMMAND...: COMMAND as root in the image (LAYER empty) or in a fresh instance of it.
in_root() {
  local limit=$1
  shift
  interruptible "$limit" unshare --mount --pid --fork --kill-child --propagation private \
    bash -c "$(declare -f enter); enter \"\$@\"" enter "$root" "$@"
}

# The zip, as instructors make it.
echo "$secret" > "$work/secret.txt"
start=$SECONDS
interruptible 300 env -C "$work" "$frob" grade "$assignment" --gradescope-zip autograder.zip --secret secret.txt > "$work/zip.log" 2>&1 ||
  { cat "$work/zip.log" >&2; fail "frob grade --gradescope-zip"; }
echo "made autograder.zip in $((SECONDS - start)) s"

# The fresh Debian root, in namespaces of its own (mmdebstrap's own mounts die with them).
start=$SECONDS
interruptible 900 unshare --mount --pid --fork --kill-child --mount-proc --propagation private \
  mmdebstrap --mode=root --variant=minbase "$suite" "$root" "deb $mirror $suite main" "deb $mirror $suite-updates main" \
  "deb $security $suite-security main" > "$work/mmdebstrap.log" 2>&1 || { tail -n 40 "$work/mmdebstrap.log" >&2; fail "mmdebstrap"; }
mmdebstrap_seconds=$((SECONDS - start))
echo "mmdebstrap: a minimal $suite root in $mmdebstrap_seconds s ($(du -sm "$root" | cut -f1) MB)"

# Gradescope's layout: the zip unpacked into /autograder/source (Unix permissions kept), its
# run_autograder and setup.sh copied to /autograder.
mkdir -p "$root/autograder/source"
"$python" - "$work/autograder.zip" "$root/autograder/source" << 'PY' || fail "unpacking autograder.zip"
import os, sys, zipfile
with zipfile.ZipFile(sys.argv[1]) as z:
    for info in z.infolist():
        path = z.extract(info, sys.argv[2])
        mode = (info.external_attr >> 16) & 0o7777
        if mode and not info.is_dir():
            os.chmod(path, mode)
PY
for script in setup.sh run_autograder; do
  [ -x "$root/autograder/source/$script" ] || fail "the zip has no executable $script"
  cp -p "$root/autograder/source/$script" "$root/autograder/$script"
done

# setup.sh, as root on the fresh root: installs a clang and frob's libraries, builds frob, grades the reference.
start=$SECONDS
in_root 1800 "" bash -c 'cd /autograder/source && exec bash ./setup.sh' > "$work/setup.log" 2>&1 ||
  { tail -n 60 "$work/setup.log" >&2; fail "setup.sh (its last lines above)"; }
[ -x "$root/autograder/source/build/app/frob" ] || { tail -n 60 "$work/setup.log" >&2; fail "setup.sh built no frob"; }
setup_seconds=$((SECONDS - start))
grep -q "check_reference.sh: the reference solution reference/solution.cpp gets full marks" "$work/setup.log" ||
  { tail -n 60 "$work/setup.log" >&2; fail "setup.sh did not prove the build with the reference solution"; }
[ ! -e "$root/autograder/source/reference" ] || fail "setup.sh left the reference solution where submissions run"
echo "setup.sh: installed the packages, built frob with $(grep -o 'building frob with clang-[0-9]*' "$work/setup.log" | cut -d' ' -f4) and proved it on the reference in $setup_seconds s (the root is now $(du -sm "$root" | cut -f1) MB)"

# The controllers' sandbox in a fresh instance of the image: every layer the host's frob applies, and
# the reference's whole run in the lounge the same, to the last bit of its trajectory's hash
# (frob grade would grade without one, saying so only on stderr). In a chroot, the kernel refuses frob the
# user namespace it makes (unshare: EPERM).
# Each run takes whichever sandbox uid is free (61000 and up), so the number itself may differ.
sandbox_layers() { sed -n '/"sandbox": \[/,/^ \]/p' "$1" | sed 's/"uid [0-9]*"/"uid N"/'; }
interruptible 300 env -C "$work" "$frob" run "$assignment/solution.cpp" --world "$assignment/worlds/lounge.toml" --json \
  > "$work/host-run.json" 2> "$work/host-run.log" || { cat "$work/host-run.log" >&2; fail "frob run on the host"; }
mkdir -p "$work/grades/sandbox/upper/autograder/submission"
cp "$assignment/solution.cpp" "$work/grades/sandbox/upper/autograder/submission/go_to_goal.cpp"
in_root 300 "$work/grades/sandbox" /autograder/source/build/app/frob run /autograder/submission/go_to_goal.cpp \
  --world /autograder/source/assignments/go_to_goal/worlds/lounge.toml --json > "$work/root-run.json" 2> "$work/root-run.log" ||
  { cat "$work/root-run.log" >&2; fail "frob run in the image"; }
grep -q '"applied": true' "$work/host-run.json" || { cat "$work/host-run.json" >&2; fail "no sandbox layers in frob run --json"; }
diff -u <(sandbox_layers "$work/host-run.json") <(sandbox_layers "$work/root-run.json") >&2 ||
  fail "the controllers' sandbox in the image differs from the host's (diff above)"
echo "the controllers' sandbox in the image: $(grep -c '"applied": true' "$work/root-run.json") layers applied, as on the host"
trajectory() { grep -o '"trajectory_hash": "[^"]*"' "$1"; }
[ -n "$(trajectory "$work/host-run.json")" ] || { cat "$work/host-run.json" >&2; fail "no trajectory hash in frob run --json"; }
[ "$(trajectory "$work/host-run.json")" = "$(trajectory "$work/root-run.json")" ] ||
  fail "the reference's run in the image is not the host's: $(trajectory "$work/root-run.json"), here $(trajectory "$work/host-run.json")"
echo "the reference's run in the lounge: the same trajectory in the image as here, $(trajectory "$work/root-run.json")"

# grade CASE CHECK...: CASE's submission ($work/CASE/, made by the caller) graded by run_autograder in
# a fresh instance of the image, as Gradescope grades it (from /autograder, as root, its output
# kept as results/stdout); its results.json checked with check_results.py's CHECK options.
timings=
grade() {
  local case=$1 layer=$work/grades/$1 start=$SECONDS status=0
  shift
  mkdir -p "$layer/upper/autograder/results"
  cp -r "$work/$case" "$layer/upper/autograder/submission"
  in_root 600 "$layer" bash -c 'cd /autograder && ./run_autograder > results/stdout 2>&1' || status=$?
  local results=$layer/upper/autograder/results
  ((status == 0)) || { cat "$results/stdout" >&2; fail "$case: run_autograder exited with status $status"; }
  [ -f "$results/results.json" ] || { cat "$results/stdout" >&2; fail "$case: no results.json"; }
  "$python" "$here/check_results.py" "$results/results.json" "$@" || { cat "$results/stdout" >&2; fail "$case: results.json is not as expected"; }
  timings+="$case $((SECONDS - start)) s, "
  echo "$case: graded as expected in $((SECONDS - start)) s"
}
visible=(--test "visits the waypoints in order=3/3" --test "within the time limit=2/2"
  --test "goes round the sofa without touching anything=2/2" --hidden "other rooms, other furniture")

# The reference solution: full marks, the hidden check included.
mkdir "$work/solution"
cp "$assignment/solution.cpp" "$work/solution/go_to_goal.cpp"
grade solution --score 10 "${visible[@]}" --test "other rooms, other furniture=3/3"

# A typical wrong submission, a route worked out by hand round the lounge: the score the host's frob
# gives it, check by check. Its two hidden lounges are drawn for it from the pool (a blind route gets
# round about a quarter of them), so the hidden check is not what go_to_goal_test.cpp states.
mkdir "$work/wrong_submission"
cp "$wrong/hard_coded_route.cpp" "$work/wrong_submission/controller.cpp"
interruptible 600 env -C "$work" "$frob" grade "$assignment" wrong_submission/controller.cpp \
  --secret secret.txt --results host.json > "$work/host.log" 2>&1 || { cat "$work/host.log" >&2; fail "grading on the host"; }
host_score=$("$python" -c 'import json, sys; print(json.load(open(sys.argv[1]))["score"])' "$work/host.json")
host_hidden=$("$python" -c 'import json, sys; print(*(t["score"] for t in json.load(open(sys.argv[1]))["tests"] if t["name"] == sys.argv[2]))' \
  "$work/host.json" "other rooms, other furniture")
grade wrong_submission --score "$host_score" "${visible[@]}" --test "other rooms, other furniture=$host_hidden/3" --scores-of "$work/host.json"

# A controller that does not compile: 0, and the compiler's message, naming the line.
mkdir "$work/compile_error"
{ cat "$assignment/starter.cpp" && echo "int broken = ;"; } > "$work/compile_error/controller.cpp"
line=$(wc -l < "$work/compile_error/controller.cpp")
grade compile_error --score 0 --output-has "controller.cpp:$line:14: error: expected expression" \
  --test "visits the waypoints in order=0/3" --test "within the time limit=0/2" \
  --test "goes round the sofa without touching anything=0/2" --test "other rooms, other furniture=0/3" --hidden "other rooms, other furniture"

# The solution split in two: distanceToLine moved to helpers.cpp, declared in helpers.hpp; the
# other .cpp files beside the controller compile with it: full marks.
mkdir "$work/multi_file"
awk -v helpers="$work/multi_file/helpers.body" '
  /^double distanceToLine\(/ { moving = 1; print "#include \"helpers.hpp\"" }
  moving { print > helpers; if ($0 ~ /^}/) moving = 0; next }
  { print }' "$assignment/solution.cpp" > "$work/multi_file/go_to_goal.cpp"
grep -q '^double distanceToLine(' "$work/multi_file/helpers.body" 2> /dev/null || fail "the solution has no distanceToLine to move"
printf '#pragma once\n#include <frob/frob.hpp>\n\ndouble distanceToLine(const frob::Point2& p, const frob::Point2& a, const frob::Point2& b);\n' \
  > "$work/multi_file/helpers.hpp"
{ printf '#include "helpers.hpp"\n\nusing namespace frob;\n\n' && cat "$work/multi_file/helpers.body"; } > "$work/multi_file/helpers.cpp"
rm "$work/multi_file/helpers.body"
grade multi_file --score 10 "${visible[@]}" --test "other rooms, other furniture=3/3"

echo "timings: mmdebstrap $mmdebstrap_seconds s, setup.sh $setup_seconds s; run_autograder: ${timings%, }"
