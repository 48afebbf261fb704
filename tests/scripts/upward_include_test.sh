#!/usr/bin/env bash
# The arrows run one way (issue 36; docs/architecture.md, "Dependencies point one way"): the layers below
# the host software, io/, profiles/, scenes/, pipeline/, tlm/ and board/, include nothing under host_sw/.
# The build already refuses such an include (no include root of host_sw/ reaches those libraries); this
# states the rule where it is read and names each offending line, including one a stale build folder
# might still compile.
#   upward_include_test.sh SOURCE_DIR
# Exit 0 when no file below includes host_sw/; 1 naming each file:line that does.
set -euo pipefail
root="$1"
cd "$root"

below=(io profiles scenes pipeline tlm board)
status=0
count=0
for d in "${below[@]}"; do
  [ -d "$d" ] || { echo "FAIL: $d/ is not a folder of $root (the list of layers below host_sw/ is out of date)" >&2; exit 1; }
done
while IFS= read -r hit; do
  echo "FAIL: $hit: includes the host software from below it (host_sw/ sits above ${below[*]})" >&2
  status=1
done < <(grep -rnE '^[[:space:]]*#[[:space:]]*include[[:space:]]*[<"]host_sw/' \
           --include='*.h' --include='*.hpp' --include='*.cpp' "${below[@]}" || true)
count=$(find "${below[@]}" -name '*.h' -o -name '*.hpp' -o -name '*.cpp' | wc -l)
[ $status -eq 0 ] && echo "upward includes: none in the $count files of ${below[*]}"
exit $status
