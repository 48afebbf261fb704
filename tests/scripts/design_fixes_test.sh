#!/usr/bin/env bash
# The segment fixes as design-search axes (issue 37, docs/design.md "The fixes as axes"): a search over
# two fixes on a small smooth mesh (a 144-triangle torus in the box) solves and measures each fix at its
# width on its own, and an error bound between the two picks the design that meets it, the neighbour
# rule's (slower: the host's re-tests are part of its time); its printed run command carries the fix and
# gives the reported time; a fix axis that does not apply is refused in run's words, writing nothing.
#   design_fixes_test.sh RC2000SIM PROJECT_SOURCE_DIR
set -euo pipefail
sim="$1"; src="$2"
work="$(mktemp -d)"; trap 'rm -rf "$work"' EXIT
"$src/scripts/make-torus-obj" "$work/torus.obj" 12 6 >/dev/null
cp "$src/configs/scenes/cornell-torus.json" "$work/torus.json"
space=(--scene "$work/torus.json" --patch-levels 0 --steps 40 --bits 15 --lanes 2 --banks 6 --results bank
       --multipliers block --neighbour-rings 0,1 --quiet)
"$sim" design "${space[@]}" --out "$work/free" >"$work/free.txt"
python3 - "$work/free/design.json" "$work/free/design.csv" >"$work/bound.txt" <<'PY'
import csv, json, sys
d = json.load(open(sys.argv[1]))
widths = {w["neighbour_rings"]: w for w in d["widths"] if w["bits"] == 15}
assert set(widths) == {0, 1}, widths
plain, ring = widths[0], widths[1]
assert plain["measured"] and ring["measured"]
assert plain["relative_rmse"] != ring["relative_rmse"], "the fix changed nothing on this mesh"
points = {p["neighbour_rings"]: p for p in d["points"]}
assert points[1]["simulated_seconds"] > points[0]["simulated_seconds"], "the re-tests cost the neighbour rule nothing"
assert points[1]["fidelity"]["software_seconds"] > points[0]["fidelity"]["software_seconds"]
rows = list(csv.DictReader(open(sys.argv[2])))
assert sorted(r["neighbour_rings"] for r in rows) == ["0", "1"], rows
assert all(r["offset_lsb"] == "0" and r["coordinate_bits"] == "0" for r in rows)
good, bad = sorted((plain, ring), key=lambda w: w["relative_rmse"])
# Unbounded, the faster (no fix) is best; bounded between the two errors, the more faithful one.
assert d["best"]["neighbour_rings"] == 0, d["best"]["design"]
print((good["relative_rmse"] + bad["relative_rmse"]) / 2, good["neighbour_rings"])
PY
read -r bound want <"$work/bound.txt"
"$sim" design "${space[@]}" --max-error "$bound" --out "$work/bounded" >"$work/bounded.txt"
python3 - "$work/bounded/design.json" "$want" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
best = d["best"]
assert best["neighbour_rings"] == int(sys.argv[2]), best["design"]
assert best["fidelity"]["neighbour_rings"] == best["neighbour_rings"]
if best["neighbour_rings"]:
    assert "--neighbour-rings 1" in best["run_command"], best["run_command"]
    assert "neighbours (ring 1)" in best["design"], best["design"]
PY
grep -q "15 bits, neighbours (ring 1):" "$work/bounded.txt" || { echo "the summary does not list the fix's width:"; cat "$work/bounded.txt"; exit 1; }
# The best design's run command gives the reported time (the re-tests charged alike).
cmd="$(python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['best']['run_command'])" "$work/bounded/design.json")"
cmd="${cmd#rc2000sim }"
# shellcheck disable=SC2086
"$sim" $cmd --quiet >/dev/null
python3 - "$work/bounded/design.json" "$work/bounded/best-run/report.json" <<'PY'
import json, sys
best = json.load(open(sys.argv[1]))["best"]
run = json.load(open(sys.argv[2]))
got = (run["simulated_seconds"], run["visibility_tests"])
want = (best["simulated_seconds"], best["tests"])
assert got == want, (got, want)
PY
echo "design: two fixes searched, the error bound picks the faithful one, its run gives its time"
# Fix axes that do not apply: refused in run's words, naming the option and the limit, nothing written.
check_refused() {  # EXPECTED_TEXT ARGS...
  local want="$1"; shift
  if "$sim" design "${space[@]}" "$@" --out "$work/bad" 2>"$work/err.txt"; then echo "accepted $*"; exit 1; fi
  grep -q -- "$want" "$work/err.txt" || { echo "error for $* does not say '$want':"; cat "$work/err.txt"; exit 1; }
  [ ! -e "$work/bad" ] || { echo "$* wrote $work/bad"; exit 1; }
}
check_refused "--coordinate-bits: must be below --bits (15)" --coordinate-bits 0,15
check_refused "--coordinate-bits" --coordinate-bits 5
check_refused "--neighbour-rings" --neighbour-rings 3
check_refused "--offset-lsb" --offset-lsb 0,2000000
# run refuses the same coordinate width in the same words.
if "$sim" run --scene "$work/torus.json" --patch-levels 0 --steps 2 --visibility fast --bits 15 --coordinate-bits 15 \
     --out "$work/bad" 2>"$work/err.txt"; then echo "run accepted --coordinate-bits 15"; exit 1; fi
grep -q -- "must be below --bits (15): the lanes compute at --bits on coordinates of fewer bits, got 15" "$work/err.txt"
echo "design: fix axes that do not apply are refused"
