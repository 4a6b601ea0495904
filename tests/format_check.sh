#!/usr/bin/env bash
# The house style holds: every library, app and test source is as clang-format ($1) formats it.
# Controllers that tests and handouts quote by line are left as written (see .clang-format).
set -euo pipefail
clang_format=$1
cd "$(dirname "$0")/.."
mapfile -t files < <(find frob worlds render course app tests -name '*.cpp' -o -name '*.hpp' -o -name '*.h' |
  grep -vE '^(tests/course/sandbox/hostile/|tests/course/run/checked/|tests/frob/compile_errors/|tests/assignments/[^/]+/|course/examples/|course/template/)' | sort)
((${#files[@]} > 100)) || { echo "format_check: only ${#files[@]} sources found: wrong folder?"; exit 1; }
"$clang_format" --dry-run --Werror "${files[@]}"
echo "format_check: ${#files[@]} sources formatted"
