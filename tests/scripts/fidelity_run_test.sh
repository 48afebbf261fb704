#!/usr/bin/env bash
# Issue 37, item 1: every run in the pipeline's arithmetic says its fidelity. A 15-bit board run of the
# duck in the box prints the share of differing decisions and warns with the cause it found;
# report.json carries the same figures; the box at 15 bits stays below the threshold; a double-
# precision run has no fidelity section. Seconds.
set -euo pipefail
sim="$1"; root="$2"
work="$(mktemp -d)"; trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
duck=/usr/share/assimp/models/Collada/duck.dae
if [ ! -e "$duck" ]; then echo "SKIP: $duck is missing (assimp-testmodels)"; exit 77; fi

"$sim" run --impl board --scene "$root/configs/scenes/cornell-duck.json" --patch-levels 0 --quiet --out "$work/duck" \
  > "$work/duck.out" 2> "$work/duck.err"
grep -q "^  fidelity .* of visibility decisions differ from double precision (95%: " "$work/duck.out" ||
  { cat "$work/duck.out"; fail "no fidelity line in the duck's summary"; }
grep -q "warning: the picture is not faithful: .*(fixed:15).*too small for the width" "$work/duck.err" ||
  { cat "$work/duck.err"; fail "no fidelity warning naming the cause"; }
python3 - "$work/duck/report.json" "$work/duck.out" <<'PY'
import json, re, sys
r = json.load(open(sys.argv[1]))["fidelity"]
line = [l for l in open(sys.argv[2]) if l.startswith("  fidelity")][0]
assert r["arithmetic"] == "fixed:15", r
assert r["sampled"] == 4096 and r["segments"] > r["sampled"] and not r["exact"], r
assert r["decisions_differ"] == r["false_shadows"] + r["missing_shadows"], r
assert abs(r["share_differ"] - r["decisions_differ"] / r["sampled"]) < 1e-15, r
assert r["share_differ_low"] < r["share_differ"] < r["share_differ_high"], r
assert r["share_differ"] > r["warn_share"] == 0.01 and r["warning"], r
causes = sum(r["false_shadow_causes"].values()) + sum(r["missing_shadow_causes"].values())
assert causes == r["decisions_differ"], r
shown = float(re.search(r"fidelity\s+([0-9.]+)%", line).group(1))
assert abs(shown - 100 * r["share_differ"]) < 0.051, (shown, r["share_differ"])
print("duck at 15 bits:", r["decisions_differ"], "of", r["sampled"], "differ;", r["warning"][:60], "...")
PY

"$sim" run --impl board --quiet --out "$work/box" > "$work/box.out" 2> "$work/box.err"
grep -q "^  fidelity " "$work/box.out" || fail "no fidelity line in the box's summary"
! grep -q "not faithful" "$work/box.err" || fail "the box at 15 bits warned: $(cat "$work/box.err")"
"$sim" run --steps 3 --quiet --out "$work/double" > "$work/double.out"
! grep -q "fidelity" "$work/double.out" || fail "a double-precision run printed a fidelity line"
python3 -c 'import json, sys; assert "fidelity" not in json.load(open(sys.argv[1]))' "$work/double/report.json" ||
  fail "a double-precision run's report has a fidelity section"
"$sim" run --visibility fast --steps 3 --fidelity-sample 0 --quiet --out "$work/none" > "$work/none.out"
! grep -q "fidelity" "$work/none.out" || fail "--fidelity-sample 0 still measured"
echo "PASS: fidelity in the duck's and the box's summaries and reports, warning with its cause"
