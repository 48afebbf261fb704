"""rc2000tlm.load() on folders made by hand (issue 39; docs/outputs.md, "Output folders own their files"):
  1. only the files the folder's rc2000sim-outputs.txt lists count: a stale study.csv beside a run's
     report.json is not read; without a listing every file counts, as before;
  2. values keep the writer's types: a sweep's rows come from its sweep.json (a scene "007" stays
     text); a CSV alone is read by column (a column of labels that look like numbers stays text, a
     number column is numbers, an empty cell None);
  3. a damaged JSON or CSV raises OutputError naming the file and the line (or key), never a bare
     JSONDecodeError or TypeError.
The package from the source tree (load() needs no compiled module).
usage: load_test.py PYTHON_PACKAGE_DIR"""
import atexit
import json
import os
import shutil
import sys
import tempfile

sys.path.insert(0, sys.argv[1])
import rc2000tlm  # noqa: E402
from rc2000tlm import OutputError  # noqa: E402

work = tempfile.mkdtemp(prefix="load-test-")
atexit.register(shutil.rmtree, work, True)


def folder(name, files):
    path = os.path.join(work, name)
    for rel, text in files.items():
        os.makedirs(os.path.dirname(os.path.join(path, rel)), exist_ok=True)
        with open(os.path.join(path, rel), "w") as f:
            f.write(text)
    return path


def listing(*names, command="run"):
    return "# rc2000sim outputs\ncommand %s\n" % command + "".join("file %s\n" % n for n in names)


def raises(path, *words):
    try:
        rc2000tlm.load(path)
    except OutputError as e:
        for w in words:
            assert w in str(e), (w, str(e))
        return str(e)
    raise AssertionError("%s loaded" % path)


report = json.dumps({"schema": "rc2000sim.run/1", "steps": 3, "simulated_seconds": 1.5})
stale = "scene,lanes\n007,1\n"
# 1. the listing decides
run = folder("run", {"report.json": report, "study.csv": stale, "rc2000sim-outputs.txt": listing("report.json")})
assert isinstance(rc2000tlm.load(run), rc2000tlm.RunResult)
legacy = folder("legacy", {"report.json": report, "sweep.csv": "lanes\n1\n"})
assert isinstance(rc2000tlm.load(legacy), rc2000tlm.SweepResult)
empty = folder("empty", {"report.json": report, "rc2000sim-outputs.txt": listing("design.json")})
try:
    rc2000tlm.load(empty)
except FileNotFoundError as e:
    assert "rc2000sim-outputs.txt lists" in str(e), str(e)
else:
    raise AssertionError("a report.json no listing names was read")
print("1. load() reads what the listing names")

# 2. the writer's types
rows = [{"device": "007", "lanes": 1, "simulated_seconds": 2.5, "status": "ok"},
        {"device": "007", "lanes": 2, "simulated_seconds": None, "status": "1e3"}]
sweep = folder("sweep", {
    "sweep.csv": "device,lanes,simulated_seconds,status\n007,1,2.5,ok\n007,2,,1e3\n",
    "sweep.json": json.dumps({"schema": "rc2000sim.sweep/1", "rows": rows}),
    "rc2000sim-outputs.txt": listing("sweep.csv", "sweep.json", command="sweep")})
assert rc2000tlm.load(sweep).rows == rows, rc2000tlm.load(sweep).rows
csv_only = folder("csv", {"sweep.csv": "device,lanes,seconds,label,nan\n007,1,2.5,1e3,nan\n008,2,,x,nan\n"})
got = rc2000tlm.load(csv_only).rows
assert got == [{"device": "007", "lanes": 1, "seconds": 2.5, "label": "1e3", "nan": "nan"},
               {"device": "008", "lanes": 2, "seconds": None, "label": "x", "nan": "nan"}], got
print("2. labels stay text (from sweep.json, or by column):", [r["device"] for r in got], got[0]["label"])

# 3. damaged files are named
print("3.", raises(folder("cut", {"report.json": report[:20]}), "report.json: line 1, column", "not valid JSON"))
print("  ", raises(folder("array", {"report.json": "[1, 2]"}), "report.json: holds a JSON list"))
print("  ", raises(folder("schema", {"report.json": json.dumps({"schema": "x"})}), 'key "schema" is \'x\''))
print("  ", raises(folder("short", {"sweep.csv": "a,b\n1,2\n3\n"}), "sweep.csv: line 3: 1 fields where the header has 2"))
print("  ", raises(folder("rows", {"sweep.csv": "a\n1\n", "sweep.json": json.dumps({"schema": "rc2000sim.sweep/1", "rows": 3})}),
                   'sweep.json: key "rows"'))
print("  ", raises(folder("design", {"design.json": json.dumps({"schema": "rc2000sim.design/1", "best": 3})}),
                   "design.json: not a design document"))
print("PASS")
