#!/usr/bin/env bash
# Builds Frob Sandbox's OCI image (course/image/Containerfile) from Debian's packages only: cpack
# makes frob's .deb from a built tree; mmdebstrap makes a Debian 12 root holding what the .deb
# depends on and recommends, which podman imports as the base; the Containerfile installs the .deb
# on it. No registry is reached; the Debian archive is (FROB_DEBIAN_MIRROR).
# Usage: course/image/build.sh BUILD_DIR [TAG]   (TAG: frob-sandbox:latest unless given)
# Then: podman run --rm -it -v "$PWD:/work" frob-sandbox frob run wander.cpp
set -euo pipefail
build=$(cd "$1" && pwd) tag=${2:-frob-sandbox:latest}
here=$(cd "$(dirname "$0")" && pwd)
source=$(cd "$here/../.." && pwd)
mirror=${FROB_DEBIAN_MIRROR:-http://deb.debian.org/debian}
base=${tag%%:*}-base:bookworm
export CONTAINERS_CONF=${CONTAINERS_CONF:-$here/containers.conf}
for program in cpack mmdebstrap podman dpkg-deb; do
  command -v "$program" > /dev/null || { echo "build.sh: $program is missing (apt-get install mmdebstrap podman runc)" >&2; exit 1; }
done

work=$(mktemp -d "${TMPDIR:-/tmp}/frob-image-XXXXXX")
trap 'rm -rf "$work"' EXIT
mkdir "$work/context"
"${CPACK:-cpack}" -G DEB --config "$build/CPackConfig.cmake" -B "$work/package" > "$work/cpack.log" 2>&1 || { cat "$work/cpack.log" >&2; exit 1; }
deb=$(ls "$work"/package/*.deb)
cp "$deb" "$work/context/frob-sandbox.deb"
cp "$source/course/autograder/grade_submission.sh" "$source/course/prairielearn/entrypoint.sh" "$work/context/"

# The base: Debian 12 with the .deb's dependencies and recommendations (its compiler, clangd, cmake).
packages=$(dpkg-deb -f "$deb" Depends Recommends | sed 's/^[A-Za-z]*: //' | paste -sd, - | tr -d ' ')
mmdebstrap --quiet --variant=minbase --include="$packages" --format=tar bookworm "$work/base.tar" "$mirror" \
  "deb ${FROB_DEBIAN_SECURITY_MIRROR:-http://deb.debian.org/debian-security} bookworm-security main"
podman import --quiet "$work/base.tar" "$base" > /dev/null
podman build --quiet --network none --build-arg "BASE=$base" --file "$here/Containerfile" --tag "$tag" "$work/context" > /dev/null
echo "built $tag (frob's $(basename "$deb") on $base)"
