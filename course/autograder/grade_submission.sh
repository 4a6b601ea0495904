#!/usr/bin/env bash
# Grades one submitted controller with `frob grade`: Gradescope's run_autograder and PrairieLearn's
# entrypoint (course/prairielearn/entrypoint.sh) both call it (course/grading.md).
#
# Usage: grade_submission.sh FORMAT ASSIGNMENT SUBMISSION_DIR RESULTS_FILE [FROB_GRADE_ARG...]
#   FORMAT          gradescope (frob's --results) or prairielearn (frob's --prairielearn)
#   ASSIGNMENT      an assignment's name (frob list), or its folder or rubric.toml
#   SUBMISSION_DIR  the submitted files; the controller is the one .cpp file in it (up to 3 folders
#                   deep) with a FROB_CONTROLLER(...) line, whatever the others beside it are
#   RESULTS_FILE    the results.json to write, in FORMAT (its folder is made if missing)
#   FROB_GRADE_ARG  more for frob grade, e.g. --logs DIR; frob runs in the controller's folder, so
#                   give their paths absolute
# Environment: FROB, the frob to run (default: frob on PATH); FROB_GRADE_SECRET, the instructor's
# secret (or give --secret FILE); FROB_CACHE_DIR, frob's controller cache.
# Exit status: frob's (0 whenever it graded, whatever the score); 0 when the submission has no
# controller, or several, and it wrote the results saying so; 2 when it is called wrongly.
set -u

usage() {
  echo "usage: $(basename "$0") gradescope|prairielearn ASSIGNMENT SUBMISSION_DIR RESULTS_FILE [FROB_GRADE_ARG...]" >&2
  exit 2
}

# json_string TEXT: TEXT as a JSON string, quotes included.
json_string() {
  local LC_ALL=C  # byte by byte: UTF-8 passes through as it is
  local s=$1 out='' c code i
  for ((i = 0; i < ${#s}; i++)); do
    c=${s:i:1}
    case $c in
      '"') out+='\"' ;;
      '\') out+='\\' ;;
      $'\n') out+='\n' ;;
      $'\r') out+='\r' ;;
      $'\t') out+='\t' ;;
      *)
        printf -v code '%d' "'$c"
        if ((code >= 0 && code < 32)); then printf -v c '\\u%04x' "$code"; fi
        out+=$c
        ;;
    esac
  done
  printf '"%s"' "$out"
}

# write_whole FILE TEXT: FILE holds TEXT and a newline, or is left as it was: never half written.
write_whole() {
  local partial
  partial=$(mktemp "$1.XXXXXX") || return 1
  if printf '%s\n' "$2" > "$partial" && chmod 644 "$partial" && mv -f "$partial" "$1"; then return 0; fi
  rm -f "$partial"
  return 1
}

# absolute PATH: PATH from the folder this was called in, so that it holds after the cd below.
absolute() { case $1 in /*) printf '%s' "$1" ;; *) printf '%s/%s' "$PWD" "$1" ;; esac; }

(($# >= 4)) || usage
format=$1 assignment=$2 submission_dir=$3 results=$4
shift 4
case $format in
  gradescope) results_option=--results ;;
  prairielearn) results_option=--prairielearn ;;
  *) usage ;;
esac
if [ ! -d "$submission_dir" ]; then
  echo "$(basename "$0"): $submission_dir: no such folder" >&2
  exit 2
fi
frob=${FROB:-frob}
case $frob in */*) frob=$(absolute "$frob") ;; esac
submission_dir=$(absolute "$submission_dir")
results=$(absolute "$results")
if [ -e "$assignment" ]; then assignment=$(absolute "$assignment"); fi  # a folder or rubric.toml; else a name
mkdir -p -- "$(dirname -- "$results")" || exit 1
rm -f -- "$results"  # if frob cannot grade, no results from an earlier run may stand for these

# The controller is the one .cpp file with a FROB_CONTROLLER(...) line; other files may lie beside it.
sources=() controllers=()
mapfile -d '' -t sources < <(find "$submission_dir" -maxdepth 3 -name '*.cpp' -type f -print0 | sort -z)
if ((${#sources[@]} > 0)); then
  mapfile -d '' -t controllers < <(grep -lZE '^[[:space:]]*FROB_CONTROLLER[[:space:]]*\(' -- "${sources[@]}" < /dev/null)
fi
if ((${#controllers[@]} != 1)); then
  if ((${#sources[@]} == 0)); then
    why="No .cpp file was submitted: submit your controller file."
  elif ((${#controllers[@]} == 0)); then
    why="None of the submitted .cpp files has a FROB_CONTROLLER(...) line: submit the file that holds your controller."
  else
    why="${#controllers[@]} of the submitted .cpp files have a FROB_CONTROLLER(...) line: submit one controller."
  fi
  text=$(json_string "$why")
  if [ "$format" = gradescope ]; then
    result="{\"score\": 0, \"output\": $text, \"tests\": []}"
  else
    # Not gradable, as for a compile error: nothing was graded, so no attempt is used up (PrairieLearn's external grading docs).
    result="{\"gradable\": false, \"score\": 0, \"message\": $text, \"output\": \"\", \"format_errors\": $text, \"tests\": []}"
  fi
  write_whole "$results" "$result" || { echo "$(basename "$0"): cannot write $results" >&2; exit 1; }
  echo "$why"
  exit 0
fi

controller=${controllers[0]}
folder=$(dirname -- "$controller")
# frob reads ASSIGNMENT as a path before a name: where the student's files hold one of that name
# (a program built from go_to_goal.cpp, say), it runs from an empty folder instead.
empty=''
if [[ $assignment != /* && -e "$folder/$assignment" ]]; then
  empty=$(mktemp -d) || exit 1
  trap 'rm -rf -- "$empty"' EXIT
  folder=$empty
fi
cd -- "$folder" || exit 1
"$frob" grade "$assignment" "$controller" "$results_option" "$results" "$@"
status=$?
if [ ! -f "$results" ]; then echo "$(basename "$0"): frob grade wrote no results (exit status $status)" >&2; fi
exit "$status"
