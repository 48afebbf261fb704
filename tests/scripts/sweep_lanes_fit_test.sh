#!/usr/bin/env bash
# Sec 5.6's "lanes that fit" of a sweep follow the swept device profile fields (docs/studies.md): a
# study sweeping wrapper.results and banks.clock_mhz gives one estimate per device, width and
# combination of their values, each naming its values (`settings`), and each equal to the estimate of
# a study that fixes those values instead ([fixed]: the profile with the setting applied, the path
# the estimates took before they followed axes). Results on chip change the model's estimate.
#   sweep_lanes_fit_test.sh RC2000SIM
set -euo pipefail
sim="$1"
work="$(mktemp -d "${TMPDIR:-/tmp}/sweep-lanes-fit-test.XXXXXX")"
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

study() {  # NAME AXES FIXED
  cat > "$work/$1.toml" <<TOML
[[scenes]]
paper = { faces = 70, patches = 280 }
[solver]
steps = 5
[axes]
devices = ["xc2v6000"]
lanes = [1]
banks = [6]
$2
[fixed]
$3
TOML
  "$sim" sweep --study "$work/$1.toml" --quiet --out "$work/$1" > "$work/$1.txt"
}

study swept '"wrapper.results" = ["bank", "on_chip"]
"banks.clock_mhz" = [100, 200]' ''
for results in bank on_chip; do
  for clock in 100 200; do
    study "fixed-$results-$clock" '' "\"wrapper.results\" = \"$results\"
\"banks.clock_mhz\" = $clock"
  done
done

python3 - "$work" <<'PY'
import json, os, sys
work = sys.argv[1]
swept = json.load(open(os.path.join(work, "swept", "sweep.json")))
fits = swept["lanes_that_fit"]
if len(fits) != 4:
    sys.exit(f"FAIL: {len(fits)} estimates for 2 x 2 swept values, want 4")
models = {}
for e in fits:
    s = e.get("settings")
    if s is None or set(s) != {"wrapper.results", "banks.clock_mhz"}:
        sys.exit(f"FAIL: an estimate does not name its swept values: {e}")
    fixed = json.load(open(os.path.join(work, f"fixed-{s['wrapper.results']}-{s['banks.clock_mhz']}", "sweep.json")))
    (want,) = fixed["lanes_that_fit"]
    for key in ("paper_rule", "model", "why_different"):
        if e[key] != want[key]:
            sys.exit(f"FAIL: the estimate for {s} differs from the study fixing those values: {key}\n{e[key]}\n{want[key]}")
    models[(s["wrapper.results"], s["banks.clock_mhz"])] = e["model"]["intersections_per_s"]
if not models[("on_chip", 100)] > models[("bank", 100)]:
    sys.exit(f"FAIL: results on chip do not change the model's estimate: {models}")
if "lanes_that_fit_note" not in swept:
    sys.exit("FAIL: no note on the estimates of a study sweeping device fields")
print("sweep lanes that fit: one estimate per swept combination, each the fixed study's;", models)
PY
grep -q '15-bit \[wrapper.results=on_chip, banks.clock_mhz=200\] xc2v6000' "$work/swept.txt" ||
  fail "the summary does not name the swept values of an estimate: $(grep -A6 'lanes that fit' "$work/swept.txt")"
echo "sweep lanes that fit: the summary names each estimate's values"
