#!/usr/bin/env bash
# Config files are found through a run-time search path (docs/outputs.md, "Config files"): --configs
# DIR, else $RC2000SIM_CONFIGS, else the build's configs/. Every profile a board run reads (counted
# by the reader's log, RC2000SIM_LOG_READS) comes from the folder chosen, and the answer is the same.
#   config_dir_test.sh RC2000SIM SOURCE_ROOT
set -euo pipefail
sim="$1"; root="$2"
work="$(mktemp -d)"; trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
cp -r "$root/configs" "$work/copy"
mkdir "$work/empty"
run=(run --impl board --faces 70 --patch-levels 0 --steps 3 --quiet)
reads_from() {  # NAME DIR: every file the run NAME read lies in DIR
  local n; n=$(grep -c '^read ' "$work/$1.log" || true)
  [ "$n" -ge 4 ] || fail "$1: only $n files read (is the log on?)"
  if grep '^read ' "$work/$1.log" | grep -v ": $2/"; then fail "$1: read outside $2"; fi
}
same_answer() {  # NAME: its report, paths aside, is the default run's
  python3 - "$work/default/report.json" "$work/$1/report.json" <<'PY' || fail "$1: a different answer"
import json, sys
def strip(j):
    if isinstance(j, dict): return {k: strip(v) for k, v in j.items() if not k.startswith("wall_seconds") and k not in ("file", "source_file")}
    if isinstance(j, list): return [strip(v) for v in j]
    if isinstance(j, str) and "/configs/" in j or isinstance(j, str) and "/copy/" in j: return "(path)"
    return j
a, b = (strip(json.load(open(p))) for p in sys.argv[1:])
sys.exit(a != b)
PY
}
RC2000SIM_LOG_READS=1 "$sim" "${run[@]}" --out "$work/default" 2>"$work/default.log"
reads_from default "$root/configs"
RC2000SIM_LOG_READS=1 "$sim" "${run[@]}" --configs "$work/copy" --out "$work/option" 2>"$work/option.log"
reads_from option "$work/copy"; same_answer option
RC2000SIM_LOG_READS=1 RC2000SIM_CONFIGS="$work/copy" "$sim" "${run[@]}" --out "$work/env" 2>"$work/env.log"
reads_from env "$work/copy"; same_answer env
# The option wins over the variable.
RC2000SIM_LOG_READS=1 RC2000SIM_CONFIGS="$work/empty" "$sim" "${run[@]}" --configs "$work/copy" --out "$work/both" 2>"$work/both.log"
reads_from both "$work/copy"
# A folder without the profile: the error names where it looked; nothing written.
if RC2000SIM_CONFIGS="$work/empty" "$sim" "${run[@]}" --out "$work/none" 2>"$work/none.log"; then fail "an empty config folder was accepted"; fi
grep -q "looked for $work/empty/devices/xc2v6000.json" "$work/none.log" || { cat "$work/none.log" >&2; fail "the error does not name the folder"; }
[ ! -e "$work/none" ] || fail "a refused run wrote $work/none"
# --configs must name a folder.
if "$sim" "${run[@]}" --configs "$work/missing" --out "$work/bad" 2>"$work/bad.log"; then fail "--configs of a missing folder was accepted"; fi
grep -q -- "--configs $work/missing: not a folder" "$work/bad.log" || { cat "$work/bad.log" >&2; fail "--configs error"; }
echo "config folder: option, variable and the build's, each read from"
