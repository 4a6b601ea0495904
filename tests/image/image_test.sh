#!/usr/bin/env bash
# The one image (labels `image` and `deployment`): course/image/build.sh builds it from this build
# tree, then, in containers of it under podman, with no network:
#   frob run of the demo            the trace (every pose, wheel and sonar of every step) is the same
#                                   file, byte for byte, as the one the frob built here writes
#   frob grade of a reference       the same score and the same result for every check, hidden
#                                   checks included (the assignment folder is mounted, with its reference)
#   a hostile controller            contained: it fails its own run with the sandbox's reason
#   clangd in a `frob init` project sees frob's headers (the dev container's editor)
# and prints which of the sandbox's layers apply in the container (podman's default seccomp profile).
# Needs root, podman (with runc), mmdebstrap and the Debian archive, else exits 77 (skipped), saying why.
# Usage: image_test.sh FROB SOURCE_DIR BUILD_DIR CPACK HOSTILE_SOURCE
set -euo pipefail
frob=$1 source=$2 build=$3 hostile=$5
export CPACK=$4
export CONTAINERS_CONF=$source/course/image/containers.conf

fail() { echo "FAILED: $*" >&2; exit 1; }
skip() { echo "SKIPPED: $*" >&2; exit 77; }
[ "$(id -u)" = 0 ] || skip "not root: mmdebstrap and podman's image store need root here"
for program in podman runc mmdebstrap; do
  command -v "$program" > /dev/null || skip "no $program: apt-get install --no-install-recommends podman runc mmdebstrap (tests/image/packages.txt)"
done

tag=frob-sandbox:image-test
work=$(mktemp -d "${TMPDIR:-/tmp}/frob-image-test-XXXXXX")
chmod 755 "$work"
cleanup() {
  podman rmi --force "$tag" frob-sandbox-base:bookworm > /dev/null 2>&1 || true
  rm -rf "$work"
}
trap cleanup EXIT
export FROB_CACHE_DIR=$work/cache

start=$SECONDS
bash "$source/course/image/build.sh" "$build" "$tag" || fail "course/image/build.sh"
echo "the image took $((SECONDS - start)) s to build"

# in_image CMD...: CMD in a fresh container, the test's folder at /work, the assignments read-only;
# its seccomp profile podman's default, or the one `security` names.
security=()
in_image() {
  podman run --rm --network none "${security[@]}" --volume "$work:/work" --volume "$source/assignments:/assignments:ro" \
    --volume "$hostile:/hostile:ro" --env FROB_CACHE_DIR=/work/image-cache "$tag" "$@"
}

# The demo's trajectory, outside and inside: its hash (frob run --json) and its trace, byte for byte.
"$frob" run bug --seconds 30 --json --trace "$work/outside.csv" > "$work/outside.json" 2> "$work/outside.log" || { cat "$work/outside.log"; fail "frob run here"; }
in_image frob run bug --seconds 30 --json --trace /work/inside.csv > "$work/inside.json" 2> "$work/inside.log" || { cat "$work/inside.log"; fail "frob run in the image"; }
field() { python3 -c 'import json,sys; d=json.load(open(sys.argv[1])); print(eval(sys.argv[2], {}, {"d": d}))' "$@"; }
outside_hash=$(field "$work/outside.json" 'd["trajectory_hash"]') inside_hash=$(field "$work/inside.json" 'd["trajectory_hash"]')
[ "$outside_hash" = "$inside_hash" ] || fail "the demo's trajectory hash in the image is $inside_hash, here $outside_hash"
cmp "$work/outside.csv" "$work/inside.csv" || fail "the demo's trace in the image differs from the one here"
echo "the demo's trajectory: hash $outside_hash and a trace of $(wc -l < "$work/outside.csv") lines, the same in the image"
echo "the sandbox's layers in the image: $(field "$work/inside.json" '", ".join(l["layer"] + ("" if l["applied"] else " (not applied: " + l["note"] + ")") for l in d["sandbox"])')"

# A reference's grade, hidden checks included.
echo ci-image-secret > "$work/secret.txt"
"$frob" grade "$source/assignments/go_to_goal" "$source/assignments/go_to_goal/solution.cpp" --secret "$work/secret.txt" \
  --results "$work/outside-grade.json" > "$work/grade-outside.log" 2>&1 || { cat "$work/grade-outside.log"; fail "frob grade here"; }
in_image frob grade /assignments/go_to_goal /assignments/go_to_goal/solution.cpp --secret /work/secret.txt \
  --results /work/inside-grade.json > "$work/grade-inside.log" 2>&1 || { cat "$work/grade-inside.log"; fail "frob grade in the image"; }
scores() {  # each test's name, score and status, then the total, from a Gradescope results.json
  python3 -c 'import json,sys; r=json.load(open(sys.argv[1])); [print(t["name"], t.get("score"), t.get("status")) for t in r["tests"]]; print("total", r["score"])' "$1"
}
scores "$work/outside-grade.json" > "$work/outside-scores.txt"
scores "$work/inside-grade.json" > "$work/inside-scores.txt"
diff "$work/outside-scores.txt" "$work/inside-scores.txt" || fail "the reference's grade in the image differs from the one here"
grep -q "^total 10" "$work/outside-scores.txt" || { cat "$work/outside-scores.txt"; fail "the reference did not get full marks"; }
echo "the reference's grade: $(tail -n 1 "$work/outside-scores.txt"), the same in the image"

# Controllers that attack the sandbox fail their own runs, with the reason, in the image; and so they
# do where the container's seccomp profile refuses user namespaces (Docker's default does, without
# CAP_SYS_ADMIN): frob then leaves that layer out, says so, and the other layers contain them.
python3 - /usr/share/containers/seccomp.json "$work/no-user-namespaces.json" << 'PY'
import json, sys
profile = json.load(open(sys.argv[1]))
for rule in profile["syscalls"]:
    rule["names"] = [n for n in rule.get("names", []) if n != "unshare"]
json.dump(profile, open(sys.argv[2], "w"))
PY
for profile in default "$work/no-user-namespaces.json"; do
  security=()
  [ "$profile" = default ] || security=(--security-opt "seccomp=$profile")
  for attack in runs_shell forks opens_socket reads_outside; do
    in_image frob run "/hostile/$attack.cpp" --seconds 2 > "$work/hostile.log" 2>&1 && { cat "$work/hostile.log"; fail "$attack ran in the image ($profile)"; }
    grep -q "the controller failed" "$work/hostile.log" || { cat "$work/hostile.log"; fail "$attack failed without the sandbox's reason ($profile)"; }
  done
done
grep -q "namespaces: NOT applied" "$work/hostile.log" || { cat "$work/hostile.log"; fail "without user namespaces, frob did not say that layer is missing"; }
echo "four attacks contained in the image, with and without user namespaces"
security=()

# clangd in the image sees frob's headers in a project frob init made.
in_image bash -c 'frob init /tmp/p > /dev/null && cd /tmp/p && clangd-16 --check=wander.cpp' > "$work/clangd.log" 2>&1 ||
  { tail -n 30 "$work/clangd.log"; fail "clangd-16 in the image finds errors in the template"; }
echo "the image builds, runs, grades and completes as the build here does"
