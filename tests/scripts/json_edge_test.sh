#!/usr/bin/env bash
# The JSON edge (issue 24): outside the tests, a file may include nlohmann/json only if it lies in io/
# (the JSON text checks), profiles/ (the profile-reading edge), apps/ (the command line), or
# its name ends in _json.h / _json.cpp (an output writer or codec: host_sw/outputs/ for a run's reports,
# the study codecs in host_sw/studies/). Models see typed values only: in the model folders (in_model
# below: scenes/, pipeline/, tlm/, board/ and host_sw/ up to host_sw/platform/) no file includes it,
# whatever its name; their writers live above them.
#   json_edge_test.sh SOURCE_DIR
# Exit 0 when every include is at an edge; 1 naming each file that is not (and each allow-listed file
# that no longer needs its place, so the list only shrinks).
set -euo pipefail
root="$1"
cd "$root"

# Allowed for now (shell patterns), each with its reason; remove a line when its files are done.
# Empty: every file that includes nlohmann/json is at an edge. A new entry needs its reason here.
allowed=(
)

is_allowed() {
  local pattern
  for pattern in "${allowed[@]}"; do
    # shellcheck disable=SC2254
    case "$1" in $pattern) return 0 ;; esac
  done
  return 1
}
in_model() {
  case "$1" in
    scenes/*|pipeline/*|tlm/*|board/*|host_sw/radiosity/*|host_sw/visibility/*|host_sw/driver/*|host_sw/energy/*|host_sw/platform/*) return 0 ;;
  esac
  return 1
}
at_edge() {
  in_model "$1" && return 1
  case "$1" in
    io/*|profiles/*|apps/*|*_json.h|*_json.cpp) return 0 ;;
  esac
  return 1
}

status=0
mapfile -t includers < <(grep -rlE '#include[[:space:]]*[<"]nlohmann/json' \
  --include='*.h' --include='*.hpp' --include='*.cpp' \
  io profiles scenes pipeline tlm board host_sw apps bench fuzz examples 2>/dev/null | sort)
for f in "${includers[@]}"; do
  at_edge "$f" && continue
  is_allowed "$f" && continue
  if in_model "$f"; then
    echo "FAIL: $f includes nlohmann/json in a model folder (its writer belongs above it: host_sw/outputs/)" >&2
  else
    echo "FAIL: $f includes nlohmann/json outside the JSON edges (io/, profiles/, apps/, *_json.h/.cpp)" >&2
  fi
  status=1
done
for pattern in "${allowed[@]}"; do
  used=0
  for f in "${includers[@]}"; do
    # shellcheck disable=SC2254
    case "$f" in $pattern) used=1 ;; esac
  done
  if [ $used -eq 0 ]; then
    echo "FAIL: allow-list entry $pattern matches no file that includes nlohmann/json: take it off the list" >&2
    status=1
  fi
done
[ $status -eq 0 ] && echo "json edge: ${#includers[@]} files include nlohmann/json, all at an edge or allow-listed (${#allowed[@]} patterns)"
exit $status
