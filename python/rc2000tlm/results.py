"""Typed results: RunResult (one board run), SweepResult (a sweep's or a study's rows), PaperResult
(Table 2) and DesignResult (a design search), each with to_dict() and pandas DataFrames; load(folder)
reads what rc2000sim or these wrote."""
import csv
import json
import os


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


def _number(text):
    if text == "":
        return None
    for kind in (int, float):
        try:
            return kind(text)
        except ValueError:
            pass
    return text


def _read_rows(path):
    with open(path, newline="") as f:
        return [{k: _number(v) for k, v in row.items()} for row in csv.DictReader(f)]


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


def _load_design(folder):
    with open(os.path.join(folder, "design.json")) as f:
        document = json.load(f)
    best_device = None
    profile = os.path.join(folder, "best-device.json")
    if os.path.isfile(profile):
        with open(profile) as f:
            best_device = json.load(f)
    return DesignResult(document, best_device)


def load(folder):
    """Outputs already written: a study over several scenes (study.csv), a sweep (sweep.csv), a design
    search (design.json) or a run (report.json); FileNotFoundError naming the folder and the files
    looked for otherwise."""
    for name in ("study.csv", "sweep.csv"):
        path = os.path.join(folder, name)
        if os.path.isfile(path):
            study = ""
            record = os.path.join(folder, "study.json")
            if os.path.isfile(record):
                study = _find(json.load(open(record)), "name") or ""
            return SweepResult(_read_rows(path), study)
    if os.path.isfile(os.path.join(folder, "design.json")):
        return _load_design(folder)
    report = os.path.join(folder, "report.json")
    if os.path.isfile(report):
        with open(report) as f:
            return RunResult(json.load(f))
    raise FileNotFoundError("%s: no study.csv, sweep.csv, design.json or report.json (rc2000tlm.load reads "
                            "rc2000sim's outputs)" % folder)


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
