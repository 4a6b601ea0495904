#!/usr/bin/env bash
# Installs to a temporary prefix, moves it, makes a project from the student template with the
# moved prefix's `frob init` (its editor flags naming the prefix's headers), and configures, builds
# and tests it with find_package(frob CONFIG) against the moved prefix.
# Usage: template_test.sh CMAKE CTEST BUILD_DIR CXX MAKE_PROGRAM
cmake=$1 ctest=$2 build=$3 cxx=$4 make_program=$5
source "$(dirname "$0")/common.sh"
make_work

"$cmake" --install "$build" --prefix "$work/installed" > "$work/install.log"
mv "$work/installed" "$work/moved"
prefix="$work/moved"
"$prefix/bin/frob" init "$work/project" > init.log 2>&1 || { cat init.log; fail "frob init"; }
cd "$work/project"
contains compile_flags.txt "-I$prefix/include"
lacks compile_flags.txt "frob-sdk"

"$cmake" -S . -B build -G Ninja -DCMAKE_MAKE_PROGRAM="$make_program" -DCMAKE_CXX_COMPILER="$cxx" \
  -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF > configure.log 2>&1 || { cat configure.log; fail "configure"; }
contains build/CMakeCache.txt "frob_DIR:PATH=$prefix/"
"$cmake" --build build > build.log 2>&1 || { cat build.log; fail "build"; }
"$ctest" --test-dir build --output-on-failure > test.log 2>&1 || { cat test.log; fail "the template's tests"; }
contains test.log "100% tests passed, 0 tests failed out of 2"

# The template's controller runs with the installed frob.
"$prefix/bin/frob" run wander.cpp --seconds 2 > run.log 2>&1 || { cat run.log; fail "frob run wander.cpp"; }
echo "the student template builds, tests and runs against the moved prefix"
