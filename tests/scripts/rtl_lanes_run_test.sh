#!/usr/bin/env bash
# `rc2000sim run --impl board --lanes-impl rtl` (the Verilated RTL lanes in the cycle-level wrapper;
# docs/board.md, "RTL lanes") against the same run with the C++ lanes (fast wrapper, the default):
# patches.csv byte for byte, and report.json equal in every field but the wrapper model ("cycle"),
# the lanes' implementation ("rtl", which it must say) and wall-clock seconds. "SKIP: ..." and exit 77 when the build has no Verilated models.
# usage: rtl_lanes_run_test.sh RC2000SIM
set -euo pipefail
sim="$1"
work="$(mktemp -d "${TMPDIR:-/tmp}/rtl-lanes-run.XXXXXX")"
trap 'rm -rf "$work"' EXIT
export SYSTEMC_DISABLE_COPYRIGHT_MESSAGE=1
args=(run --impl board --face-levels 0 --patch-levels 1 --steps 20 --lanes 2 --image-size 16 --quiet)
if ! "$sim" "${args[@]}" --lanes-impl rtl --out "$work/rtl" 2> "$work/err.txt"; then
  if grep -q "no Verilated RTL models" "$work/err.txt"; then
    echo "SKIP: $(cat "$work/err.txt" | head -1)"
    exit 77
  fi
  cat "$work/err.txt" >&2
  exit 1
fi
"$sim" "${args[@]}" --out "$work/cpp"
cmp "$work/cpp/patches.csv" "$work/rtl/patches.csv"
python3 - "$work/cpp/report.json" "$work/rtl/report.json" <<'PY'
import json, sys
def clean(x):
    if isinstance(x, dict):
        return {k: clean(v) for k, v in x.items() if not k.startswith("wall_seconds") and k not in ("wrapper_model", "lanes_impl")}
    if isinstance(x, list):
        return [clean(v) for v in x]
    return x
raw = [json.load(open(p)) for p in sys.argv[1:3]]
impl = [r["board"]["device"]["lanes_impl"] for r in raw]
if impl != ["cpp", "rtl"]:
    sys.exit(f"report.json board.device.lanes_impl: expected cpp and rtl, got {impl}")
a, b = (clean(r) for r in raw)
if a != b:
    sys.exit("report.json differs beyond the wrapper model and wall time")
print("RTL lanes: patches.csv and report.json equal to the C++ lanes'")
PY
