"""rc2000tlm.design() against `rc2000sim design` (issue 26; README, "Use it from Python"), from the
build tree's package:
  1. a small search from Python equals the command's design.json field by field (the command parses
     its options with CLI11 and writes its own file; the call goes through the Python codec and a
     worker process), and its DataFrame has one row per simulated design with the columns of the
     point records, the front and the best marked as the command's design.csv marks them;
  2. load() of the command's folder equals the call's result (and keeps the folder's run command);
  3. the defaults are the command's: design_defaults() against the defaults `rc2000sim design --help`
     shows;
  4. values the command refuses raise ValueError with the command's message (naming the option and
     the limit); an option the command does not have is a TypeError;
  5. jobs= of run_many, paper, run and sweep: checked as `--jobs` is, with its message;
  6. resources= of run() and sweep() (`--resources`): the source the report names and the lanes it lets fit;
  7. max_error= (`--max-error`) on a mesh composition: the same design.json as the command's, the best the
     fastest design whose relative RMSE meets the bound, every width with its own steps and software time.
Prints "SKIP: <reason>" and exits 77 without pandas or the module.
usage: design_test.py RC2000SIM BUILD_DIR"""
import glob
import json
import os
import re
import subprocess
import sys
import tempfile

sim, build = sys.argv[1], sys.argv[2]
if not glob.glob(os.path.join(build, "python", "rc2000tlm", "_core*.so")):
    print("SKIP: the Python module was not built (RC_BUILD_PYTHON=OFF, or pybind11-dev / python3-dev missing)")
    sys.exit(77)
try:
    import pandas
except ImportError:
    print("SKIP: pandas not importable (Debian: python3-pandas)")
    sys.exit(77)
sys.path.insert(0, os.path.join(build, "python"))
os.environ["SYSTEMC_DISABLE_COPYRIGHT_MESSAGE"] = "1"
import rc2000tlm  # noqa: E402

work = tempfile.mkdtemp(prefix="design-test-")


def differences(a, b, path="design"):
    """Every path where two JSON trees differ (numbers exactly: both come from one simulation)."""
    if isinstance(a, dict) and isinstance(b, dict):
        out = ["%s.%s: only in one" % (path, k) for k in set(a) ^ set(b)]
        for k in a:
            if k in b:
                out += differences(a[k], b[k], "%s.%s" % (path, k))
        return out
    if isinstance(a, list) and isinstance(b, list):
        if len(a) != len(b):
            return ["%s: %d against %d items" % (path, len(a), len(b))]
        return [d for i, (x, y) in enumerate(zip(a, b)) for d in differences(x, y, "%s[%d]" % (path, i))]
    return [] if a == b and type(a) == type(b) else ["%s: %r against %r" % (path, a, b)]


def command(*args):
    return subprocess.run([sim, "design", *args], capture_output=True, text=True)


# 1. The same small search both ways: two lane counts, banks up to 7, both result stores and multipliers.
cli_dir = os.path.join(work, "cli")
done = command("--device", "virtex4-sx55", "--faces", "70", "--patch-levels", "1", "--steps", "12", "--lanes", "1,2",
               "--max-banks", "7", "--quiet", "--out", cli_dir)
assert done.returncode == 0, done.stderr
with open(os.path.join(cli_dir, "design.json")) as f:
    cli = json.load(f)
run_command = cli["best"].pop("run_command")
# An axis as a list, as the command's text and as one value (concurrent=True is --concurrent on).
got = rc2000tlm.design(device="virtex4-sx55", faces=70, patch_levels=1, steps=12, lanes=[1, 2], max_banks=7, bits="15",
                       concurrent=True)
diff = differences(got.to_dict(), cli)
assert not diff, "design() differs from rc2000sim design's design.json:\n  " + "\n  ".join(diff[:20])
assert got.simulated == len(got.points) >= 4 and got.best is not None and got.front, got
assert got.best.design == cli["best"]["design"] and got.best.bound.text == cli["best"]["bound"]["text"]
assert got.best_device == json.load(open(os.path.join(cli_dir, "best-device.json")))
print("1. design() equals design.json: %d designs (%d infeasible, %d pruned), %d simulated, best %s, %.6f s; "
      "%d on the front" % (got.designs, got.infeasible, got.pruned_spare_banks, got.simulated, got.best.design,
                           got.best.simulated_seconds, len(got.front)))

df = got.to_dataframe()
point_keys = [k for k in cli["points"][0] if k not in ("bound", "fidelity")]
bound_keys = ["bound_" + k for k in cli["points"][0]["bound"]]
fidelity_keys = ["fidelity_" + k for k in cli["points"][0]["fidelity"]]
assert list(df.columns) == point_keys + bound_keys + fidelity_keys + ["best"], list(df.columns)
assert len(df) == got.simulated and df.best.sum() == 1 and df[df.best].design.iloc[0] == got.best.design
assert sorted(df[df.on_front].design) == sorted(p["design"] for p in cli["front"])
csv = pandas.read_csv(os.path.join(cli_dir, "design.csv"))  # the command's other writer (design_csv)
assert len(csv) == len(df), (len(csv), len(df))
for col in ("lanes", "banks", "bits", "cards"):
    assert list(df[col]) == list(csv[col]), col
for col in ("simulated_seconds", "energy_joules", "average_watts", "bank_bytes_per_test", "pci_bytes_per_test"):
    for a, b in zip(df[col], csv[col]):
        assert abs(a - b) <= 1e-12 * abs(b), (col, a, b)
assert list(df.on_front.astype(int)) == list(csv.on_front) and list(df.best.astype(int)) == list(csv.best)
assert list(df.bound_run) == list(csv.bound) and list(df.bound_fpga_stream) == list(csv.fpga_stream_limit)
print("   DataFrame: %d rows x %d columns, equal to design.csv's; front and best marked" % df.shape)

# 2. load() of the command's folder.
loaded = rc2000tlm.load(cli_dir)
assert isinstance(loaded, rc2000tlm.DesignResult) and not differences(loaded.to_dict(), got.to_dict())
assert loaded.run_command == run_command and got.run_command is None
assert loaded.to_dataframe().equals(df) and loaded.best_device == got.best_device
# A cap no design meets: no best, nothing marked.
capped = rc2000tlm.design(device="virtex4-sx55", faces=70, patch_levels=1, steps=12, lanes=1, max_banks=6, max_power=0.001)
assert capped.best is None and capped.best_device is None and not capped.front and len(capped.points) > 0
assert not capped.to_dataframe().best.any() and not capped.to_dataframe().meets_constraints.any()
print("2. load() of the command's folder equals the call's result; a cap no design meets leaves no best")

# 3. The defaults: what `rc2000sim design --help` shows for every option that shows one.
defaults = rc2000tlm.design_defaults()
help_text = command("--help").stdout
shown = dict(re.findall(r"(?m)^\s+--([a-z-]+) [^=\n]*?=(\S+)", help_text))  # "--bits TEXT=15"
shown = {k.replace("-", "_"): v for k, v in shown.items() if k not in ("out", "configs")}
assert len(shown) >= 9, shown
for name, text in shown.items():
    assert str(defaults[name]) == text, (name, defaults[name], text)
assert all(defaults[k] is None for k in ("lanes", "banks", "bank_clocks", "steps", "max_banks", "max_energy"))
# Every option of the command is one of design()'s, by its snake_case name (issue 39, Python parity), except
# the two that are about the command's files and terminal: out (design() returns the result) and quiet
# (progress= says whether to show the search's phases).
options = set(n.replace("-", "_") for n in re.findall(r"(?m)^\s+(?:-\w,\s?)?--([a-z][a-z-]*)", help_text))
assert options - {"help", "out", "quiet"} == set(defaults), ("design() and `rc2000sim design --help` differ",
                                                          options - {"help", "out", "quiet"} ^ set(defaults))
print("3. design_defaults() shows the command's %d shown defaults: %s" % (len(shown), ", ".join(sorted(shown))))

# 4. Refusals: the command's message, naming the option and the limit.
space = dict(device="virtex4-sx55", faces=70, patch_levels=1, steps=12, lanes="1,2", max_banks=7)
base = {"--device": "virtex4-sx55", "--faces": "70", "--patch-levels": "1", "--steps": "12", "--lanes": "1,2",
        "--max-banks": "7"}
bad = [({"max_banks": 65}, ["--max-banks", "65"]), ({"max_banks": 4}, ["--max-banks", "4"]),
       ({"min_bits": 3}, ["--min-bits", "3"]), ({"steps": 0}, ["--steps", "0"]), ({"lanes": [0, 1]}, ["--lanes", "0,1"]),
       ({"results": "nowhere"}, ["--results", "nowhere"]), ({"multipliers": ["dsp"]}, ["--multipliers", "dsp"]),
       ({"bank_clocks": [0]}, ["--bank-clocks", "0"]), ({"max_power": float("nan")}, ["--max-power", "nan"]),
       ({"max_energy": -1.5}, ["--max-energy", "-1.5"]), ({"concurrent": "sometimes"}, ["--concurrent", "sometimes"]),
       ({"patch_levels": 9}, ["--patch-levels", "9"]), ({"faces": 0}, ["--faces", "0"]),
       ({"form_factor": "exact"}, ["--form-factor", "exact"]), ({"scene": "no-such.scene"}, ["--scene", "no-such.scene"]),
       ({"patch_size": 0.1}, ["--patch-levels", "1", "--patch-size", "0.1"]),
       ({"min_bits": 23, "bits": 15}, ["--min-bits", "23", "--bits", "15"]),
       ({"jobs": 0}, ["--jobs", "0"]), ({"jobs": 513}, ["--jobs", "513"]),
       ({"resources": "yosys"}, ["--resources", "yosys"]), ({"max_error": 0}, ["--max-error", "0"]),
       ({"max_error_max": float("inf")}, ["--max-error-max", "inf"]), ({"fidelity": "maybe"}, ["--fidelity", "maybe"]),
       ({"max_error": 0.01, "fidelity": False}, ["--max-error", "0.01", "--fidelity", "off"]),
       # The segment fixes as axes (issue 37): run's limits, a coordinate width at the width searched.
       ({"coordinate_bits": [0, 15]}, ["--coordinate-bits", "0,15"]), ({"coordinate_bits": 5}, ["--coordinate-bits", "5"]),
       ({"neighbour_rings": 3}, ["--neighbour-rings", "3"]), ({"offset_lsb": "0,2000000"}, ["--offset-lsb", "0,2000000"])]
for options, flags in bad:
    given = dict(base, **dict(zip(flags[::2], flags[1::2])))  # the bad values in place of the space's
    done = command(*[x for pair in given.items() for x in pair], "--quiet", "--out", os.path.join(work, "bad"))
    assert done.returncode != 0, ("the command accepted", flags)
    try:
        rc2000tlm.design(**dict(space, **options))
    except ValueError as e:
        message = str(e)
    else:
        sys.exit("design() accepted %r" % options)
    assert message and message in done.stderr, (options, message, done.stderr)
    assert flags[-2] in message, (flags, message)
    print("   %-40s ValueError: %s" % (options, message))
assert not os.path.exists(os.path.join(work, "bad")), "a refused command wrote its folder"
try:
    rc2000tlm.design(lane=2)
except TypeError as e:
    assert "lane" in str(e) and "lanes" in str(e), e
else:
    sys.exit("design() accepted an option the command does not have")
print("4. %d refusals carry the command's messages; an unknown option is a TypeError" % len(bad))

# 5. jobs= of the other functions: the rule's count, or --jobs's check and message (docs/outputs.md, "Cores").
paper_refusal = subprocess.run([sim, "paper", "--jobs", "0", "--quiet", "--out", os.path.join(work, "bad")],
                               capture_output=True, text=True).stderr
assert rc2000tlm.workers._jobs(3) == 3 and rc2000tlm.workers._jobs(None) >= 1
os.environ["RC2000SIM_JOBS"] = "2"
assert rc2000tlm.workers._jobs(None) == 2 and rc2000tlm.workers._jobs(5) == 5
del os.environ["RC2000SIM_JOBS"]
for call in (lambda: rc2000tlm.run_many([], jobs=0), lambda: rc2000tlm.paper(jobs=0), lambda: rc2000tlm.run(steps=1, jobs=0),
             lambda: rc2000tlm.sweep(lanes=[1], steps=2, jobs=0)):
    try:
        call()
    except ValueError as e:
        assert str(e) and str(e) in paper_refusal, (str(e), paper_refusal)
    else:
        sys.exit("a call accepted jobs=0")
try:
    rc2000tlm.run_many([], jobs=600)
except ValueError as e:
    assert "--jobs must be 1..512 (" in str(e) and "got 600" in str(e), e
else:
    sys.exit("run_many accepted jobs=600")
print("5. jobs=: the rule's count (RC2000SIM_JOBS too), and the command's refusal of 0 and 600")

# 6. resources= of run() (`run --resources`): the source the report names, a lane count that fits only under
# the paper fit refused with the run's message, and an unknown source refused naming the option.
one = rc2000tlm.run(steps=1, patch_levels=1, device="virtex4-sx55", lanes=1, resources="synthesis")
assert one.board["device"]["design"]["resources"] == "synthesis", one.board["device"]["design"]
done = subprocess.run([sim, "run", "--impl", "board", "--device", "virtex4-sx55", "--lanes", "10", "--banks", "17",
                       "--resources", "synthesis", "--steps", "1", "--quiet", "--out", os.path.join(work, "bad")],
                      capture_output=True, text=True)
assert done.returncode != 0 and "(resources: synthesis)" in done.stderr, done.stderr
for options, expected in (({"lanes": 10, "banks": 17, "resources": "synthesis"}, "(resources: synthesis)"),
                          ({"resources": "yosys"}, "--resources: yosys not in {paper,synthesis}")):
    try:
        rc2000tlm.run(steps=1, patch_levels=1, device="virtex4-sx55", **options)
    except ValueError as e:
        assert expected in str(e), (options, str(e))
    else:
        sys.exit("run() accepted %r" % options)
# sweep(resources=) writes the study file's top-level key: ten block-multiplier lanes fit the SX55 under the
# paper fit (23,346 slices of 24,576) and not under the synthesis (24,836), so its row says why.
fits = {}
for source in ("paper", "synthesis"):
    rows = rc2000tlm.sweep(lanes=[9, 10], banks=[17], devices=["virtex4-sx55"], steps=2, resources=source,
                           scenes=[{"faces": 70, "patch_levels": 1}]).rows
    fits[source] = [not row.get("reason") for row in rows]
assert fits == {"paper": [True, True], "synthesis": [True, False]}, fits
assert 'resources = "synthesis"' in rc2000tlm.workers.study_text(resources="synthesis")
print("6. resources=: the report names the source; a design that does not fit under it, and an unknown source, refused; sweep(resources=) decides which lanes fit")

# 7. An error bound on a mesh composition (Assimp's concave 66-gon in the Cornell Box, 102 faces, one patch
# each): the command and the call agree, the best design is the fastest whose picture meets 1% relative
# RMSE, and every width has its own solve's steps and software time.
mesh = os.path.join(work, "mesh.json")
with open(mesh, "w") as f:
    f.write('{"schema": "rc2000sim.composition/1", "room": "cornell-box", "meshes": [{"file": '
            '"/usr/share/assimp/models/OBJ/concave_polygon.obj", "rotate": {"axis": [1, 0.3, 0.2], "degrees": 50}, '
            '"fit_into": {"min": [120, 180, 250], "max": [420, 420, 450]}, "material": {"reflectance": [0.3, 0.4, 0.7]}}]}')
mesh_dir = os.path.join(work, "mesh")
# --faces 102 --face-levels 0: the composition as it is (the search's default refinement is the paper's).
done = command("--scene", mesh, "--faces", "102", "--face-levels", "0", "--patch-levels", "0", "--bits", "11,15,23,31",
               "--lanes", "1,2", "--max-banks", "6", "--max-error", "0.01", "--quiet", "--out", mesh_dir)
assert done.returncode == 0, done.stderr
cli = json.load(open(os.path.join(mesh_dir, "design.json")))
cli["best"].pop("run_command")
got = rc2000tlm.design(scene=mesh, faces=102, face_levels=0, patch_levels=0, bits="11,15,23,31", lanes="1,2",
                       max_banks=6, max_error=0.01)
diff = differences(got.to_dict(), cli)
assert not diff, "design(max_error=) differs from the command's design.json:\n  " + "\n  ".join(diff[:20])
assert got.constraints["max_error"] == 0.01
widths = {w["bits"]: w for w in got.widths}
assert sorted(widths) == [11, 15, 23, 31] and all(w["measured"] and w["software_seconds"] > 0 for w in widths.values())
meeting = [p for p in got.points if p.fidelity["relative_rmse"] <= 0.01]
assert meeting and got.best is not None and got.best.fidelity["relative_rmse"] <= 0.01
assert got.best.simulated_seconds == min(p.simulated_seconds for p in meeting)
for p in got.points:
    w = widths[p.bits]
    assert p.steps == w["steps"] and p.fidelity == w, (p.design, p.steps, w)
    assert p.meets_constraints == (w["relative_rmse"] <= 0.01)
    assert abs(p.speedup_vs_software - w["software_seconds"] / p.simulated_seconds) <= 1e-12 * p.speedup_vs_software
assert got.front and all(p.fidelity["relative_rmse"] <= 0.01 for p in got.front)
print("7. max_error=0.01 on a mesh: best %s (relative RMSE %.3g); widths %s" % (
    got.best.design, got.best.fidelity["relative_rmse"],
    ", ".join("%d bits: %d steps, %.3g RMSE, %.3f s software" % (b, w["steps"], w["relative_rmse"], w["software_seconds"])
              for b, w in sorted(widths.items()))))
subprocess.run(["rm", "-rf", work])
print("PASS: rc2000tlm.design() is rc2000sim design")
