"""Typed results: RunResult (one board run) and SweepResult (a sweep's or a study's rows), each with
to_dict() and pandas DataFrames; load(folder) reads what rc2000sim or these wrote."""
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
    """One board run: steps, simulated_seconds, the board report (`board`: report.json's "board"),
    and per-step records (step, convergence_reached, simulated_seconds) when the run recorded them."""

    def __init__(self, data):
        self._data = data
        self.steps = data.get("steps")
        self.simulated_seconds = data.get("simulated_seconds", _find(data, "simulated_seconds"))
        self.board = data.get("board", {})
        self.per_step = data.get("per_step", [])

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

    @classmethod
    def from_core(cls, data):
        several = len(data["scenes"]) > 1
        rows = []
        for scene in data["scenes"]:
            for row in scene["rows"]:
                rows.append(dict({"scene": scene["name"]}, **row) if several else row)
        return cls(rows, data.get("study", ""))

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


def load(folder):
    """Outputs already written: a study over several scenes (study.csv), a sweep (sweep.csv) or a run
    (report.json); FileNotFoundError naming the folder and the files looked for otherwise."""
    for name in ("study.csv", "sweep.csv"):
        path = os.path.join(folder, name)
        if os.path.isfile(path):
            study = ""
            record = os.path.join(folder, "study.json")
            if os.path.isfile(record):
                study = _find(json.load(open(record)), "name") or ""
            return SweepResult(_read_rows(path), study)
    report = os.path.join(folder, "report.json")
    if os.path.isfile(report):
        with open(report) as f:
            return RunResult(json.load(f))
    raise FileNotFoundError("%s: no study.csv, sweep.csv or report.json (rc2000tlm.load reads rc2000sim's outputs)"
                            % folder)


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
