#!/usr/bin/env bash
# Output folders own their files, and what writes and reads them (issue 39; docs/outputs.md, "Output
# folders own their files"):
#   1. run, sweep (a study of two scenes named "007" and "1e3"), design, design with no best, run
#      again, all into one folder beside a file of the user's: after each command the folder holds
#      its outputs (as its rc2000sim-outputs.txt lists them), the user's file and nothing of the
#      earlier commands; Python's load() returns that command's outputs, a scene named "007" as text;
#   2. the check before any work finds what the write would hit: --out a dangling symbolic link, a
#      loop of links, a file where a folder must be; nothing is computed or written;
#   3. shards of one study into one folder add to its listing; shards run with different contents of
#      one profile name are refused by merge, naming the profile and both shards;
#   4. load() of a damaged JSON or CSV names the file and the line;
#   5. wording: --exhaustive prunes nothing and says so; a printed command carries --patch-size 0.2;
#      a sweep without a one-lane row prints no "nanx"; no design meeting the limits says why (a
#      profile without an energy table, a limit met by none).
#   output_folders_test.sh RC2000SIM SOURCE_DIR
set -euo pipefail
sim="$1"; root="$2"
work="$(mktemp -d)"; trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
export PYTHONPATH="$root/python" SYSTEMC_DISABLE_COPYRIGHT_MESSAGE=1
o="$work/o"
mkdir -p "$o"
echo "mine" > "$o/notes.txt"
tiny=(--faces 70 --patch-levels 0 --steps 3 --quiet)

# The folder holds exactly the listed files, the listing and the user's notes.
owns() {  # COMMAND WHAT-LOAD-RETURNS
  python3 - "$o" "$1" "$2" <<'PY'
import os, sys
folder, command, kind = sys.argv[1:4]
import rc2000tlm
listing = open(os.path.join(folder, "rc2000sim-outputs.txt")).read().splitlines()
assert "command " + command in listing, listing[:3]
listed = {l[5:] for l in listing if l.startswith("file ")}
present = {os.path.relpath(os.path.join(d, f), folder) for d, _, fs in os.walk(folder) for f in fs}
extra = present - listed - {"rc2000sim-outputs.txt", "notes.txt"}
missing = listed - present
if extra or missing:
    sys.exit("after %s: files of no listing %s, listed but absent %s" % (command, sorted(extra), sorted(missing)))
assert open(os.path.join(folder, "notes.txt")).read() == "mine\n", "the user's file changed"
loaded = rc2000tlm.load(folder)
assert type(loaded).__name__ == kind, (command, type(loaded).__name__)
print("  %s: %d files listed, load() gives %s" % (command, len(listed), kind))
PY
}

echo "1. run, sweep, design, design without a best, run: one folder"
"$sim" run "${tiny[@]}" --out "$o" > /dev/null
owns run RunResult
cat > "$work/names.toml" <<'TOML'
name = "names"
[[scenes]]
name = "007"
paper = { faces = 70, patches = 280 }
[[scenes]]
name = "1e3"
paper = { faces = 70, patches = 280 }
[solver]
steps = 3
[axes]
devices = ["xc2v6000"]
bits = [15]
concurrent = "on"
lanes = [1, 2]
banks = [6]
TOML
"$sim" sweep --study "$work/names.toml" --quiet --out "$o" > /dev/null
owns sweep SweepResult
[ ! -e "$o/report.json" ] && [ ! -e "$o/image.png" ] || fail "the run's files stayed beside the sweep's"
python3 - "$o" <<'PY'
import sys, rc2000tlm
rows = rc2000tlm.load(sys.argv[1]).rows
assert [r["scene"] for r in rows] == ["007", "007", "1e3", "1e3"], [r["scene"] for r in rows]
assert all(isinstance(r["lanes"], int) and isinstance(r["simulated_seconds"], float) for r in rows), rows[0]
print("  load(): scenes", sorted({r["scene"] for r in rows}), "stay text; lanes and seconds are numbers")
PY
space=(--faces 70 --patch-levels 0 --steps 5 --lanes 1-2 --max-banks 6 --quiet)
"$sim" design "${space[@]}" --out "$o" > /dev/null
owns design DesignResult
[ -e "$o/best-device.json" ] || fail "design wrote no best-device.json"
[ ! -e "$o/study.csv" ] && [ ! -d "$o/007" ] || fail "the sweep's files stayed beside the design's"
"$sim" design "${space[@]}" --max-power 0.001 --out "$o" > "$work/capped.txt"
owns design DesignResult
[ ! -e "$o/best-device.json" ] || fail "the earlier design's best-device.json stayed beside a design without a best"
python3 -c "import sys, rc2000tlm; assert rc2000tlm.load(sys.argv[1]).best_device is None" "$o"
"$sim" run "${tiny[@]}" --out "$o" > /dev/null
owns run RunResult

echo "2. the check before the work finds what the write would hit"
ln -s "$work/nowhere/deeper" "$work/dangling"
if "$sim" run "${tiny[@]}" --out "$work/dangling" 2> "$work/err.txt"; then fail "--out a dangling link was accepted"; fi
grep -q "$work/dangling is a symbolic link to $work/nowhere/deeper, which does not exist" "$work/err.txt" ||
  fail "the dangling link is not named: $(cat "$work/err.txt")"
ln -s "$work/loop" "$work/loop"
if "$sim" run "${tiny[@]}" --out "$work/loop/x" 2> "$work/err.txt"; then fail "--out through a loop of links was accepted"; fi
grep -q "$work/loop is a symbolic link" "$work/err.txt" || fail "the loop is not named: $(cat "$work/err.txt")"
if "$sim" run "${tiny[@]}" --out "$o/notes.txt/sub" 2> "$work/err.txt"; then fail "--out under a file was accepted"; fi
grep -q "$o/notes.txt is not a folder" "$work/err.txt" || fail "the file on the way is not named: $(cat "$work/err.txt")"
grep -q "nothing written" "$work/err.txt" || fail "the refusal does not say nothing was written"
[ ! -e "$work/nowhere" ] || fail "a refused run made a folder"

echo "3. shards: one folder adds them up; other contents of one profile name are refused"
cp "$root/configs/devices/xc2v6000.json" "$work/board.json"
one=(--devices "$work/board.json" --faces 70 --patch-levels 0 --steps 3 --lanes 1-2 --banks 6 --concurrent on --quiet)
"$sim" sweep "${one[@]}" --shard 0/2 --out "$work/shards" > /dev/null
"$sim" sweep "${one[@]}" --shard 1/2 --out "$work/shards" > /dev/null
[ -e "$work/shards/shard-0-of-2.json" ] && [ -e "$work/shards/shard-1-of-2.json" ] || fail "a shard removed the other"
"$sim" sweep merge "$work/shards" --quiet --out "$work/shards" > /dev/null
[ -e "$work/shards/shard-0-of-2.json" ] && [ -e "$work/shards/sweep.csv" ] || fail "merging into the shards' folder removed them"
python3 - "$work/board.json" <<'PY'
import json, sys
p = json.load(open(sys.argv[1]))
p["pci"]["clock_mhz"]["value"] = 33.333
json.dump(p, open(sys.argv[1], "w"), indent=2)
PY
"$sim" sweep "${one[@]}" --shard 1/2 --out "$work/edited" > /dev/null
cp "$work/shards/shard-0-of-2.json" "$work/edited/"
if "$sim" sweep merge "$work/edited" --quiet --out "$work/merged" 2> "$work/err.txt"; then fail "shards of other profile contents merged"; fi
grep -q "device profile '$work/board.json' held other contents when $work/edited/shard-1-of-2.json ran" "$work/err.txt" ||
  fail "the merge refusal does not name the profile and the shards: $(cat "$work/err.txt")"
[ ! -e "$work/merged" ] || fail "a refused merge wrote $work/merged"

echo "4. load() of a damaged file names it"
"$sim" run "${tiny[@]}" --out "$work/damaged" > /dev/null
head -c 300 "$o/report.json" > "$work/damaged/report.json"
python3 - "$work/damaged" <<'PY'
import sys, rc2000tlm
try:
    rc2000tlm.load(sys.argv[1])
except rc2000tlm.OutputError as e:
    assert "report.json: line" in str(e) and "not valid JSON" in str(e), str(e)
    print("  ", e)
else:
    sys.exit("a cut report.json loaded")
PY
"$sim" sweep "${one[@]}" --out "$work/cut" > /dev/null
printf '1,2\n' >> "$work/cut/sweep.csv"
python3 - "$work/cut" <<'PY'
import sys, rc2000tlm
try:
    rc2000tlm.load(sys.argv[1])
except rc2000tlm.OutputError as e:
    assert "sweep.csv: line 4: 2 fields where the header has" in str(e), str(e)
    print("  ", e)
else:
    sys.exit("a damaged sweep.csv loaded")
PY

echo "5. wording"
"$sim" design --faces 70 --patch-size 0.2 --steps 5 --lanes 1-2 --max-banks 6 --quiet --exhaustive --out "$work/all" > "$work/all.txt"
grep -q "none pruned (--exhaustive)" "$work/all.txt" || fail "--exhaustive reports pruning: $(grep designs "$work/all.txt")"
grep -q -- "--patch-size 0.2 " "$work/all.txt" || fail "the printed command's patch size: $(grep 'run:' "$work/all.txt")"
grep -q "0.20000000000000001" "$work/all.txt" "$work/all/design.json" "$work/all/design.md" && fail "a printed number in 17 digits"
"$sim" sweep --devices xc2v6000 --faces 70 --patch-levels 0 --steps 3 --lanes 2-3 --banks 6 --concurrent on --out "$work/two" > "$work/two.txt"
grep -q "nanx" "$work/two.txt" && fail "the summary prints nanx: $(grep fastest "$work/two.txt")"
grep -q "no one-lane design in its group to compare" "$work/two.txt" || fail "the summary does not say why: $(grep fastest "$work/two.txt")"
grep -q "met by 0 of" "$work/capped.txt" || fail "no design meeting --max-power does not say why: $(cat "$work/capped.txt")"
python3 - "$root/configs/devices/xc2v6000.json" "$work/noenergy.json" <<'PY'
import json, sys
p = json.load(open(sys.argv[1]))
p.pop("energy", None)
json.dump(p, open(sys.argv[2], "w"), indent=2)
PY
"$sim" design --device "$work/noenergy.json" "${space[@]}" --max-energy 100 --out "$work/noenergy" > "$work/noenergy.txt"
grep -q "no energy figure: the profile has no energy table" "$work/noenergy.txt" ||
  fail "a limit on a figure the profile cannot give is not named: $(cat "$work/noenergy.txt")"
echo "PASS: output folders own their files; the checks, merges, loads and words as above"
