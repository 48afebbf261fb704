#!/usr/bin/env bash
# `rc2000sim run --impl board` reads each profile once (issue 24): the device and host profiles, the
# pipeline resources and the paper's table, counted by the reader's own log (RC2000SIM_LOG_READS:
# io/input_file.cpp names every file it reads). Fixed-point and float lanes: sec 5.6's full-rate
# estimate asks for the RC2000's own xc2v6000 profile again for its bank bandwidth
# (board/throughput_estimates.cpp, rc2000_bandwidth), which a device named from the config folder
# answers from the process's one read (board::find_device_profile).
#   profile_reads_test.sh RC2000SIM
set -euo pipefail
sim="$1"
work="$(mktemp -d)"; trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
check() {  # NAME ARGS...: one run, its reads counted
  local name="$1"; shift
  RC2000SIM_LOG_READS=1 "$sim" run --impl board --faces 70 --patch-levels 0 --steps 3 --quiet --out "$work/$name" "$@" \
    >/dev/null 2>"$work/$name.log"
  grep '^read ' "$work/$name.log" | sort | uniq -c >"$work/$name.counts"
  for what in "a device profile" "a host profile" "the pipeline resources" "the paper's Table 2 data"; do
    grep -q "read $what: " "$work/$name.counts" || fail "$name: never read $what (is the log on?)"
  done
  if awk '$1 != 1 { bad = 1 } END { exit !bad }' "$work/$name.counts"; then
    cat "$work/$name.counts" >&2
    fail "$name: a file is read more than once"
  fi
  echo "$name: $(wc -l <"$work/$name.counts") files, each read once"
}
check fixed --lanes 2
check concurrent --lanes 2 --concurrent --bits 12
check float --lanes 2 --arith float:8,23
check float-other-device --device virtex4-sx55 --arith float:5,10
