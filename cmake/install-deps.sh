#!/usr/bin/env bash
# Installs the Debian 12 packages Frob Sandbox builds against; does nothing when all are present.
set -euo pipefail
packages=(
  cmake ninja-build pkg-config ccache clang-format-16   # build tools; the house style
  clangd-16                                        # editor completion (frob init's test)
  clang-16 libclang-rt-16-dev                      # the compiler (see README: GCC 12 breaks coroutines), its sanitizers
  binutils                                         # addr2line: names the line in a checked run's report
  libeigen3-dev libbox2d-dev libassimp-dev         # maths, physics, meshes
  libseccomp-dev                                   # the controller host's system-call filter
  libzip-dev                                       # the Gradescope autograder zip
  libssl-dev                                       # HMAC signatures of graded runs' wheel logs
  zlib1g-dev                                       # the run viewer page's packed data
  libosmesa6-dev libpng-dev libfreetype-dev fonts-dejavu-core   # offscreen rendering and text
  libavcodec-dev libavformat-dev libavutil-dev libswscale-dev   # video encoding
  libtomlplusplus-dev libcli11-dev nlohmann-json3-dev           # world files, command line, JSON
  libgtest-dev libgmock-dev libbenchmark-dev libenki-dev        # tests and benchmarks
  libxml2-dev chromium                                          # grade report tests: XML read back, HTML rendered headless
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
done
if ((${#missing[@]} == 0)); then
  exit 0
fi
sudo=""
if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
echo "install-deps: installing ${missing[*]}"
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
