# Shared by the install tests: checks that say what failed, and a temporary folder of the test's own.
set -euo pipefail

fail() { echo "FAILED: $*" >&2; exit 1; }
# contains FILE TEXT: FILE has a line containing TEXT (fixed string).
contains() { grep -qF -- "$2" "$1" || { cat "$1" >&2; fail "$1 does not contain '$2'"; }; }
# lacks FILE TEXT: no line of FILE contains TEXT.
lacks() { ! grep -qF -- "$2" "$1" || { cat "$1" >&2; fail "$1 contains '$2'"; }; }

# make_work: $work, a new folder removed at the end; compiled controllers are cached in it.
make_work() {
  work=$(mktemp -d "${TMPDIR:-/tmp}/frob-install-test-XXXXXX")
  trap 'rm -rf "$work"' EXIT
  chmod 755 "$work"  # run as root, the controller host runs as a user of its own, and runs from a prefix in here
  export FROB_CACHE_DIR="$work/cache"
}
