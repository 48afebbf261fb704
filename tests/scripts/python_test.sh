#!/usr/bin/env bash
# The Python module from an installed prefix (issue 26; README, "Use it from Python"): `cmake
# --install` of this build into a temporary prefix, then, with only that prefix on PYTHONPATH and
# from a folder outside the source tree:
#  1. `python3 -c "import rc2000tlm; ..."` runs a small sweep into a DataFrame, whose rows equal the
#     installed rc2000sim's sweep.csv for the same study file (another process, another writer);
#  2. run() gives `rc2000sim run --impl board`'s report (and its fidelity) for the same options, with per-step and
#     per-bank DataFrames; run_many() gives the same answers in parallel; an unknown option is refused;
#     run() has exactly `rc2000sim run --help`'s options, its checks and words, and a software run with
#     the options printed commands carry (--patch-size, --form-factor, --paper-faithful) equals the command's;
#  3. a study over two scenes has a scene column, and load() of rc2000sim's outputs of the same study
#     (its study.csv) gives the same rows;
#  4. a bad study arrives as an exception (ValueError, RuntimeError) carrying the command line's message;
#  5. paper() gives the installed `rc2000sim paper`'s Table 2 cells (paper.csv's scene records);
#  6. design() gives the installed `rc2000sim design`'s design.json (load() of its folder);
#  with MODE=notebook: examples/python/sweep-results.ipynb runs headless (nbclient).
# Prints "SKIP: <reason>" and exits 77 when a Debian package it needs is missing (python3-pandas,
# python3-nbclient, python3-ipykernel) or the module was not built (RC_BUILD_PYTHON).
# usage: python_test.sh BUILD_DIR REPO_ROOT PYTHON MODE(module|notebook)
set -euo pipefail
build="$1"; root="$2"; python="$3"; mode="$4"
fail() { echo "FAIL: $*" >&2; exit 1; }
ls "$build"/python/rc2000tlm/_core*.so > /dev/null 2>&1 || { echo "SKIP: the Python module was not built (RC_BUILD_PYTHON=OFF, or pybind11-dev / python3-dev missing: see the configure warning)"; exit 77; }
[ -x "$python" ] || { echo "SKIP: no Python interpreter found by CMake ($python)"; exit 77; }
"$python" -c "import pandas" 2> /dev/null || { echo "SKIP: pandas not importable by $python (Debian: python3-pandas)"; exit 77; }
if [ "$mode" = notebook ]; then
  "$python" -c "import nbclient, nbformat, ipykernel, matplotlib" 2> /dev/null ||
    { echo "SKIP: nbclient, nbformat, ipykernel or matplotlib missing for $python (Debian: python3-nbclient python3-ipykernel python3-matplotlib)"; exit 77; }
fi
work="$(mktemp -d "${TMPDIR:-/tmp}/python-test.XXXXXX")"
trap 'rm -rf "$work"' EXIT
export SYSTEMC_DISABLE_COPYRIGHT_MESSAGE=1
prefix="$work/prefix"
cmake --install "$build" --prefix "$prefix" > "$work/install.log" || { cat "$work/install.log" >&2; fail "cmake --install"; }
export PYTHONPATH="$prefix/lib/python3/dist-packages"
unset RC2000SIM_CONFIGS
cd "$work"

if [ "$mode" = notebook ]; then
  PYDEVD_DISABLE_FILE_VALIDATION=1 RC_REPO_ROOT="$root" RC_NOTEBOOK_PLOT="$work/lanes.png" "$python" -Xfrozen_modules=off - "$root/examples/python/sweep-results.ipynb" <<'PY'
import sys, nbformat
from nbclient import NotebookClient
nb = nbformat.read(sys.argv[1], as_version=4)
NotebookClient(nb, timeout=600, kernel_name="python3", resources={"metadata": {"path": "."}}).execute()
for cell in nb.cells:
    for out in cell.get("outputs", []):
        if out.get("name") == "stdout":
            print("  " + out["text"].strip())
PY
  [ -s "$work/lanes.png" ] || fail "the notebook drew no plot"
  echo "PASS: the notebook reproduces the sweep page's table and plot"
  exit 0
fi

cat > "$work/small.toml" <<'TOML'
name = "python-test"
[[scenes]]
paper = { faces = 70, patches = 280 }
[solver]
steps = 20
[axes]
devices = ["xc2v6000"]
bits = [15]
concurrent = "on"
lanes = [1, 2]
banks = [6]
TOML
step() { echo "[$(date +%T)] $*"; }

step "1. a small sweep into a DataFrame, as the installed rc2000sim writes it"
"$prefix/bin/rc2000sim" sweep --study "$work/small.toml" --quiet --out "$work/cli-sweep" > /dev/null
"$python" -c "
import rc2000tlm, pandas, sys
assert rc2000tlm.__file__.startswith('$prefix/'), rc2000tlm.__file__
s = rc2000tlm.sweep(scenes=[{'paper': {'faces': 70, 'patches': 280}}], steps=20, name='python-test',
                    devices=['xc2v6000'], bits=[15], concurrent='on', lanes=[1, 2], banks=[6])
df = s.to_dataframe()
cli = pandas.read_csv('$work/cli-sweep/sweep.csv')
assert list(df.lanes) == [1, 2] and (df.status == 'ok').all(), df
for col in ('simulated_seconds', 'fpga_busy_seconds', 'energy_joules', 'speedup_vs_one_lane'):
    for a, b in zip(df[col], cli[col]):
        assert abs(a - b) <= 1e-9 * abs(b), (col, a, b)
print('  ', len(df), 'rows;', ', '.join('%d lanes %.6f s' % (r.lanes, r.simulated_seconds) for r in df.itertuples()))
"

step "2. run() is rc2000sim run --impl board"
"$prefix/bin/rc2000sim" run --impl board --steps 3 --patch-levels 1 --lanes 2 --quiet --out "$work/cli-run" > /dev/null
"$python" - "$work/cli-run/report.json" "$prefix/bin/rc2000sim" <<'PY'
import json, sys, rc2000tlm
def no_wall(j):
    if isinstance(j, dict):
        return {k: no_wall(v) for k, v in j.items() if not k.startswith("wall_seconds")}
    if isinstance(j, list):
        return [no_wall(v) for v in j]
    return j
cmd = json.load(open(sys.argv[1]))
r = rc2000tlm.run(steps=3, patch_levels=1, lanes=2)
assert r.steps == cmd["steps"] == 3 and r.simulated_seconds == cmd["simulated_seconds"], (r, cmd["simulated_seconds"])
assert no_wall(r.board) == no_wall(cmd["board"]), "the board report differs from the command's"
assert r.fidelity == cmd["fidelity"], ("run()'s fidelity differs from the command's", r.fidelity, cmd["fidelity"])
assert rc2000tlm.run(steps=1, patch_levels=1, fidelity_sample=0).fidelity is None
for bad, words in ((dict(fidelity_sample=-1), "--fidelity-sample: Value -1 not in range 0 to 10000000"),
                   (dict(fidelity_warn=2.0), "--fidelity-warn: Value 2 not in range 0 to 1")):
    try:
        rc2000tlm.run(steps=1, patch_levels=1, **bad)
    except Exception as e:
        assert words in str(e), (bad, str(e))
    else:
        sys.exit("run() accepted %r" % bad)
steps = r.to_dataframe()
assert list(steps.step) == [1, 2, 3] and steps.simulated_seconds.is_monotonic_increasing
assert steps.simulated_seconds.iloc[-1] <= r.simulated_seconds
banks = r.banks_dataframe()
assert len(banks) > 0 and (banks.bytes_read + banks.bytes_written).sum() > 0
loaded = rc2000tlm.load(sys.argv[1].rsplit("/", 1)[0])
assert loaded.simulated_seconds == r.simulated_seconds
# Several runs at once, each in its own process: the same answers as one at a time, in order.
many = rc2000tlm.run_many([dict(steps=3, patch_levels=1, lanes=1), dict(steps=3, patch_levels=1, lanes=2)], progress=False)
assert many[1].simulated_seconds == r.simulated_seconds and no_wall(many[1].board) == no_wall(r.board)
assert many[0].simulated_seconds != r.simulated_seconds
try:
    rc2000tlm.run(lane=2)
except TypeError:
    pass
else:
    sys.exit("run() accepted an option that does not exist")
# One option table (issue 39): run() takes every option of `rc2000sim run --help` by its snake_case name,
# with the command's checks and words, and a run the printed commands describe (patch_size, face_levels,
# form_factor, paper_faithful, software backends) equals the command's report.
import re, subprocess
helped = set(n.replace("-", "_") for n in re.findall(r"^\s+(?:-\w,\s?)?--([a-z][a-z-]*)", subprocess.run(
    [sys.argv[2], "run", "--help"], capture_output=True, text=True).stdout, re.M)) - {"help"}
assert helped == set(rc2000tlm.run_options()), ("run() and `rc2000sim run --help` differ", helped ^ set(rc2000tlm.run_options()))
for bad, words in ((dict(banks=65), "--banks: Value 65 not in range 1 to 64"),
                   (dict(lanes=-1), "--lanes: Value -1 not in range 1 to 255"),
                   (dict(steps=10**9), "--steps 1000000000 is above the solver's cap"),
                   (dict(patch_levels=1, patch_size=0.2), "--patch-levels excludes --patch-size"),
                   (dict(impl="software", lanes=2), "--lanes applies to --impl board only")):
    try:
        rc2000tlm.run(**bad)
    except ValueError as e:
        assert words in str(e), (bad, str(e))
    else:
        sys.exit("run() accepted %r" % bad)
opts = ["--impl", "software", "--visibility", "fast", "--steps", "2", "--patch-size", "0.2", "--form-factor", "point",
        "--paper-faithful", "--face-levels", "1"]
subprocess.run([sys.argv[2], "run"] + opts + ["--quiet", "--out", "cli-soft"], check=True, stdout=subprocess.DEVNULL)
cmd = json.load(open("cli-soft/report.json"))
soft = rc2000tlm.run(impl="software", visibility="fast", steps=2, patch_size=0.2, form_factor="point", paper_faithful=True,
                     face_levels=1)
assert no_wall(soft.to_dict()) == dict(no_wall(cmd), per_step=soft.per_step), "run() differs from rc2000sim run " + " ".join(opts)
assert soft.simulated_seconds is None and [s["step"] for s in soft.per_step] == [1, 2]
# sweep(): `rc2000sim sweep`'s study options by the same names (all but the command's files, terminal and
# shards, and --jobs, which is jobs= as everywhere), and the command's rows for the same options.
helped = set(n.replace("-", "_") for n in re.findall(r"^\s+(?:-\w,\s?)?--([a-z][a-z-]*)", subprocess.run(
    [sys.argv[2], "sweep", "--help"], capture_output=True, text=True).stdout, re.M))
helped -= {"help", "study", "shard", "out", "quiet", "jobs", "list_fields"}
assert helped == set(rc2000tlm.sweep_options()), ("sweep() and `rc2000sim sweep --help` differ", helped ^ set(rc2000tlm.sweep_options()))
opts = ["--lanes", "1,2", "--banks", "6", "--steps", "5", "--faces", "70", "--patch-levels", "1", "--concurrent", "off"]
subprocess.run([sys.argv[2], "sweep"] + opts + ["--quiet", "--out", "cli-sweep"], check=True, stdout=subprocess.DEVNULL)
cmd_rows = json.load(open("cli-sweep/sweep.json"))["rows"]
swept = rc2000tlm.sweep(lanes=[1, 2], banks=6, steps=5, faces=70, patch_levels=1, concurrent=False)
assert [r["simulated_seconds"] for r in swept.rows] == [r["simulated_seconds"] for r in cmd_rows], "sweep() differs from rc2000sim sweep"
try:
    rc2000tlm.sweep(lanes="0-3", steps=2)
except ValueError as e:
    assert "--lanes: '0-3' is outside 1..255" in str(e), str(e)
else:
    sys.exit("sweep() accepted lanes 0")
print("   %d steps, %.9f s, %d banks; per step: %s" % (r.steps, r.simulated_seconds, len(banks),
      ", ".join("%.6f" % t for t in steps.simulated_seconds)))
PY

step "3. a study over two scenes: a scene column, and load() of rc2000sim's study.csv"
"$prefix/bin/rc2000sim" sweep --study "$root/tests/host_sw/studies/data/small.toml" --quiet --out "$work/cli-study" > /dev/null
"$python" - "$root/tests/host_sw/studies/data/small.toml" "$work/cli-study" <<'PY'
import sys, rc2000tlm
fresh = rc2000tlm.study(sys.argv[1]).to_dataframe()
loaded = rc2000tlm.load(sys.argv[2]).to_dataframe()
assert list(fresh.columns[:1]) == ["scene"] and fresh.scene.nunique() == 2, fresh.columns
assert list(fresh.scene) == list(loaded.scene) and list(fresh.lanes) == list(loaded.lanes)
for a, b in zip(fresh.simulated_seconds, loaded.simulated_seconds):
    assert (a != a and b != b) or abs(a - b) <= 1e-9 * abs(b), (a, b)
print("  ", len(fresh), "rows over", ", ".join(fresh.scene.unique()))
PY

step "4. errors are exceptions with the command line's message"
printf 'name = "bad"\n[axes]\nlanes = [0]\n' > "$work/bad.toml"
if "$prefix/bin/rc2000sim" sweep --study "$work/bad.toml" --quiet --out "$work/bad" > /dev/null 2> "$work/cli.err"; then
  fail "rc2000sim accepted lanes = [0]"
fi
"$python" - "$work/bad.toml" "$work/cli.err" <<'PY'
import sys, rc2000tlm
try:
    rc2000tlm.study(sys.argv[1])
except (ValueError, RuntimeError) as e:
    kind, message = type(e).__name__, str(e)
else:
    sys.exit("lanes = [0] was accepted")
cli = open(sys.argv[2]).read()
assert message and message in cli, (message, cli)
print("   %s:" % kind, message)
PY
step "5. paper() is rc2000sim paper's Table 2"
"$prefix/bin/rc2000sim" paper --quiet --out "$work/cli-paper" > /dev/null
"$python" - "$work/cli-paper/paper.csv" <<'PY'
import sys, pandas, rc2000tlm
cli = pandas.read_csv(sys.argv[1])
cli = cli[cli.record == "scene"].reset_index(drop=True)
got = rc2000tlm.paper().to_dataframe()
assert len(got) == len(cli) > 0 and list(got.implementation) == list(cli.implementation)
for col in ("faces", "patches", "steps"):
    assert list(got[col]) == [int(x) for x in cli[col]], col
for col in ("seconds", "paper_seconds", "spread_min_seconds", "spread_max_seconds", "fpga_busy_seconds", "speedup_vs_software"):
    for a, b in zip(got[col], cli[col]):
        assert (a is None or a != a) == (b != b) and (b != b or abs(a - b) <= 1e-9 * abs(b)), (col, a, b)
print("   %d Table 2 cells equal paper.csv's" % len(got))
PY
step "6. design() from the installed prefix is the installed rc2000sim design (tests/python/design_test.py: the rest)"
"$prefix/bin/rc2000sim" design --device virtex4-sx55 --faces 70 --patch-levels 1 --steps 5 --lanes 1 --max-banks 6 --quiet \
  --out "$work/cli-design" > /dev/null
"$python" - "$work/cli-design" <<'PY'
import sys, rc2000tlm
got = rc2000tlm.design(device="virtex4-sx55", faces=70, patch_levels=1, steps=5, lanes=1, max_banks=6)
assert got.to_dict() == rc2000tlm.load(sys.argv[1]).to_dict() and got.best is not None
print("   %d designs simulated; best %s" % (len(got.to_dataframe()), got.best.design))
PY
echo "PASS: the installed module runs sweeps, runs, studies, the paper's table and design searches into DataFrames; errors carry the command's message"
