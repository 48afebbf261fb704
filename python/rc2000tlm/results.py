"""Typed results: RunResult (one board run), SweepResult (a sweep's or a study's rows), PaperResult
(Table 2) and DesignResult (a design search), each with to_dict() and pandas DataFrames; load(folder)
reads what rc2000sim or these wrote."""
import csv
import json
import os
import re


def _dataframe(records, columns=None):
    import pandas  # Debian: python3-pandas
    return pandas.DataFrame.from_records(records, columns=columns)


def _find(tree, key):
    """The first value under `key` anywhere in a JSON tree (depth first), or None."""
    if isinstance(tree, dict):
        if key in tree:
            return tree[key]
        tree = list(tree.values())
    if isinstance(tree, list):
        for v in tree:
            found = _find(v, key)
            if found is not None:
                return found
    return None


class RunResult:
    """One run: report.json's document (docs/outputs.md; to_dict()) with per-step records (step,
    convergence_reached, simulated_seconds: the simulated time when the step ended, None in software runs).
    steps, simulated_seconds (board runs; None in software runs), board (report.json's "board"), fidelity (its "fidelity": the
    sampled share of decisions that differ from double precision, its interval and causes; None when
    not measured) and warnings (the scene's, the solver's and the picture's, as the command prints them)."""

    def __init__(self, data):
        self._data = data
        self.steps = data.get("steps")
        self.board = data.get("board", {})
        self.simulated_seconds = data.get("simulated_seconds", _find(self.board, "simulated_seconds"))
        self.per_step = data.get("per_step", [])
        self.fidelity = data.get("fidelity")
        if "warnings" in data:  # a document of the core's own (older results)
            self.warnings = data["warnings"]
        else:
            scene = data.get("scene") or {}
            solver = data.get("solver") or {}
            image = data.get("image_warning")
            self.warnings = list(scene.get("warnings", [])) + list(solver.get("warnings", [])) + ([image] if image else [])

    def to_dict(self):
        return self._data

    def to_dataframe(self):
        """Per step: step, convergence_reached, simulated_seconds (the time when the step ended)."""
        return _dataframe(self.per_step, ["step", "convergence_reached", "simulated_seconds"])

    def banks_dataframe(self):
        """Per bank: role, reads, writes, bytes, busy time and bandwidth (bytes per second)."""
        return _dataframe(_find(self.board, "banks") or [])

    def __repr__(self):
        return "RunResult(steps=%s, simulated_seconds=%s)" % (self.steps, self.simulated_seconds)


class SweepResult:
    """A sweep's rows, one per configuration (the columns of sweep.csv, docs/outputs.md), with a
    `scene` column when the study has several scenes."""

    def __init__(self, rows, study=""):
        self.rows = rows
        self.study = study
        self.warnings = []

    @classmethod
    def from_core(cls, data):
        several = len(data["scenes"]) > 1
        rows = []
        warnings = []
        for scene in data["scenes"]:
            for row in scene["rows"]:
                rows.append(dict({"scene": scene["name"]}, **row) if several else row)
            warnings += [(scene["name"] + ": " if several else "") + w for w in scene.get("warnings", [])]
        result = cls(rows, data.get("study", ""))
        result.warnings = warnings  # what `rc2000sim sweep` prints as warnings (a profile axis that changed nothing)
        return result

    def to_dict(self):
        return {"study": self.study, "rows": self.rows}

    def to_dataframe(self):
        return _dataframe(self.rows)

    def __len__(self):
        return len(self.rows)

    def __repr__(self):
        return "SweepResult(study=%r, %d rows)" % (self.study, len(self.rows))


class OutputError(ValueError):
    """An output file that cannot be read back as rc2000sim writes it (damaged, cut short, edited):
    the message names the file and the line or key."""


LISTING = "rc2000sim-outputs.txt"  # apps/outputs.h, kOutputListing


def _listed(folder):
    """The files the folder's listing names (docs/outputs.md, "Output folders own their files"): the
    outputs of the command that last wrote there; None for a folder without a listing (written by an
    older rc2000sim, or by hand), where every file counts."""
    path = os.path.join(folder, LISTING)
    if not os.path.isfile(path):
        return None
    with open(path, encoding="utf-8", errors="replace") as f:
        return {os.path.normpath(line[5:].rstrip("\n")) for line in f if line.startswith("file ")}


def _present(folder, name, listed):
    return os.path.isfile(os.path.join(folder, name)) and (listed is None or os.path.normpath(name) in listed)


def _read_json(path):
    """A JSON output, or OutputError naming the file and the line and column of the damage."""
    try:
        with open(path, encoding="utf-8") as f:
            return json.load(f)
    except json.JSONDecodeError as e:
        raise OutputError("%s: line %d, column %d: not valid JSON: %s" % (path, e.lineno, e.colno, e.msg)) from None
    except UnicodeDecodeError as e:
        raise OutputError("%s: not UTF-8 (byte 0x%02X at offset %d)" % (path, e.object[e.start], e.start)) from None


def _object(path, data, schema=None):
    """`data` read from `path` must be a JSON object (of `schema`, when given)."""
    if not isinstance(data, dict):
        raise OutputError("%s: holds a JSON %s, not the object rc2000sim writes" % (path, type(data).__name__))
    if schema is not None and data.get("schema") != schema:
        raise OutputError("%s: key \"schema\" is %r, not %r" % (path, data.get("schema"), schema))
    return data


def _read_csv(path):
    """(header, rows of text) of a CSV output; OutputError naming the file and line of a row whose
    number of fields is not the header's, or of text the CSV reader refuses."""
    try:
        with open(path, newline="", encoding="utf-8") as f:
            reader = csv.reader(f)
            header = next(reader, None)
            if not header:
                raise OutputError("%s: empty, no header line" % path)
            rows = []
            for fields in reader:
                if len(fields) != len(header):
                    raise OutputError("%s: line %d: %d fields where the header has %d" %
                                      (path, reader.line_num, len(fields), len(header)))
                rows.append(fields)
            return header, rows
    except csv.Error as e:
        raise OutputError("%s: line %d: %s" % (path, reader.line_num, e)) from None
    except UnicodeDecodeError as e:
        raise OutputError("%s: not UTF-8 (byte 0x%02X at offset %d)" % (path, e.object[e.start], e.start)) from None


_INTEGER = re.compile(r"-?(0|[1-9][0-9]*)\Z")
_DECIMAL = re.compile(r"-?([0-9]+\.?[0-9]*|\.[0-9]+)([eE][-+]?[0-9]+)?\Z")


def _number(text):
    """A number as rc2000sim writes one in a CSV (%d, %.10g: no leading zeros, no "nan" or "inf": an
    empty cell is a missing figure), else None."""
    if _INTEGER.match(text):
        return int(text)
    if _DECIMAL.match(text) and not re.match(r"-?0[0-9]", text):
        return float(text)
    return None


def _typed_rows(path):
    """A CSV without the writer's JSON beside it: a column is numbers only when every cell of it is a
    number as rc2000sim writes them ("007", "1e3x" and a column of names keep their text: a name that
    looks like a number stays a name when any other cell of its column is text); empty cells are None."""
    header, rows = _read_csv(path)
    numeric = [all(r[i] == "" or _number(r[i]) is not None for r in rows) and any(r[i] != "" for r in rows)
               for i in range(len(header))]
    return [{k: (None if v == "" else _number(v) if numeric[i] else v) for i, (k, v) in enumerate(zip(header, r))}
            for r in rows]


def _json_rows(folder, csv_path):
    """The rows of `folder`'s sweep.json (the writer's own types: a label stays text, a number a
    number), in the columns of the CSV beside it; OutputError when the two disagree."""
    path = os.path.join(folder, "sweep.json")
    data = _object(path, _read_json(path), "rc2000sim.sweep/1")
    rows = data.get("rows")
    if not isinstance(rows, list) or not all(isinstance(r, dict) for r in rows):
        raise OutputError("%s: key \"rows\" is not a list of row objects" % path)
    header, text_rows = _read_csv(csv_path)
    if len(text_rows) != len(rows):
        raise OutputError("%s has %d rows, %s %d: one of them was changed or cut short" %
                          (csv_path, len(text_rows), path, len(rows)))
    return [{k: r.get(k) for k in header} if set(header) <= set(r) else r for r in rows]


def _sweep_rows(folder, listed):
    """A one-scene sweep's rows: sweep.json's when listed beside sweep.csv, else the CSV's by column."""
    csv_path = os.path.join(folder, "sweep.csv")
    if _present(folder, "sweep.json", listed):
        return _json_rows(folder, csv_path)
    return _typed_rows(csv_path)


def _study_rows(folder, listed):
    """A study of several scenes: each scene's sweep.json (folder/<scene>/) with a first column scene,
    in study.csv's order; study.csv by column where a scene's JSON is missing."""
    path = os.path.join(folder, "study.csv")
    header, text_rows = _read_csv(path)
    if not header or header[0] != "scene":
        raise OutputError("%s: line 1: the first column is %r, not scene" % (path, header[0] if header else ""))
    scenes = []
    for r in text_rows:
        if r[0] not in scenes:
            scenes.append(r[0])
    if not all(_present(folder, os.path.join(s, "sweep.json"), listed) and
               _present(folder, os.path.join(s, "sweep.csv"), listed) for s in scenes):
        return _typed_rows(path)
    rows = []
    for s in scenes:
        for r in _json_rows(os.path.join(folder, s), os.path.join(folder, s, "sweep.csv")):
            rows.append(dict({"scene": s}, **r))
    if len(rows) != len(text_rows):
        raise OutputError("%s has %d rows, its scenes' sweep.json %d" % (path, len(text_rows), len(rows)))
    return rows


class DesignBound:
    """What bounds a design, in the words `rc2000sim run` prints (design.json's "bound"): run (the
    largest part of the host's timeline: fpga, host_compute, host_driver, pci), fpga_stream (what
    bounded the FPGA's stream), fpga_share (of the FPGA's busy time), fpga_next (what comes next), text."""

    def __init__(self, record):
        self.run = record.get("run")
        self.fpga_stream = record.get("fpga_stream")
        self.fpga_share = record.get("fpga_share")
        self.fpga_next = record.get("fpga_next")
        self.text = record.get("text")

    def __repr__(self):
        return "DesignBound(%r)" % self.text


class DesignPoint:
    """One simulated design (a point record of design.json, docs/outputs.md): design (its description),
    device, lanes, banks, bank_clock_mhz, results, bits, offset_lsb, neighbour_rings, coordinate_bits (its
    segment fix, 0 for off), multipliers, cards, concurrent, clock_mhz,
    simulated_seconds, speedup_vs_reference, speedup_vs_software, energy_joules, average_watts, tests,
    tests_per_second, tests_per_second_while_fpga_busy, bank_bytes_per_test, pci_bytes_per_test, steps
    (its width's own solve's), fidelity (a dict: bits, steps, software_seconds, measured, relative_rmse,
    relative_max_error, decisions_compared, decisions_differ, decisions_differ_share; None figures when
    not measured), bound (a DesignBound), meets_constraints, on_front."""

    def __init__(self, record):
        self._record = record
        for key, value in record.items():
            setattr(self, key, DesignBound(value) if key == "bound" else value)

    def to_dict(self):
        return self._record

    def __repr__(self):
        return "DesignPoint(%r, %.6g s)" % (self._record.get("design"), self._record.get("simulated_seconds"))


class DesignResult:
    """A design search (`rc2000sim design`, docs/design.md): best (the fastest design meeting the
    constraints, a DesignPoint, or None when none does), front (the Pareto front of time, energy,
    banks and error), points (every simulated design, in the search's order), reference (the paper's two-lane
    design on the same workload), the workload, constraints, counts (designs, infeasible,
    pruned_spare_banks, simulated), software_seconds (15 bits'), widths (every width solved: its steps,
    software time and error against one double-precision solve of reference_steps), roofline, and best_device (the best design's
    device profile, best-device.json, for run(device=...) once written to a file). run_command: the
    `rc2000sim run` line of a loaded output folder (it names that folder's files; None for a call)."""

    def __init__(self, document, best_device=None):
        document = json.loads(json.dumps(document))  # a copy: to_dict() is the document as given
        best = document.get("best")
        self.run_command = best.pop("run_command", None) if isinstance(best, dict) else None
        self._document = document
        self.best_device = best_device
        self.device = document.get("device")
        self.workload = document.get("workload")
        self.constraints = document.get("constraints")
        for key in ("designs", "infeasible", "pruned_spare_banks", "simulated", "infeasible_examples",
                    "software_seconds", "reference_steps", "widths", "roofline"):
            setattr(self, key, document.get(key))
        self.best = DesignPoint(best) if best else None
        self.reference = DesignPoint(document["reference"]) if document.get("reference") else None
        self.front = [DesignPoint(p) for p in document.get("front", [])]
        self.points = [DesignPoint(p) for p in document.get("points", [])]

    def to_dict(self):
        """design.json's document (schema rc2000sim.design/1) without the best design's run command."""
        return self._document

    def to_dataframe(self):
        """One row per simulated design: the point records' columns with the bound spread into bound_run,
        bound_fpga_stream, bound_fpga_share, bound_fpga_next and bound_text, the fidelity spread into
        fidelity_relative_rmse, fidelity_software_seconds, ...; on_front, and best (the fastest design
        meeting the constraints)."""
        best = self.best.design if self.best else None
        rows = []
        for p in self._document.get("points", []):
            row = {k: v for k, v in p.items() if k not in ("bound", "fidelity")}
            row.update({"bound_" + k: v for k, v in p.get("bound", {}).items()})
            row.update({"fidelity_" + k: v for k, v in (p.get("fidelity") or {}).items()})
            row["best"] = p.get("design") == best
            rows.append(row)
        return _dataframe(rows)

    def __len__(self):
        return len(self.points)

    def __repr__(self):
        return "DesignResult(%s: %d simulated, best %s)" % (self.device, len(self.points),
                                                          self.best.design if self.best else None)


def _load_design(folder, listed):
    path = os.path.join(folder, "design.json")
    document = _object(path, _read_json(path), "rc2000sim.design/1")
    best_device = None
    if _present(folder, "best-device.json", listed):
        profile = os.path.join(folder, "best-device.json")
        best_device = _object(profile, _read_json(profile))
    try:
        return DesignResult(document, best_device)
    except (AttributeError, KeyError, TypeError) as e:
        raise OutputError("%s: not a design document as rc2000sim writes it (%s: %s)" %
                          (path, type(e).__name__, e)) from None


def load(folder):
    """Outputs already written: a study over several scenes (study.csv), a sweep (sweep.csv), a design
    search (design.json) or a run (report.json). Only the files the folder's listing names count
    (rc2000sim-outputs.txt: the last command's outputs; docs/outputs.md), so a file an earlier command
    left is never read. Values keep the writer's types (a sweep's rows from its sweep.json: a scene
    named "007" stays text). FileNotFoundError naming the folder and the files looked for when there
    are none; OutputError (a ValueError) naming the file and the line or key of a damaged one."""
    listed = _listed(folder)
    for name in ("study.csv", "sweep.csv"):
        if _present(folder, name, listed):
            study = ""
            if _present(folder, "study.json", listed):
                record = os.path.join(folder, "study.json")
                study = _find(_object(record, _read_json(record)), "name") or ""
            rows = _study_rows(folder, listed) if name == "study.csv" else _sweep_rows(folder, listed)
            return SweepResult(rows, study)
    if _present(folder, "design.json", listed):
        return _load_design(folder, listed)
    if _present(folder, "report.json", listed):
        path = os.path.join(folder, "report.json")
        return RunResult(_object(path, _read_json(path), "rc2000sim.run/1"))
    raise FileNotFoundError("%s: no study.csv, sweep.csv, design.json or report.json%s (rc2000tlm.load reads "
                            "rc2000sim's outputs)" % (folder, "" if listed is None else " among the files its " +
                                                      LISTING + " lists"))


class PaperResult:
    """Table 2 as `rc2000sim paper` predicts it: one record per scene and implementation (software,
    one_pipe, two_pipes, concurrent) with seconds, the paper's seconds for the calibration cells, the
    driver-model spread for the predicted ones, FPGA busy time and speedup (paper.json's scene records)."""

    def __init__(self, rows):
        self.rows = rows

    def to_dict(self):
        return {"rows": self.rows}

    def to_dataframe(self):
        return _dataframe(self.rows)

    def __repr__(self):
        return "PaperResult(%d cells)" % len(self.rows)
