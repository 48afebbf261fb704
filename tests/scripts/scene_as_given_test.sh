#!/usr/bin/env bash
# Issue 37, item 5: a scene file is taken as it is by every command (no paper refinement unless asked)
# and solved with run's form factor unless one is given: `design --scene` on a mesh composition of
# 768 + 38 faces (it used to fail: "cannot refine ... faces down to 70"), `sweep --scene`, and `run`
# record the same construction and form factor. Seconds.
set -euo pipefail
sim="$1"; root="$2"
work="$(mktemp -d)"; trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
rock=/usr/share/assimp/models/3DS/fels.3ds
if [ ! -e "$rock" ]; then echo "SKIP: $rock is missing (assimp-testmodels)"; exit 77; fi
scene=(--scene "$root/configs/scenes/cornell-rock.json")
"$sim" design "${scene[@]}" --steps 3 --bits 15 --lanes 1 --banks 6 --results bank --multipliers block --concurrent on \
  --quiet --out "$work/design" > /dev/null || fail "design --scene on a mesh composition failed"
"$sim" sweep "${scene[@]}" --steps 3 --lanes 1 --quiet --out "$work/sweep" > /dev/null || fail "sweep --scene failed"
"$sim" run "${scene[@]}" --steps 3 --quiet --out "$work/run" > /dev/null 2>&1 || fail "run --scene failed"
# Refinement when asked still applies.
"$sim" design "${scene[@]}" --steps 3 --bits 15 --lanes 1 --banks 6 --results bank --multipliers block --concurrent on \
  --patch-levels 0 --form-factor point --quiet --out "$work/asked" > /dev/null || fail "design with --patch-levels 0 failed"
python3 - "$work" <<'PY'
import json, sys
w = sys.argv[1]
design = json.load(open(w + "/design/design.json"))["workload"]
sweep_doc = json.load(open(w + "/sweep/sweep.json"))
sweep = {"scene": sweep_doc["scene"], "form_factor": sweep_doc["solver"]["form_factor"]}
run = json.load(open(w + "/run/report.json"))["workload"]
for name, got in (("design", design), ("sweep", sweep)):
    assert got["scene"]["faces"] == run["scene"]["faces"] == 806, (name, got["scene"], run["scene"])
    assert got["scene"]["patches"] == run["scene"]["patches"], (name, got["scene"], run["scene"])
    assert got["form_factor"] == run["form_factor"] == "analytic", (name, got["form_factor"])
asked = json.load(open(w + "/asked/design.json"))["workload"]
assert asked["scene"]["patches"] == 806 and asked["form_factor"] == "point", asked
print("design, sweep and run take the rock as it is:", run["scene"]["faces"], "faces,", run["scene"]["patches"],
      "patches, form factor", run["form_factor"])
PY
