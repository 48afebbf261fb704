#!/usr/bin/env bash
# Issue 39: how a solve ends, through the command line. A fixed step count run past subnormal powers
# stops, says so (stderr, the summary, report.json) and writes its outputs, in double precision, a
# float:E,M pipeline and on the board; a closed room of reflectance 0.999 that books most of its power
# as escaping warns; a composition of such rooms too; subnormal emission names the underflow. Seconds.
set -euo pipefail
sim="$1"
work="$(mktemp -d)"; trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
room() {  # room <reflectance> <emission>: a closed cube lit by a small lamp below its top
  cat <<SCENE
material white reflectance $1 $1 $1
material lamp  reflectance 0.5 0.5 0.5 emission $2 $2 $2
quad floor   white  2 0 0   0 0 0   0 0 2   2 0 2
quad ceiling white  2 2 0   2 2 2   0 2 2   0 2 0
quad back    white  2 0 2   0 0 2   0 2 2   2 2 2
quad front   white  0 0 0   2 0 0   2 2 0   0 2 0
quad left    white  0 0 2   0 0 0   0 2 0   0 2 2
quad right   white  2 0 0   2 0 2   2 2 2   2 2 0
quad lamp    lamp   1.2 1.99 0.8   1.2 1.99 1.2   0.8 1.99 1.2   0.8 1.99 0.8
camera 1 1 0.2   1 1 2   0 1 0   60
SCENE
}
room 0.1 10 > "$work/dim.scene"
room 0.999 10 > "$work/closed.scene"
room 0.5 1e-310 > "$work/subnormal.scene"

# 1. Past subnormal powers: was "internal error: step 2611 delivered ... (a bug; please report it)".
for arith in "" "--arith float:8,23" "--impl board"; do
  out="$work/dim${arith// /}"
  # shellcheck disable=SC2086
  "$sim" run --scene "$work/dim.scene" --patch-levels 0 --steps 5000 $arith --quiet --out "$out" \
    > "$out.txt" 2> "$out.err" || fail "dim room with '$arith' failed: $(cat "$out.err")"
  grep -q "warning: the solve stopped after [0-9]* steps, before the 5000 asked for" "$out.err" ||
    fail "no stop warning with '$arith': $(cat "$out.err")"
  grep -q "steps (stopped: nothing left to shoot is a normal number)" "$out.txt" || fail "summary silent with '$arith'"
  python3 - "$out/report.json" <<'PY' || fail "report.json with '$arith'"
import json, sys
r = json.load(open(sys.argv[1]))["solver"]
assert r["exhausted"] is True and r["steps"] < 5000, r
assert any("the solve stopped after" in w for w in r["warnings"]), r["warnings"]
PY
  [ -s "$out/patches.csv" ] && [ -s "$out/image.png" ] || fail "outputs missing with '$arith'"
done

# 2. A closed room of reflectance 0.999: most power booked as escaping, warned about.
"$sim" run --scene "$work/closed.scene" --patch-levels 1 --quiet --out "$work/closed" > /dev/null 2> "$work/closed.err"
grep -q "warning: the energy accounting is implausible for this scene" "$work/closed.err" || fail "closed room: $(cat "$work/closed.err")"
python3 -c 'import json,sys; assert any("implausible" in w for w in json.load(open(sys.argv[1]))["solver"]["warnings"])' \
  "$work/closed/report.json" || fail "closed room: report.json has no warning"
# A composition (docs/scenes.md): the closed room with a white block standing in it, still closed.
cat > "$work/block.obj" <<'OBJ'
v 0 0 0
v 1 0 0
v 1 1 0
v 0 1 0
v 0 0 1
v 1 0 1
v 1 1 1
v 0 1 1
f 1 4 3 2
f 5 6 7 8
f 1 2 6 5
f 4 8 7 3
f 1 5 8 4
f 2 3 7 6
OBJ
cat > "$work/two.json" <<'JSON'
{"schema": "rc2000sim.composition/1",
 "room": {"file": "closed.scene"},
 "meshes": [{"file": "block.obj", "fit_into": {"min": [0.3, 0, 0.3], "max": [0.9, 0.6, 0.9]},
             "material": {"reflectance": [0.999, 0.999, 0.999]}}]}
JSON
"$sim" run --scene "$work/two.json" --patch-levels 1 --quiet --out "$work/two" > /dev/null 2> "$work/two.err" ||
  fail "composition: $(cat "$work/two.err")"
grep -q "warning: the energy accounting is implausible for this scene" "$work/two.err" || fail "the composed closed room: $(cat "$work/two.err")"
# The Cornell Box (open at the front) gives no such warning.
"$sim" run --patch-levels 1 --quiet --out "$work/box" > /dev/null 2> "$work/box.err"
! grep -q "implausible\|stopped after" "$work/box.err" || fail "the Cornell Box warned: $(cat "$work/box.err")"

# 3. Subnormal emission: the underflow in the scene's units is named; the picture is not black.
"$sim" run --scene "$work/subnormal.scene" --patch-levels 1 --quiet --out "$work/sub" > /dev/null 2> "$work/sub.err"
grep -q "have radiosity that underflows to zero or a subnormal number in the scene's units" "$work/sub.err" ||
  fail "subnormal emission: $(cat "$work/sub.err")"
! grep -q "picture is dark" "$work/sub.err" || fail "subnormal emission: dark picture"
echo "PASS: subnormal powers stop and say so; implausible energy and underflow are warned about"
