#!/usr/bin/env bash
# `rc2000sim design` (docs/design.md): the run command it prints for the best design, run, gives the
# same simulated seconds, energy and tests as the search reported, and the same bound in the same
# words (run_bounds.h's summary); the search with its pruning and
# the exhaustive one (--exhaustive) choose the same best design and the same Pareto front; a cap
# that no design meets says so; options that cannot apply are refused. A small workload (seconds).
#   design_run_test.sh RC2000SIM
set -euo pipefail
sim="$1"
work="$(mktemp -d)"; trap 'rm -rf "$work"' EXIT
space=(--device virtex4-sx55 --faces 70 --patch-levels 1 --steps 30 --lanes 1-4 --max-banks 9 --cards 1,2 --quiet)
"$sim" design "${space[@]}" --out "$work/search" >/dev/null
"$sim" design "${space[@]}" --exhaustive --out "$work/all" >/dev/null
cmd="$(python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['best']['run_command'])" "$work/search/design.json")"
cmd="${cmd#rc2000sim }"
# shellcheck disable=SC2086
"$sim" $cmd --quiet >/dev/null
python3 - "$work/search/design.json" "$work/all/design.json" "$work/search/best-run/report.json" <<'PY'
import json, sys
search, everything, run = (json.load(open(p)) for p in sys.argv[1:4])
best = search["best"]
got = {"simulated_seconds": run["simulated_seconds"], "energy_joules": run["board"]["energy"]["joules"],
       "tests": run["visibility_tests"]}
want = {k: best[k] for k in ("simulated_seconds", "energy_joules", "tests")}
if got != want:
    sys.exit(f"the best design's run differs: run {got}, search {want}")
# --exhaustive prunes nothing, and says so (issue 39: it reported the spare-bank designs as "pruned").
assert search["pruned_spare_banks"] > 0 and everything["pruned_spare_banks"] == 0
assert len(search["points"]) < len(everything["points"]), "the pruning simulated nothing less"
assert search["best"]["design"] == everything["best"]["design"], (search["best"]["design"], everything["best"]["design"])
front = lambda d: sorted(p["design"] for p in d["front"])
assert front(search) == front(everything), (front(search), front(everything))
assert best["bound"]["run"], "the best design names no bound"
# One bound model (host_sw/platform/run_bounds.h): the search names the bound in the words the run does.
bounds = run["board"]["bounds"]
got = (best["bound"]["text"], best["bound"]["run"], best["bound"]["fpga_stream"], best["bound"]["fpga_next"])
want = (bounds["summary"], bounds["run"]["bound"], bounds["fpga_stream"]["bound"], bounds["fpga_stream"]["next"])
if got != want:
    sys.exit(f"design and run name different bounds: design {got}, run {want}")
print("design: the best design's run gives its figures;", len(search["points"]), "of", len(everything["points"]),
      "designs simulated give the exhaustive best and front")
PY
# A cap no design meets: no best, said so, and the outputs still written.
"$sim" design "${space[@]}" --max-power 0.001 --out "$work/capped" >"$work/capped.txt"
grep -q "best: no design meets the constraints" "$work/capped.txt"
python3 -c "import json,sys; assert json.load(open(sys.argv[1]))['best'] is None" "$work/capped/design.json"
# Bad options name themselves and write nothing.
for bad in "--results nowhere" "--multipliers dsp" "--bank-clocks 0" "--max-banks 65" "--lanes 0"; do
  # shellcheck disable=SC2086
  if "$sim" design "${space[@]}" $bad --out "$work/bad" 2>"$work/err.txt"; then echo "accepted $bad"; exit 1; fi
  grep -q -- "${bad%% *}" "$work/err.txt" || { echo "error for $bad does not name it:"; cat "$work/err.txt"; exit 1; }
  [ ! -e "$work/bad" ] || { echo "$bad wrote $work/bad"; exit 1; }
done
echo "design: errors name their options"
# Caps and widths that cannot apply, refused before any work.
for bad in "--max-energy nan" "--max-power inf" "--min-bits 31" "--max-error 0" "--max-error-max nan" "--fidelity maybe" \
           "--max-error 0.01 --fidelity off"; do
  # shellcheck disable=SC2086
  if "$sim" design "${space[@]}" $bad --out "$work/bad" 2>"$work/err.txt"; then echo "accepted $bad"; exit 1; fi
  grep -q -- "${bad%% *}" "$work/err.txt" || { echo "error for $bad does not name it:"; cat "$work/err.txt"; exit 1; }
  [ ! -e "$work/bad" ] || { echo "$bad wrote $work/bad"; exit 1; }
done
echo "design: caps and widths that cannot apply are refused"
# An error bound on a mesh composition (Assimp's concave 66-gon in the Cornell Box, 102 faces, as it is):
# the best design is the fastest whose relative RMSE against double precision meets it, each width has its
# own solve's steps and software time, and the front carries the error.
printf '{"schema": "rc2000sim.composition/1", "room": "cornell-box", "meshes": [{"file": "/usr/share/assimp/models/OBJ/concave_polygon.obj", "rotate": {"axis": [1, 0.3, 0.2], "degrees": 50}, "fit_into": {"min": [120, 180, 250], "max": [420, 420, 450]}}]}' \
  > "$work/mesh.json"
"$sim" design --scene "$work/mesh.json" --faces 102 --face-levels 0 --patch-levels 0 --bits 11,15,23,31 --lanes 1,2 \
  --max-banks 6 --max-error 0.01 --quiet --out "$work/mesh" > "$work/mesh.txt"
grep -q "error bound: relative RMSE <= 0.01" "$work/mesh.txt"
python3 - "$work/mesh/design.json" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
widths = {w["bits"]: w for w in d["widths"]}
assert sorted(widths) == [11, 15, 23, 31] and all(w["measured"] and w["software_seconds"] > 0 for w in widths.values()), widths
meeting = [p for p in d["points"] if p["fidelity"]["relative_rmse"] <= 0.01]
assert d["best"] and d["best"]["fidelity"]["relative_rmse"] <= 0.01, d["best"]
assert d["best"]["simulated_seconds"] == min(p["simulated_seconds"] for p in meeting)
assert all(p["steps"] == widths[p["bits"]]["steps"] and p["meets_constraints"] == (p["fidelity"]["relative_rmse"] <= 0.01)
           for p in d["points"])
assert d["front"] and all(p["fidelity"]["measured"] for p in d["front"])
print("design: --max-error 0.01 on a mesh chooses", d["best"]["design"], "at relative RMSE", d["best"]["fidelity"]["relative_rmse"])
PY
# --fidelity off: no double-precision solve; every design's error "not measured", the widths' own steps kept.
"$sim" design "${space[@]}" --fidelity off --out "$work/nofid" > "$work/nofid.txt"
grep -q "fidelity not measured" "$work/nofid.txt"
python3 - "$work/nofid/design.json" "$work/search/design.json" <<'PY'
import json, sys
off, on = (json.load(open(p)) for p in sys.argv[1:3])
assert off["reference_steps"] is None and all(not p["fidelity"]["measured"] for p in off["points"])
assert [p["simulated_seconds"] for p in off["points"]] == [p["simulated_seconds"] for p in on["points"]]
assert off["best"]["design"] == on["best"]["design"]
print("design: --fidelity off measures no error and changes no time")
PY
