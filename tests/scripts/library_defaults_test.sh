#!/usr/bin/env bash
# The library's defaults are the command's (issue 24): a program that calls run_radiosity_on_board
# with default options (tests/tools/default_board_run) gets the report `rc2000sim run --impl board`
# writes with no other option: the same steps, simulated seconds and board report (report.json's
# "board"), every field but the wall-clock ones. A different host profile (the uncalibrated
# athlon-mp-2600 was once the library's) moves every time in it.
#   library_defaults_test.sh RC2000SIM DEFAULT_BOARD_RUN
set -euo pipefail
sim="$1"; lib="$2"
work="$(mktemp -d)"; trap 'rm -rf "$work"' EXIT
"$sim" run --impl board --out "$work/cmd" --quiet >/dev/null
"$lib" "$work/lib.json" >/dev/null
python3 - "$work/cmd/report.json" "$work/lib.json" <<'PY'
import json, sys
cmd = json.load(open(sys.argv[1]))
lib = json.load(open(sys.argv[2]))
def no_wall(j):
    if isinstance(j, dict):
        return {k: no_wall(v) for k, v in j.items() if not k.startswith("wall_seconds")}
    if isinstance(j, list):
        return [no_wall(v) for v in j]
    return j
want = {"steps": cmd["steps"], "simulated_seconds": cmd["simulated_seconds"], "board": no_wall(cmd["board"])}
got = no_wall(lib)
if got != want:
    for key in want:
        if got.get(key) != want[key]:
            print(f"library defaults differ from `rc2000sim run --impl board` in '{key}'", file=sys.stderr)
    print("host: command", cmd["board"].get("host", {}).get("profile"), "library", lib["board"].get("host", {}).get("profile"), file=sys.stderr)
    sys.exit(1)
print("library defaults give the command's report:", cmd["steps"], "steps,", cmd["simulated_seconds"], "simulated s")
PY
