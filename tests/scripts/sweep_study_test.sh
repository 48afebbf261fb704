#!/usr/bin/env bash
# rc2000sim sweep --study end to end (docs/studies.md), on this machine alone:
#  1. the default study file reproduces docs/results/sweep/default/sweep.csv byte for byte, and so
#     does `rc2000sim sweep` without options;
#  2. a profile-path axis means exactly what editing the profile means: the study's rows for
#     banks.clock_mhz = 133 (with pci.clock_mhz fixed at 33.333) are the rows of a sweep of a copy
#     of the device profile with those two values, but for the axis's own column;
#  3. shards run one after another and merged are the single-machine outputs, byte for byte;
#  4. several cards are an axis, and one card's row is the plain sweep's;
#  5. bad studies and options fail with the file, line, key or option named;
#  6. a study over several scenes writes study.csv: every scene folder's sweep.csv rows, in order,
#     behind a first column `scene` (its folder's name).
# usage: sweep_study_test.sh RC2000SIM REPO_ROOT
set -euo pipefail
sim="$1"
root="$2"
work="$(mktemp -d "${TMPDIR:-/tmp}/sweep-study-test.XXXXXX")"
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
step() { echo "[$(date +%T)] $*"; }

step "1. the default study reproduces docs/results/sweep/default/sweep.csv"
"$sim" sweep --study "$root/configs/studies/default.toml" --quiet --out "$work/default" > /dev/null
cmp "$work/default/sweep.csv" "$root/docs/results/sweep/default/sweep.csv" || fail "default study: sweep.csv differs from docs/results/sweep/default"
"$sim" sweep --quiet --out "$work/default-cli" > /dev/null
cmp "$work/default-cli/sweep.csv" "$work/default/sweep.csv" || fail "rc2000sim sweep without options differs from the default study"

step "2. a profile-path axis is the profile edited"
cat > "$work/axis.toml" <<'TOML'
[[scenes]]
paper = { faces = 70, patches = 280 }
[solver]
steps = 30
[axes]
devices = ["xc2v6000"]
lanes = "1-3"
banks = [6, 9]
concurrent = "both"
"banks.clock_mhz" = [100, 133]  # quoted: banks is also the bank-count axis
[fixed]
"pci.clock_mhz" = 33.333
TOML
"$sim" sweep --study "$work/axis.toml" --quiet --out "$work/axis" > /dev/null
python3 - "$root/configs/devices/xc2v6000.json" "$work/edited.json" <<'PY'
import json, sys
profile = json.load(open(sys.argv[1]))
profile["banks"]["clock_mhz"]["value"] = 133
profile["pci"]["clock_mhz"]["value"] = 33.333
json.dump(profile, open(sys.argv[2], "w"), indent=2)
PY
"$sim" sweep --devices "$work/edited.json" --faces 70 --face-levels 0 --patch-levels 1 --steps 30 --lanes 1-3 \
  --banks 6,9 --concurrent both --quiet --out "$work/edited" > /dev/null
python3 - "$work/axis/sweep.csv" "$work/edited/sweep.csv" <<'PY'
import csv, sys
axis = list(csv.DictReader(open(sys.argv[1])))
edited = list(csv.DictReader(open(sys.argv[2])))
picked = [dict(r) for r in axis if r["banks.clock_mhz"] == "133"]
for r in picked:
    del r["banks.clock_mhz"]
# The speedup over software is taken against the same software time in both; everything else is the run's own.
if picked != edited:
    for a, b in zip(picked, edited):
        if a != b:
            print("first different row:\n  study: ", a, "\n  edited:", b)
            break
    sys.exit("the study's banks.clock_mhz=133 rows differ from the edited profile's rows")
if len(picked) != 12 or not any(r["status"] == "ok" for r in picked):
    sys.exit("expected 12 rows, some simulated, got %d" % len(picked))
slower = [r for r in axis if r["banks.clock_mhz"] == "100" and r["status"] == "ok"]
print("  %d rows identical; 133 MHz banks: %s s, 100 MHz: %s s (2 lanes, 6 banks, serial)" % (
    len(picked), next(r["simulated_seconds"] for r in picked if r["lanes"] == "2" and r["banks"] == "6"),
    next(r["simulated_seconds"] for r in slower if r["lanes"] == "2" and r["banks"] == "6")))
PY
[ -f "$work/axis/axis_banks.clock_mhz.png" ] || fail "no axis plot"

step "3. shards one after another, merged, are the single-machine outputs"
for i in 0 1 2; do "$sim" sweep --study "$work/axis.toml" --shard "$i/3" --quiet --out "$work/shards" > /dev/null; done
"$sim" sweep merge "$work/shards" --out "$work/merged" --quiet > /dev/null
diff -r "$work/axis" "$work/merged" || fail "merged shards differ from the single-machine outputs"
echo "  identical: $(find "$work/merged" -type f | wc -l) files"

step "4. several cards are an axis; one card's rows are the plain sweep's"
"$sim" sweep --faces 70 --face-levels 0 --patch-levels 1 --steps 30 --lanes 2 --banks 6 --devices xc2v6000 \
  --cards 1,2 --card-split rays,faces --card-bus shared,separate --quiet --out "$work/cards" > /dev/null
"$sim" sweep --faces 70 --face-levels 0 --patch-levels 1 --steps 30 --lanes 2 --banks 6 --devices xc2v6000 \
  --quiet --out "$work/one-card" > /dev/null
python3 - "$work/cards/sweep.csv" "$work/one-card/sweep.csv" <<'PY'
import csv, sys
cards = list(csv.DictReader(open(sys.argv[1])))
one = list(csv.DictReader(open(sys.argv[2])))
if len(cards) != 5 or [r["cards"] for r in cards] != ["1", "2", "2", "2", "2"]:
    sys.exit("expected 1 one-card row and 4 two-card rows, got %s" % [r["cards"] for r in cards])
first = dict(cards[0])
for k in ("cards", "card_split", "card_bus"):
    if k == "cards" or first[k] == "":
        del first[k]
    else:
        sys.exit("the one-card row has a %s: %s" % (k, first[k]))
# Whether a row is on the time-energy Pareto front depends on the rows beside it (two cards may beat it).
for row in (first, one[0]):
    del row["pareto_time_energy"]
if first != one[0]:
    sys.exit("the one-card row differs from the plain sweep's:\n %s\n %s" % (first, one[0]))
if not all(r["status"] == "ok" for r in cards):
    sys.exit("a card configuration did not run")
print("  two cards: " + ", ".join("%s/%s %s s" % (r["card_split"], r["card_bus"], r["simulated_seconds"]) for r in cards[1:]))
PY

step "5. bad studies and options name what is wrong"
expect_error() {  # EXPECTED-TEXT ARGS...: rc2000sim must fail and say EXPECTED-TEXT
  local expected="$1"; shift
  if "$sim" "$@" > "$work/out.txt" 2> "$work/err.txt"; then fail "accepted: $*"; fi
  grep -qF -- "$expected" "$work/err.txt" || { cat "$work/err.txt" >&2; fail "'$expected' not in the error of: $*"; }
}
printf '[axes]\n"banks.clok_mhz" = [1]\n' > "$work/bad.toml"
expect_error "bad.toml:2: axes.banks.clok_mhz" sweep --study "$work/bad.toml" --out "$work/bad"
expect_error "fields there: banks.count, banks.capacity_bytes" sweep --study "$work/bad.toml" --out "$work/bad"
expect_error "--lanes does not apply with --study" sweep --study "$work/axis.toml" --lanes 1-2 --out "$work/bad"
expect_error "--shard: expected I/N" sweep --study "$work/axis.toml" --shard 3 --out "$work/bad"
expect_error "I counts from 0" sweep --study "$work/axis.toml" --shard 3/3 --out "$work/bad"
rm "$work/shards/shard-1-of-3.json"
expect_error "1 of 3 shards are missing: 1" sweep merge "$work/shards" --out "$work/bad"
expect_error "no shard files" sweep merge "$work/axis" --out "$work/bad"
[ ! -e "$work/bad" ] || fail "a failed run left $work/bad behind"
step "6. a study over several scenes: one table with a scene column"
"$sim" sweep --study "$root/tests/host_sw/studies/data/small.toml" --quiet --out "$work/scenes" > /dev/null
python3 - "$work/scenes" <<'PY'
import csv, json, os, sys
out = sys.argv[1]
combined = list(csv.reader(open(os.path.join(out, "study.csv"))))
want, header = [], None
scene_dirs = [d for d in os.listdir(out) if os.path.isfile(os.path.join(out, d, "sweep.csv"))]
order = []
for row in combined[1:]:
    if row[0] not in order:
        order.append(row[0])
if sorted(order) != sorted(scene_dirs) or len(order) < 2:
    sys.exit("scenes in study.csv %s, folders %s" % (order, scene_dirs))
for name in order:
    rows = list(csv.reader(open(os.path.join(out, name, "sweep.csv"))))
    header = header or rows[0]
    if rows[0] != header:
        sys.exit("scene %s has other columns" % name)
    want += [[name] + r for r in rows[1:]]
if combined[0] != ["scene"] + header or combined[1:] != want:
    sys.exit("study.csv is not the scenes' sweep.csv rows behind their scene")
print("  study.csv: %d rows from %s" % (len(want), ", ".join(order)))
PY

echo PASS
