#!/usr/bin/env bash
# Installs to a temporary prefix, moves it, and from another folder runs an example, a student file
# and a student file that breaks out of its sandbox; where the system allows (root), with the source
# and build trees hidden under empty folders, so that nothing can come from them.
# Usage: relocated_test.sh CMAKE SOURCE_DIR BUILD_DIR VERSION
source "$(dirname "$0")/common.sh"

if [ "$1" != --inner ]; then
  cmake=$1 source=$2 build=$3 version=$4
  make_work
  "$cmake" --install "$build" --prefix "$work/installed" > "$work/install.log"
  mv "$work/installed" "$work/moved"  # a prefix that moved: nothing may name where it was installed
  mkdir "$work/scripts" && cp "$0" "$(dirname "$0")/common.sh" "$work/scripts/"  # these come from the source tree
  inner=("$work/scripts/$(basename "$0")" --inner "$work" "$version")
  if unshare --mount --propagation private true 2> /dev/null; then
    # The build tree first: it may lie inside the source tree.
    unshare --mount --propagation private bash -c 'mount -t tmpfs none "$1" && mount -t tmpfs none "$2" && shift 2 && bash "$@"' \
      hide "$build" "$source" "${inner[@]}"
    echo "(the source tree $source and the build tree $build were hidden)"
  else
    bash "${inner[@]}"
    echo "(no mount namespace here: the source and build trees were not hidden)"
  fi
  exit 0
fi

work=$2 version=$3
export FROB_CACHE_DIR="$work/cache"
prefix="$work/moved"
frob="$prefix/bin/frob"
mkdir "$work/elsewhere" && cd "$work/elsewhere"
chmod 777 .  # writable by anyone, so that only the sandbox keeps a controller from writing here

# The version, the compiler, and the files of the moved prefix, not of the build.
"$frob" --version > version.txt
contains version.txt "frob $version"
contains version.txt "compiles controllers with "
contains version.txt "files in $prefix (installed)"

# The worlds, examples and assignments of the prefix.
"$frob" list > list.txt
contains list.txt "arena"
contains list.txt "06_bug"
contains list.txt "go_to_goal"
contains list.txt "frob run $prefix/share/frob/examples/NAME.cpp"
contains list.txt "frob init my_project (the template: $prefix/share/frob/template)"
lacks list.txt "cannot"

# An assignment of the prefix graded (its starter scores, visible checks only).
"$frob" grade go_to_goal "$prefix/share/frob/assignments/go_to_goal/starter.cpp" --visible-only > grade.txt 2>&1 || { cat grade.txt; fail "frob grade"; }
contains grade.txt "Total"

# An example by name (prebuilt), and one as a file compiled like a student's.
"$frob" run run_around --seconds 1 --json > example.json || fail "frob run run_around"
contains example.json '"trajectory_hash"'
"$frob" run "$prefix/share/frob/examples/02_wall_follower.cpp" --seconds 1 > example_file.txt 2>&1 || { cat example_file.txt; fail "an example file"; }

# A student's file, in this folder, against the installed headers and precompiled header.
cat > student.cpp <<'CPP'
#include <frob/frob.hpp>
using namespace frob;
Behavior<Wheels> forward(const Robot&) { return wheels(0.2, 0.1); }
FROB_CONTROLLER(forward, .world = "empty", .seconds = 2)
CPP
"$frob" run student.cpp --video student.mp4 --json > student.json 2> student.err || { cat student.err; fail "frob run student.cpp"; }
contains student.json '"trajectory_hash"'
# It ran in the installed controller host, sandboxed by the installed frob-sandbox.
contains student.json '"landlock"'
contains student.json '"seccomp"'
[ -s student.mp4 ] || fail "no video"

# The sandbox of the installed host: a controller writing outside its scratch folder is stopped and
# writes nothing.
cat > escapes.cpp <<CPP
#include <frob/frob.hpp>
#include <cstdio>
using namespace frob;
Behavior<Wheels> escapes(const Robot&) {
  return toBehavior(lift([](double t) {
    if (t > 0.5) if (std::FILE* f = std::fopen("$work/elsewhere/escaped", "w")) std::fclose(f);
    return Wheels{0.1, 0.0};
  }, time()));
}
FROB_CONTROLLER(escapes)
CPP
if "$frob" run escapes.cpp --seconds 2 --quiet > escapes.out 2> escapes.err; then fail "a controller writing outside its sandbox ran to the end"; fi
contains escapes.err "tried to write $work/elsewhere/escaped (not allowed)"
[ ! -e escaped ] || fail "the controller wrote outside its sandbox"
echo "the moved prefix $prefix runs examples and student files, sandboxed"
