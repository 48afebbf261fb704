#!/usr/bin/env bash
# rc2000sim refuses bad profiles, options that do not apply and unwritable outputs (issue 15;
# docs/outputs.md, "Which options apply where" and "When a command fails"; docs/board.md, "Profiles"):
# each bad input exits non-zero (1 or CLI11's 105, never a signal: 128+), says what is wrong (the
# message checked), and leaves no output file or folder behind. The good paths still exit 0 and
# leave no temporary file. Every case is refused before any solve, so the whole test takes seconds.
# usage: cli_errors_test.sh RC2000SIM REPO_ROOT
set -euo pipefail
sim="$1"
root="$2"
work="$(mktemp -d "${TMPDIR:-/tmp}/cli-errors-test.XXXXXX")"
trap 'rm -rf "$work"' EXIT
export SYSTEMC_DISABLE_COPYRIGHT_MESSAGE=1
fail() { echo "FAIL: $*" >&2; exit 1; }
cases=0

# refused OUT EXPECTED-TEXT ARGS...: rc2000sim ARGS must fail (not by a signal), say EXPECTED-TEXT on
# stderr, print no "wrote" on stdout, and leave nothing at OUT.
refused() {
  local out="$1" expected="$2"; shift 2
  local rc=0
  timeout 60 "$sim" "$@" > "$work/stdout.txt" 2> "$work/stderr.txt" || rc=$?  # a hang fails the case
  [ "$rc" -ne 0 ] || fail "accepted: $*"
  [ "$rc" -lt 128 ] || { cat "$work/stderr.txt" >&2; fail "killed by signal $((rc - 128)): $*"; }
  grep -qF -- "$expected" "$work/stderr.txt" || { cat "$work/stderr.txt" >&2; fail "'$expected' not in the error of: $*"; }
  # Numbers in messages are readable: a range's bound once came as the 309 digits of 1.8e308.
  ! grep -qE '[0-9]{25}' "$work/stderr.txt" || fail "a number of 25 digits or more in the error of: $*"
  ! grep -q "wrote" "$work/stdout.txt" || fail "says it wrote something: $*"
  [ ! -e "$out" ] || fail "left $out behind: $*"
  cases=$((cases + 1))
}

# A copy of a shipped profile with one change: profile KIND NAME OUT PYTHON-STATEMENT (on p).
profile() {
  python3 - "$root/configs/$1/$2.json" "$3" "$4" <<'PY'
import json, sys
p = json.load(open(sys.argv[1]))
exec(sys.argv[3])
json.dump(p, open(sys.argv[2], "w"), indent=2)
PY
}
device() { profile devices xc2v6000 "$work/$1.json" "$2"; }

tiny=(--face-levels 0 --patch-levels 0 --steps 3 --image-size 16 --quiet)
board=(run --impl board "${tiny[@]}")

echo "1. device and host profiles, against the limits the model derives"
device small 'p["banks"]["capacity_bytes"]["value"] = 16'
refused "$work/o" "small.json: banks.capacity_bytes = 16 is smaller than one face record and its own-face table entry (40 bytes" \
  "${board[@]}" --device "$work/small.json" --out "$work/o"
refused "$work/o" "rc2000sim run: failed: " "${board[@]}" --device "$work/small.json" --out "$work/o"
refused "$work/o" "nothing written to $work/o/" "${board[@]}" --device "$work/small.json" --out "$work/o"
refused "$work/o" "banks.capacity_bytes = 16 is smaller than one face record" \
  sweep --devices "$work/small.json" --face-levels 0 --patch-levels 0 --steps 3 --lanes 1 --banks 6 --quiet --out "$work/o"
device parts 'p["banks"]["capacity_bytes"]["value"] = 4194305'
refused "$work/o" "banks.capacity_bytes = 4194305 is not a whole number of 4-byte words" \
  "${board[@]}" --device "$work/parts.json" --out "$work/o"
device huge 'p["banks"]["capacity_bytes"]["value"] = 2**40'
refused "$work/o" "banks.capacity_bytes = 1099511627776 is larger than the wrapper can address (171798691800 bytes" \
  "${board[@]}" --device "$work/huge.json" --out "$work/o"
device lanes 'p["clock"]["mhz_by_lanes"]["2abc"] = p["clock"]["mhz_by_lanes"].pop("2")'
refused "$work/o" "lanes.json: clock.mhz_by_lanes.2abc: key must be a lane count, a whole number 1..255" \
  "${board[@]}" --device "$work/lanes.json" --lanes 2 --out "$work/o"
device typo 'p["banks"]["clock_mhzz"] = p["banks"]["clock_mhz"]'
refused "$work/o" "typo.json: banks.clock_mhzz: unknown key (known in banks:" \
  "${board[@]}" --device "$work/typo.json" --out "$work/o"
device four 'p["banks"]["count"]["value"] = 4'
refused "$work/o" "banks.count = 4 is fewer than the 5 banks the wrapper needs" \
  "${board[@]}" --device "$work/four.json" --out "$work/o"
device slow 'p["banks"]["clock_mhz"]["value"] = 0'
refused "$work/o" "slow.json: banks.clock_mhz: value 0 is outside" "${board[@]}" --device "$work/slow.json" --out "$work/o"
profile hosts athlon-mp-2600 "$work/host.json" 'p["driver_seconds"]["word_stor"] = p["driver_seconds"]["word_store"]'
refused "$work/o" "host.json: driver_seconds.word_stor: unknown key" \
  "${board[@]}" --host "$work/host.json" --out "$work/o"
printf '[[scenes]]\npaper = { faces = 70, patches = 280 }\n[axes]\ndevices = ["xc2v6000"]\n"banks.capacity_bytes" = [16]\n' \
  > "$work/capacity.toml"
refused "$work/o" "banks.capacity_bytes=16 (study $work/capacity.toml): banks.capacity_bytes = 16 is smaller than one face record" \
  sweep --study "$work/capacity.toml" --quiet --out "$work/o"

# A path that is there but is not a file; patches smaller than the splitting reaches.
refused "$work/o" "/dev/null: is a character device, not a regular file (a device profile must be one)" "${board[@]}" --device /dev/null --out "$work/o"
refused "$work/o" "--patch-size 1e-09: face 0: patches of at most 1e-09 need more than 8 levels of splitting" \
  run --patch-size 1e-9 --steps 3 --quiet --out "$work/o"

echo "2. options that do not apply"
for option in "--lanes 2" "--banks 6" "--concurrent" "--device xc2v6000" "--host athlon-mp-2600" "--trace $work/t.json" \
              "--vcd $work/v.vcd" "--cards 2" "--lanes-compute" "--lanes-impl rtl" "--resources synthesis"; do
  # shellcheck disable=SC2086  # the option and its value are two words
  refused "$work/o" "${option%% *} applies to --impl board only" run "${tiny[@]}" $option --out "$work/o"
done
refused "$work/o" "--visibility applies to --impl software only" "${board[@]}" --visibility fixed --out "$work/o"
refused "$work/o" "--lanes-impl rtl: the RTL pipeline is fixed-point; it does not apply with --arith float:5,10" \
  "${board[@]}" --lanes-impl rtl --arith float:5,10 --out "$work/o"
refused "$work/o" "--lanes-impl rtl: " "${board[@]}" --lanes-impl rtl --bits 8 --out "$work/o"  # no model at 8 bits (or no Verilator)
refused "$work/o" "--lanes-compute does not apply with --lanes-impl rtl" "${board[@]}" --lanes-impl rtl --lanes-compute --out "$work/o"
refused "$work/o" "--lanes-impl: verilog not in {cpp,rtl}" "${board[@]}" --lanes-impl verilog --out "$work/o"
refused "$work/o" "--resources applies to fixed-point lanes only" "${board[@]}" --arith float:5,10 --resources synthesis --out "$work/o"
refused "$work/o" "--resources: yosys not in {paper,synthesis}" "${board[@]}" --resources yosys --out "$work/o"
refused "$work/o" "--bits does not apply with --visibility float" run "${tiny[@]}" --bits 12 --out "$work/o"
refused "$work/o" "--fidelity-sample does not apply with --visibility float: double precision is the reference" run "${tiny[@]}" --fidelity-sample 100 --out "$work/o"
refused "$work/o" "--fidelity-warn does not apply with --fidelity-sample 0" run "${tiny[@]}" --visibility fast --fidelity-sample 0 --fidelity-warn 0.1 --out "$work/o"
refused "$work/o" "--fidelity-warn: Value 2 not in range" run "${tiny[@]}" --visibility fast --fidelity-warn 2 --out "$work/o"
refused "$work/o" "--bits does not apply with --arith float:5,10" run "${tiny[@]}" --arith float:5,10 --bits 12 --out "$work/o"
# The segment fixes (docs/radiosity.md, "Fixed-point acne and its fixes") need the fixed-point grid.
refused "$work/o" "--offset-lsb needs the fixed-point width (--bits); --visibility float" run "${tiny[@]}" --offset-lsb 2 --out "$work/o"
refused "$work/o" "--coordinate-bits needs the fixed-point width (--bits)" run "${tiny[@]}" --coordinate-bits 11 --out "$work/o"
refused "$work/o" "--neighbour-rings does not apply with --arith float:5,10" run "${tiny[@]}" --arith float:5,10 --neighbour-rings 1 --out "$work/o"
refused "$work/o" "--coordinate-bits must be below --bits (15)" run "${tiny[@]}" --visibility fast --coordinate-bits 15 --out "$work/o"
refused "$work/o" "--neighbour-rings: Value 3 not in range" run "${tiny[@]}" --visibility fast --neighbour-rings 3 --out "$work/o"
refused "$work/o" "--t-guard does not apply with --arith float:5,10" run "${tiny[@]}" --arith float:5,10 --t-guard 1 --out "$work/o"
refused "$work/o" "--t-guard needs the fixed-point width (--bits); --visibility float" run "${tiny[@]}" --t-guard 1 --out "$work/o"
refused "$work/o" "--t-guard: Value 256 not in range 0 to 255" run "${tiny[@]}" --visibility fast --t-guard 256 --out "$work/o"
refused "$work/o" "--t-guard: Value -1 not in range 0 to 255" run "${tiny[@]}" --visibility fast --t-guard -1 --out "$work/o"
refused "$work/o" "--steps must be at least 1; omit it to run to convergence" run --steps 0 --quiet --out "$work/o"
refused "$work/o" "--steps must be at least 1; omit it to run to convergence" accuracy --steps 0 --quiet --out "$work/o"
refused "$work/o" "--convergence does not apply with --steps" run --steps 5 --convergence 0.9 --quiet --out "$work/o"
refused "$work/o" "1 is not strictly between 0 and 1" run --convergence 1 --quiet --out "$work/o"
refused "$work/o" "--trace-steps applies only with --trace" "${board[@]}" --trace-steps 1:2 --out "$work/o"
refused "$work/o" "--trace-steps expects FIRST:LAST, e.g. 1:3, got '1x:3'" \
  "${board[@]}" --trace "$work/t.json" --trace-steps 1x:3 --out "$work/o"
refused "$work/o" "--card-split applies only with more than one card" "${board[@]}" --card-split faces --out "$work/o"
refused "$work/o" "--cpu-share applies to --impl board only" run "${tiny[@]}" --cpu-share 0.5 --out "$work/o"
refused "$work/o" "--cpu-cores applies only with --cpu-share" "${board[@]}" --cpu-cores 2 --out "$work/o"
refused "$work/o" "--cpu-cores does not apply with --cpu-share 0 (no CPU/FPGA split" "${board[@]}" --cpu-share 0 --cpu-cores 2 --out "$work/o"
refused "$work/o" "--cpu-share: expected a fraction 0..1 or 'balanced', got '1.5'" "${board[@]}" --cpu-share 1.5 --out "$work/o"
refused "$work/o" "--cpu-share: expected a fraction 0..1 or 'balanced', got 'half'" "${board[@]}" --cpu-share half --out "$work/o"
refused "$work/o" "--cpu-cores: expected 1 or 2" "${board[@]}" --cpu-share balanced --cpu-cores 3 --out "$work/o"
refused "$work/o" "--cpu-share a CPU/FPGA split drives one card" "${board[@]}" --cpu-share 0.5 --cards 2 --out "$work/o"
refused "$work/o" "--patch-levels does not apply to bench" bench --patch-levels 2 --quiet --out "$work/o"
refused "$work/o" "--patch-size does not apply to adaptive" adaptive --patch-size 0.1 --quiet --out "$work/o"
refused "$work/o" "--out does not apply with --list-fields" sweep --list-fields --out "$work/o"
refused "$work/o" "--lanes does not apply to sweep merge" sweep --lanes 2 merge "$work" --out "$work/o"
refused "$work/o" "--shard: expected I/N" sweep --study "$root/tests/host_sw/studies/data/small.toml" --shard 1x/3 --out "$work/o"
refused "$work/o" "--study is empty: name a study file" sweep --study "" --out "$work/o"
refused "$work/o" "--shard is empty: expected I/N" sweep --study "$root/tests/host_sw/studies/data/small.toml" --shard "" --out "$work/o"
refused "$work/o" "--lanes does not apply with --study" sweep --study "$root/tests/host_sw/studies/data/small.toml" --lanes 2 --out "$work/o"
refused "$work/o" "--resources does not apply with --study" sweep --study "$root/tests/host_sw/studies/data/small.toml" --resources synthesis --out "$work/o"
# --jobs and RC2000SIM_JOBS (docs/outputs.md, "Cores: --jobs and RC2000SIM_JOBS"): one check everywhere.
for command in paper design sweep calibrate adaptive bench accuracy; do
  refused "$work/o" "--jobs must be 1..512 (worker processes and threads; default: the " $command --jobs 0 --quiet --out "$work/o"
done
refused "$work/o" "--jobs must be 1..512 (" paper --jobs 513 --quiet --out "$work/o"
refused "$work/o" ", got -3" design --jobs -3 --quiet --out "$work/o"
refused "$work/o" "--jobs must be a whole number 1..512, got 'many'" sweep --jobs many --quiet --out "$work/o"
RC2000SIM_JOBS=0 refused "$work/o" "RC2000SIM_JOBS must be 1..512 (" paper --quiet --out "$work/o"
RC2000SIM_JOBS=two refused "$work/o" "RC2000SIM_JOBS must be a whole number 1..512, got 'two'" sweep --quiet --out "$work/o"
refused "$work/o" "--jobs applies only where the fast backend runs" run "${tiny[@]}" --jobs 2 --out "$work/o"
refused "$work/o" "--jobs applies only where the fast backend runs" "${board[@]}" --lanes-compute --jobs 2 --out "$work/o"
refused "$work/o" "--jobs does not apply with --list-fields" sweep --list-fields --jobs 2
refused "$work/o" "--jobs does not apply to sweep merge" sweep --jobs 2 merge "$work" --out "$work/o"

echo "3. outputs that cannot be written: refused before any work, nothing written, no 'wrote'"
refused "$work/nothing" "/dev/full: exists and is not a regular file; not replaced" \
  calibrate --out /dev/full --variants-out "$work/nothing/v.json" --quiet
touch "$work/file"
refused "$work/file/x.json" "$work/file/x.json: cannot be written: $work/file is not a folder" \
  calibrate --out "$work/file/x.json" --variants-out "$work/file/v.json" --quiet
refused "$work/file/o" "is not a folder; nothing written to $work/file/o/" run "${tiny[@]}" --out "$work/file/o"
refused "$work/o" "$work/o/report.json: named twice among this command's outputs" \
  "${board[@]}" --trace "$work/o/report.json" --out "$work/o"
mkdir "$work/t"
refused "$work/o" "$work/t: exists and is not a regular file; not replaced" "${board[@]}" --trace "$work/t" --out "$work/o"
rmdir "$work/t"
# An empty output path was joined into "/patches.csv", at the file system's root.
for command in run accuracy sweep paper bench adaptive design; do
  refused "$work/nothing" "--out: is empty: name a folder or file to write" "$command" --quiet --out ""
done
refused "$work/nothing" "--variants-out: is empty" calibrate --quiet --variants-out ""
refused "$work/nothing" "--docs: is empty" paper --quiet --docs ""
refused "$work/o" "--trace: is empty" "${board[@]}" --trace "" --out "$work/o"
refused "$work/o" "--vcd: is empty" "${board[@]}" --vcd "" --out "$work/o"

echo "4. round three (docs/reliability.md, \"Round three: commands\"): numbers, profiles, studies, shards, cameras"
refused "$work/o" "--patch-size: 'nan' is not a finite number" run --patch-size nan --quiet --out "$work/o"
refused "$work/o" "--patch-size: 'inf' is not a finite number" run --patch-size inf --quiet --out "$work/o"
refused "$work/o" "--patch-size: -1e+308 must be positive" run --patch-size -1e308 --quiet --out "$work/o"
refused "$work/o" "--patch-size: 'nan' is not a finite number" sweep --patch-size nan --quiet --out "$work/o"
refused "$work/o" "--faces: must be at least 1 (the number of faces to refine to); omit it" run --faces 0 --quiet --out "$work/o"
refused "$work/o" "--faces: must be at least 1" sweep --faces 0 --quiet --out "$work/o"
refused "$work/o" "--banks: Value 0 not in range 1 to 64" "${board[@]}" --banks 0 --out "$work/o"
device burst 'p["pci"]["max_burst_bytes"]["value"] = 2**32'
refused "$work/o" "burst.json: pci.max_burst_bytes: value 4294967296 is outside [8, 4294967295]" \
  "${board[@]}" --device "$work/burst.json" --out "$work/o"
# No default clock, a clock for one lane only: a one-lane run works (sec 5.6's estimate, which
# would ask for more lanes, says why it is missing); a two-lane run is refused naming file and key.
device noclock 'p["clock"].pop("mhz_default"); p["clock"]["mhz_by_lanes"] = {"1": p["clock"]["mhz_by_lanes"]["1"]}'
"$sim" "${board[@]}" --device "$work/noclock.json" --out "$work/noclock" > "$work/stdout.txt" || fail "a one-lane run on a profile with a one-lane clock failed"
grep -q "not estimated: $work/noclock.json: clock.mhz_by_lanes.2: missing" "$work/noclock/report.json" || fail "report.json does not say why sec 5.6 is not estimated"
refused "$work/o" "noclock.json: clock.mhz_by_lanes.2: missing: device profile xc2v6000 gives no clock for 2 lanes" \
  "${board[@]}" --device "$work/noclock.json" --lanes 2 --out "$work/o"
device samename 'p["description"] = "an edited copy, not renamed"'
refused "$work/o" "two device profiles are named 'xc2v6000': $root/configs/devices/xc2v6000.json and $work/samename.json" \
  sweep --devices "xc2v6000,$work/samename.json" --lanes 1 --banks 6 --steps 3 --quiet --out "$work/o"
# A study's device paths lie beside the study, as its scenes do: run from another folder.
mkdir -p "$work/study/profiles"
device study/profiles/renamed 'p["name"] = "renamed"'
printf '[[scenes]]\npaper = { faces = 70, patches = 280 }\n[axes]\ndevices = ["profiles/renamed.json"]\nlanes = [1]\nbanks = [6]\n' \
  > "$work/study/s.toml"
(cd / && "$sim" sweep --study "$work/study/s.toml" --list-fields > "$work/stdout.txt") || fail "a study's device path did not resolve beside the study"
grep -qF "device profile $work/study/profiles/renamed.json" "$work/stdout.txt" || fail "the study read another device profile"
# A field of view below 1e-3 degrees (1e-300 gave an all-black picture, exit 0).
sed 's/ 45$/ 1e-300/' "$root/scenes/examples/two-rooms.scene" > "$work/narrow.scene"
refused "$work/o" "narrow.scene:19: camera vertical field of view 1e-300 degrees is outside [0.001, 180)" \
  run --scene "$work/narrow.scene" --quiet --out "$work/o"
# Emission in any unit gives a picture (1e-10 gave an all-black one): emission scaled by 2^-30 and
# by 2^-50 gives the same PNG byte for byte, and it is not black.
for e in 30 50; do
  k=$(python3 -c "print(10 * 2**-$e)")
  sed "s/emission 10 10 10/emission $k $k $k/" "$root/scenes/examples/two-rooms.scene" > "$work/dim$e.scene"
  "$sim" run --scene "$work/dim$e.scene" --steps 20 --image-size 32 --quiet --out "$work/dim$e" > /dev/null || fail "the dim scene failed"
done
cmp -s "$work/dim30/image.png" "$work/dim50/image.png" || fail "the picture depends on the scene's unit of emission"
python3 - "$work/dim50/image.png" <<'PY' || fail "the dim scene's picture is black"
import sys, zlib
data = open(sys.argv[1], "rb").read()
pos, idat, width = 8, b"", 0
while pos < len(data):  # PNG chunks: length, type, data, CRC
    n = int.from_bytes(data[pos:pos + 4], "big")
    kind, body = data[pos + 4:pos + 8], data[pos + 8:pos + 8 + n]
    if kind == b"IHDR":
        width = int.from_bytes(body[:4], "big")
        assert body[8:10] == bytes([8, 2]) and body[12] == 0, "expected 8-bit RGB, not interlaced"
    elif kind == b"IDAT":
        idat += body
    pos += 12 + n
raw, stride, previous, pixels = zlib.decompress(idat), 3 * width, bytearray(3 * width), []
for start in range(0, len(raw), stride + 1):  # undo each row's filter (PNG spec, section 9)
    kind, row = raw[start], bytearray(raw[start + 1:start + 1 + stride])
    for i in range(stride):
        a = row[i - 3] if i >= 3 else 0
        b, c = previous[i], previous[i - 3] if i >= 3 else 0
        p = a + b - c
        paeth = a if abs(p - a) <= abs(p - b) and abs(p - a) <= abs(p - c) else b if abs(p - b) <= abs(p - c) else c
        row[i] = (row[i] + [0, a, b, (a + b) // 2, paeth][kind]) & 255
    pixels += row
    previous = row
mean = sum(pixels) / len(pixels)
print(f"   the dim scene's picture: mean grey level {mean:.0f} of 255")
sys.exit(0 if mean > 20 else 1)
PY
# Calibration on a one-row table: two runs cannot pin five cost groups; the fit sets some to 0 and is
# refused, after the variants are printed with the table's run count (it said "all 16 runs").
python3 - "$root/configs/paper-table2.json" "$work/one-row.json" <<'PY'
import json, sys
t = json.load(open(sys.argv[1]))
t["scenes"] = t["scenes"][:1]
json.dump(t, open(sys.argv[2], "w"))
PY
refused "$work/cal" "one-row.json: variant per_segment/dma/once/form_factors: the fit sets every cost of group step to 0 s" \
  calibrate --table "$work/one-row.json" --out "$work/cal/host.json" --variants-out "$work/cal/variants.json" --quiet
grep -q "fit to all 2 runs" "$work/stdout.txt" || fail "calibrate does not print the table's run count"
# Shards whose rows hold figures no run produces are refused by merge, naming the row and key.
"$sim" sweep --study "$root/tests/host_sw/studies/data/small.toml" --shard 0/1 --quiet --out "$work/shards" > /dev/null || fail "a shard failed"
for bad in -1 1e308; do
  python3 - "$work/shards/shard-0-of-1.json" "$work/bad/shard-0-of-1.json" "$bad" <<'PY'
import json, os, sys
j = json.load(open(sys.argv[1]))
row = next(r for g in j["groups"] for r in g["rows"] if r["status"] == "ok")
row["simulated_seconds"] = float(sys.argv[3])
os.makedirs(os.path.dirname(sys.argv[2]), exist_ok=True)
json.dump(j, open(sys.argv[2], "w"))
PY
  refused "$work/o" "shard-0-of-1.json: row xc2v6000 15-bit concurrent 1 lane 6 banks" sweep merge "$work/bad" --quiet --out "$work/o"
  grep -qE "simulated_seconds = (-1.0 is not a figure a run produces|1e\+308 is outside \(0, 1e\+12\])" "$work/stderr.txt" \
    || fail "merge does not name simulated_seconds = $bad"
done
"$sim" sweep merge "$work/shards" --quiet --out "$work/merged" > /dev/null || fail "the unedited shard does not merge"

echo "5. good paths still work and leave no temporary file"
"$sim" run "${tiny[@]}" --out "$work/soft" > /dev/null || fail "a software run failed"
"$sim" "${board[@]}" --lanes 2 --trace "$work/board/trace.json" --vcd "$work/board/signals.vcd" --out "$work/board" \
  > "$work/stdout.txt" || fail "a board run failed"
grep -q "wrote .*report.json" "$work/stdout.txt" || fail "the board run does not say what it wrote"
for f in soft/report.json soft/patches.csv soft/image.png board/report.json board/trace.json board/signals.vcd; do
  [ -s "$work/$f" ] || fail "$f missing or empty"
done
python3 -c "import json, sys; r = json.load(open(sys.argv[1])); sys.exit(r['settings']['bits'] is not None)" \
  "$work/soft/report.json" || fail "a float-visibility run records a fractional width"
! find "$work" -name '*.partial-*' | grep -q . || fail "a temporary file was left: $(find "$work" -name '*.partial-*')"
"$sim" sweep --devices xc2v6000 --face-levels 0 --patch-levels 0 --steps 3 --lanes 1-2 --banks 6 --quiet \
  --out "$work/sweep" > /dev/null || fail "a sweep failed"
[ -s "$work/sweep/sweep.csv" ] && [ -s "$work/sweep/study.json" ] || fail "the sweep wrote no sweep.csv or study.json"
# --jobs where the fast backend runs, and a good RC2000SIM_JOBS, are taken.
"$sim" run --visibility fast "${tiny[@]}" --jobs 1 --out "$work/jobs" > /dev/null || fail "run --visibility fast --jobs 1 failed"
RC2000SIM_JOBS=1 "$sim" run --impl board "${tiny[@]}" --out "$work/jobs-env" > /dev/null || fail "a run with RC2000SIM_JOBS=1 failed"
# A room beside a mesh ten million units away: at 15 bits the room's faces have no area on the grid
# and would block nothing, silently; the run warns on stderr and in report.json.
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n' > "$work/tetra.obj"
printf '{"schema": "rc2000sim.composition/1", "room": "cornell-box", "meshes": [{"file": "tetra.obj", "translate": [1e7, 0, 0]}]}' \
  > "$work/far.json"
"$sim" run --scene "$work/far.json" --visibility fixed --steps 1 --image-size 16 --quiet --out "$work/far" \
  2> "$work/stderr.txt" > /dev/null || fail "the far-mesh run failed"
grep -q "faces (the first: face .*) have no area on the 2^-15 grid" "$work/stderr.txt" || fail "no warning of faces lost at 15 bits"
grep -q "have no area on the 2^-15 grid" "$work/far/report.json" || fail "report.json does not carry the warning"
"$sim" run --scene "$work/far.json" --steps 1 --image-size 16 --quiet --out "$work/far-float" 2> "$work/stderr.txt" > /dev/null
! grep -q "have no area" "$work/stderr.txt" || fail "a double-precision run warns of a fixed-point grid"
# Special files and foreign text (docs/reliability.md, round three). A FIFO anywhere used to block
# forever: each is refused by name at once (timeout: a hang fails the test instead of stalling it).
mkfifo "$work/in.fifo"
fifo="$work/in.fifo: is a named pipe (FIFO), not a regular file"
refused "$work/o" "$fifo (a scene file must be one)" run --scene "$work/in.fifo" --steps 1 --quiet --out "$work/o"
refused "$work/o" "$fifo (a study file must be one)" sweep --study "$work/in.fifo" --quiet --out "$work/o"
refused "$work/o" "$fifo (a device profile must be one)" run --impl board --device "$work/in.fifo" --steps 1 --quiet --out "$work/o"
refused "$work/o" "$fifo (the paper's Table 2 data must be one)" paper --table "$work/in.fifo" --out "$work/o"
refused "$work/o" "$fifo (a variants file must be one)" paper --variants "$work/in.fifo" --out "$work/o"
printf '{"schema": "rc2000sim.composition/1", "room": {"file": "in.fifo"}}' > "$work/fifo-room.json"
refused "$work/o" "$fifo (a scene file must be one)" run --scene "$work/fifo-room.json" --steps 1 --quiet --out "$work/o"
# A composition with a key twice, a comment, or 200,000 levels of nesting (a crash before).
printf '{"schema": "rc2000sim.composition/1",\n "meshes": [],\n "meshes": []}' > "$work/twice.json"
refused "$work/o" "$work/twice.json: line 3: key \"meshes\" given twice in the top level (first on line 2)" \
  run --scene "$work/twice.json" --steps 1 --quiet --out "$work/o"
python3 -c 'import sys; open(sys.argv[1], "w").write("[" * 200000 + "]" * 200000)' "$work/deep.json"
refused "$work/o" "$work/deep.json: line 1: nested deeper than the limit of 64" run --scene "$work/deep.json" --steps 1 --quiet --out "$work/o"
# --scene <(...) is read once (it used to say "has no faces").
"$sim" run --scene <(cat "$root/scenes/examples/two-rooms.scene") --steps 2 --image-size 16 --quiet --out "$work/piped" \
  > /dev/null || fail "a scene through process substitution failed"
[ -s "$work/piped/report.json" ] || fail "the piped run wrote no report.json"
# A Latin-1 material name in an MTL: the run finishes and report.json holds it escaped (it used to fail
# with type_error.316 after the solve and write nothing).
printf 'newmtl caf\xe9\nKd 0.5 0.5 0.5\nKe 1 1 1\n' > "$work/latin1.mtl"
printf 'mtllib latin1.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nusemtl caf\xe9\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n' > "$work/latin1.obj"
printf '{"schema": "rc2000sim.composition/1", "meshes": [{"file": "latin1.obj", "scale": 100, "translate": [278, 100, 279]}]}' \
  > "$work/latin1.json"
"$sim" run --scene "$work/latin1.json" --steps 2 --image-size 16 --quiet --out "$work/latin1" > /dev/null 2>&1 ||
  fail "the run with a Latin-1 material name failed"
python3 -c 'import json, sys; json.load(open(sys.argv[1], encoding="utf-8"))' "$work/latin1/report.json" ||
  fail "report.json of the Latin-1 run is not UTF-8 JSON"
echo "PASS: $cases refusals, each with its message and nothing written; the good paths write their files"
