#!/usr/bin/env bash
# Builds the Debian package, checks its metadata and contents, and runs frob from its files.
# Usage: deb_test.sh CPACK BUILD_DIR VERSION
cpack=$1 build=$2 version=$3
source "$(dirname "$0")/common.sh"
make_work

"$cpack" -G DEB --config "$build/CPackConfig.cmake" -B "$work/package" > "$work/cpack.log" 2>&1 || { cat "$work/cpack.log"; fail "cpack"; }
deb=$(ls "$work"/package/*.deb)
dpkg-deb -I "$deb" > "$work/info.txt"
contains "$work/info.txt" "Package: frob-sandbox"
contains "$work/info.txt" "Version: $version"
# Depends: what the programs load, and what a controller is compiled with; each a package Debian knows.
depends=$(sed -n 's/^ Depends: //p' "$work/info.txt")
for needed in libc6 libstdc++6 libbox2d2 libassimp5 libtomlplusplus3 libosmesa6 libavcodec59 libswscale6 libzip4 libseccomp2 libssl3 \
              fonts-dejavu-core clang-16 libeigen3-dev libclang-rt-16-dev binutils; do
  [[ ", $depends," == *", $needed,"* ]] || fail "Depends lacks $needed: $depends"
done
for package in ${depends//,/ }; do
  dpkg-query -W "$package" > /dev/null 2>&1 || fail "Depends names $package, which is not a Debian package installed here"
done
# Each library the programs link comes from a package in Depends.
dpkg-deb -x "$deb" "$work/root"
owner_of() {  # the package owning a library, under /lib or /usr/lib (Debian 12 merges them)
  local p
  for p in "$1" "/usr$1" "${1#/usr}" "$(realpath "$1")"; do
    dpkg -S "$p" 2> /dev/null | head -n 1 | cut -d: -f1 && return 0
  done
  true
}
for program in usr/bin/frob usr/libexec/frob/frob-controller-host usr/libexec/frob/frob-sandbox; do
  for name in $(readelf -d "$work/root/$program" | sed -n 's/.*Shared library: \[\(.*\)\]/\1/p'); do
    # ldd names a library, then its path; the dynamic loader only by its path.
    path=$(ldd "$work/root/$program" | awk -v n="$name" '$1 == n {print $3} $1 ~ ("/" n "$") {print $1}' | head -n 1)
    owner=$(owner_of "$path")
    [ -n "$owner" ] || fail "$program links $name ($path), which no Debian package owns"
    [[ ", $depends," == *", $owner,"* ]] || fail "$program links $name of $owner, which Depends lacks: $depends"
  done
done

dpkg-deb -c "$deb" | awk '{print $6}' > "$work/contents.txt"
for path in ./usr/bin/frob ./usr/libexec/frob/frob-controller-host ./usr/libexec/frob/frob-sandbox ./usr/include/frob/frob.hpp \
            ./usr/lib/libfrob_frob.a ./usr/lib/cmake/frob/frobConfig.cmake ./usr/lib/cmake/frob/frobTargets.cmake \
            ./usr/lib/frob/frob.pch ./usr/lib/frob/frob-headers.yaml ./usr/lib/frob/examples/06_bug.so \
            ./usr/share/frob/version ./usr/share/frob/worlds/arena.toml ./usr/share/frob/models/robot.obj \
            ./usr/share/frob/examples/06_bug.cpp ./usr/share/frob/assignments/bug/rubric.toml ./usr/share/frob/template/CMakeLists.txt; do
  grep -qx -- "$path" "$work/contents.txt" || fail "the package lacks $path"
done
lacks "$work/contents.txt" "solution.cpp"  # reference solutions stay with the instructors
lacks "$work/contents.txt" "/work/"

# The package's files run where they were unpacked (a prefix that is not /usr).
mkdir "$work/elsewhere" && cd "$work/elsewhere"
"$work/root/usr/bin/frob" --version > version.txt
contains version.txt "files in $work/root/usr (installed)"
"$work/root/usr/bin/frob" run run_around --seconds 1 > run.log 2>&1 || { cat run.log; fail "frob run from the package's files"; }
echo "the package $deb has its metadata and files, and runs"
