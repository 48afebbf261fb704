"""The worker processes: each call of the C++ core (rc2000tlm._core) runs in a fresh process of its
own (`python3 -m rc2000tlm._worker`; SystemC elaborates once per process), at most as many at once as
`jobs` says (run_many; the command line's --jobs and its rule: RC2000SIM_JOBS, else the cores this process
may use). Every function takes jobs= (None: that rule), checked by the C++ side as --jobs is. A fresh interpreter per call, not multiprocessing's spawn, so that callers
whose main module is no file (`python3 -`, notebooks) work the same."""
import builtins
import concurrent.futures
import json
import math
import os
import subprocess
import signal
import sys
import tempfile
import threading
import time

from .results import DesignResult, PaperResult, RunResult, SweepResult


def _find_configs(env):
    """The installed configs of the prefix this package is installed in, unless RC2000SIM_CONFIGS is
    set (io/config_dir.h); a build tree's package finds the source tree's configs by itself."""
    if env.get("RC2000SIM_CONFIGS"):
        return
    folder = os.path.dirname(os.path.abspath(__file__))
    for _ in range(6):
        folder = os.path.dirname(folder)
        configs = os.path.join(folder, "share", "rc2000tlm", "configs")
        if os.path.isdir(configs):
            env["RC2000SIM_CONFIGS"] = configs
            return


def _worker_env():
    env = dict(os.environ)
    package_parent = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    env["PYTHONPATH"] = os.pathsep.join(p for p in (package_parent, env.get("PYTHONPATH")) if p)
    _find_configs(env)
    return env


def _exception(name, message):
    kind = getattr(builtins, name, None)
    if not (isinstance(kind, type) and issubclass(kind, Exception)):
        kind = RuntimeError
    return kind(message)


class _Workers:
    """The worker processes alive now, so that an interrupted or failed call ends them all: each runs
    in a session (process group) of its own, and terminate_all() signals the whole group (the core's
    own children included), then kills what is left after a grace period."""

    def __init__(self):
        self._lock = threading.Lock()
        self._live = set()
        self.stopping = False

    def add(self, process):
        with self._lock:
            if self.stopping:  # a call started after the stop: end it at once
                _signal_group(process, signal.SIGKILL)
            self._live.add(process)

    def remove(self, process):
        with self._lock:
            self._live.discard(process)

    def terminate_all(self, grace=1.0):
        with self._lock:
            self.stopping = True
            live = list(self._live)
        for p in live:
            _signal_group(p, signal.SIGTERM)
        deadline = time.monotonic() + grace
        for p in live:
            try:
                p.wait(max(0.0, deadline - time.monotonic()))
            except subprocess.TimeoutExpired:
                _signal_group(p, signal.SIGKILL)
                p.wait()


def _signal_group(process, sig):
    try:
        os.killpg(process.pid, sig)
    except (ProcessLookupError, PermissionError):
        pass


def _call(function, kwargs, show_progress, workers=None):
    """One call in a fresh worker process; its JSON result, or the worker's exception raised here. The
    result comes back through an unlinked temporary file whose descriptor the worker inherits, so
    nothing is left on disk whatever happens to either process; the worker dies with its caller
    (rc2000tlm._worker sets PR_SET_PDEATHSIG)."""
    with tempfile.TemporaryFile(prefix="rc2000tlm-") as result:
        fd = result.fileno()
        process = subprocess.Popen([sys.executable, "-m", "rc2000tlm._worker", str(fd), str(os.getpid())],
                                   stdin=subprocess.PIPE, stdout=subprocess.DEVNULL,
                                   stderr=None if show_progress else subprocess.PIPE, text=True,
                                   env=_worker_env(), pass_fds=(fd,), start_new_session=True)
        if workers is not None:
            workers.add(process)
        try:
            _, err = process.communicate(json.dumps({"function": function, "kwargs": kwargs}))
        finally:
            if workers is not None:
                workers.remove(process)
        if workers is not None and workers.stopping:
            raise _Stopped()
        result.seek(0)
        text = result.read().decode("utf-8")
    if not text:
        tail = (err or "").strip().splitlines()[-5:]
        raise RuntimeError("rc2000tlm: the worker process for %s ended without a result (exit status %d)%s"
                           % (function, process.returncode, (": " + " | ".join(tail)) if tail else ""))
    response = json.loads(text)
    if "error" in response:
        raise _exception(response["error"], response["message"])
    return json.loads(response["result"])


class _Stopped(Exception):
    """A call ended because the others were stopped (an interrupt, or another call's error)."""


def _jobs(jobs):
    """The job count: `jobs` checked as `rc2000sim --jobs` checks it (a ValueError with its message), or
    the rule's (RC2000SIM_JOBS, else the cores this process may use), as the C++ side has it."""
    return _call("jobs", {"jobs": jobs}, False)


def _submit_all(calls, progress, what, show_worker_progress=False, workers=1, labels=None):
    """Runs (function, kwargs) calls, each in its own worker process, at most `workers` at once;
    their JSON results in order. progress: a count of finished calls on stderr.

    Nothing outlives the call: on KeyboardInterrupt (Ctrl-C) or the first call that fails, the calls not
    started are cancelled and the running workers (and their children) are terminated within about a
    second, then the exception is raised. With several calls, a failure names the call (labels[i], or
    "call i of n") and carries every result that had finished as `.results` (None for the others)."""
    live = _Workers()
    results = [None] * len(calls)
    pool = concurrent.futures.ThreadPoolExecutor(max_workers=workers)
    futures = {}
    try:
        futures = {pool.submit(_call, f, kw, show_worker_progress, live): i for i, (f, kw) in enumerate(calls)}
        done = 0
        pending = set(futures)
        while pending:
            # A timeout, so that the main thread wakes for Ctrl-C however long a worker takes.
            finished, pending = concurrent.futures.wait(pending, timeout=0.2,
                                                        return_when=concurrent.futures.FIRST_COMPLETED)
            for future in finished:
                i = futures[future]
                error = future.exception()
                if error is not None:
                    raise _named(error, i, len(calls), labels, results)
                results[i] = future.result()
                done += 1
                if progress and len(calls) > 1:
                    print("\r%s: %d of %d done" % (what, done, len(calls)), end="", file=sys.stderr, flush=True)
        if progress and len(calls) > 1:
            print(file=sys.stderr)
        return results
    except BaseException:
        for future in futures:
            future.cancel()
        live.terminate_all()
        raise
    finally:
        pool.shutdown(wait=True)


def _named(error, i, n, labels, results):
    """The error of call i, naming it when there are several, with the finished results attached."""
    if n > 1:
        label = labels[i] if labels else "call %d of %d" % (i + 1, n)
        named = type(error)("%s: %s" % (label, error)) if type(error) in (ValueError, RuntimeError, TypeError) \
            else RuntimeError("%s: %s: %s" % (label, type(error).__name__, error))
        named.__cause__ = error
        error = named
    error.results = list(results)
    return error


_OPTION_TABLES = {}  # a command's option table, read once per process (run_options(), sweep_options())


def _option_table(function):
    if function not in _OPTION_TABLES:
        _OPTION_TABLES[function] = _submit_all([(function, {})], False, "options")[0]
    return _OPTION_TABLES[function]


def run_options():
    """`rc2000sim run`'s options by snake_case name, from the command line's own table
    (apps/run_command.h): {"default": the default it shows as text, or None; "flag": whether it takes
    no value; "negation": a flag's name that turns it off, or None}. run() takes exactly these, plus progress."""
    return _option_table("run_options")


def sweep_options():
    """`rc2000sim sweep`'s study options (scene, solver, axes, backend) by snake_case name, as run_options()
    shows run's; sweep() takes them by these names."""
    return _option_table("sweep_options")


def _cli_text(name, v):
    """A value as the command line spells it: a list or tuple joined with commas, True and False as on
    and off, a float in its shortest exact form (repr), a numpy or pandas scalar as its Python value."""
    if isinstance(v, (list, tuple)):
        return ",".join(_cli_text(name, x) for x in v)
    if hasattr(v, "item") and not isinstance(v, (str, bytes)):
        v = v.item()
    if isinstance(v, bool):
        return "on" if v else "off"
    if isinstance(v, float):
        return repr(v)
    return str(v)


def _command_args(command, known, options):
    """Keyword options as `rc2000sim COMMAND` arguments: every name one of the command's (else a TypeError
    naming it, as Python does), a flag given as True (False: its negation when it has one, else not
    given), the rest as text that the command's own table parses and checks."""
    for name in options:
        if name not in known:
            raise TypeError("rc2000tlm.%s() got an unexpected keyword argument '%s' (the options of "
                            "`rc2000sim %s`: %s, and progress)" % (command, name, command, ", ".join(known)))
    args = []
    for name, v in options.items():
        if v is None:
            continue
        flag = "--" + name.replace("_", "-")
        if known[name]["flag"]:
            if not isinstance(v, bool):
                raise ValueError("%s: expected True or False, got %r" % (flag, v))
            if v:
                args.append(flag)
            elif known[name].get("negation"):
                args.append("--" + known[name]["negation"])
        else:
            args += [flag, _cli_text(name, v)]
    return args


def _run_call(options):
    """run()'s options as `rc2000sim run` arguments (_command_args). Two defaults are the module's:
    --impl board (run() is a board run unless impl= says otherwise) and no output files unless out=."""
    options = dict(options)
    progress = bool(options.pop("progress", False))
    args = _command_args("run", run_options(), options)
    if options.get("impl") is None:
        args = ["--impl", "board"] + args
    if not progress and not options.get("quiet"):
        args.append("--quiet")
    return {"args": args, "write_outputs": options.get("out") is not None, "summary": False}


def run(**options):
    """One run as `rc2000sim run` does it, with its options by the same names in snake_case (run_options()
    lists them with their defaults: scene, patch_levels, patch_size, faces, face_levels, steps,
    form_factor, paper_faithful, device, lanes, bits, arith, banks, concurrent, host, cards, jobs,
    fidelity_sample, ...), the same checks and messages (a refused value is a ValueError with the
    command's words, an unknown name a TypeError). impl defaults to "board" (the command's default is
    software); out= writes the command's files there (none without it); progress=True shows the run's
    progress line on stderr. Returns a RunResult: report.json's document with per-step records."""
    return RunResult(_submit_all([("run", _run_call(options))], False, "runs")[0])


def run_many(option_sets, progress=True, jobs=None):
    """Several board runs at once: a list of run() option dicts; their RunResults in the same order.
    jobs: how many run at once (as --jobs, checked the same way; None: RC2000SIM_JOBS, else the cores
    this process may use). progress: a count of finished runs on stderr. The first option set that fails
    ends the call at once (the running runs are stopped) with its error, naming the set; the runs that
    had finished are in the exception's `results` (a RunResult, or None, per set)."""
    calls = [("run", _run_call(o)) for o in option_sets]
    labels = ["run_many: option set %d of %d %r" % (i + 1, len(option_sets), o) for i, o in enumerate(option_sets)]
    try:
        return [RunResult(d) for d in _submit_all(calls, progress, "runs", workers=_jobs(jobs), labels=labels)]
    except Exception as e:  # the finished runs stay reachable: e.results, RunResult or None in order
        e.results = [None if d is None else RunResult(d) for d in getattr(e, "results", [])]
        raise


def study(path, progress=False, jobs=None):
    """A study file (TOML, docs/studies.md) run on this machine; a SweepResult (a `scene` column when
    the study has several scenes). progress: the study's own progress line on stderr. jobs: the
    study's processes and threads, as --jobs (None: the rule's)."""
    kwargs = {"path": os.path.abspath(path), "progress": progress, "jobs": jobs}
    return SweepResult.from_core(_submit_all([("study_file", kwargs)], False, "studies", progress)[0])


def _toml_value(v):
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, (int, float)):
        return repr(v)
    if isinstance(v, str):
        return json.dumps(v)  # a TOML basic string is a JSON string for what a study holds
    if isinstance(v, (list, tuple)):
        return "[" + ", ".join(_toml_value(x) for x in v) + "]"
    if isinstance(v, dict):
        return "{ " + ", ".join("%s = %s" % (_toml_key(k), _toml_value(x)) for k, x in v.items()) + " }"
    raise TypeError("rc2000tlm.sweep: a value of type %s has no study-file form: %r" % (type(v).__name__, v))


def _toml_key(k):
    return k if k.replace("_", "").replace("-", "").isalnum() else json.dumps(k)


def study_text(scenes=None, steps=None, name="python", fixed=None, resources=None, **axes):
    """The study file (TOML) that sweep() runs: scenes as [[scenes]] tables, steps under [solver],
    resources ("paper" or "synthesis", the study's top-level key; None: the study default, paper), the
    keyword arguments under [axes] (as a study file spells them: devices, bits, lanes, banks,
    concurrent, "banks.clock_mhz", ...) and `fixed` under [fixed]."""
    lines = ["name = %s" % _toml_value(name)]
    if resources is not None:
        lines.append("resources = %s" % _toml_value(resources))
    for s in scenes or []:
        lines += ["", "[[scenes]]"] + ["%s = %s" % (_toml_key(k), _toml_value(v)) for k, v in s.items()]
    if steps is not None:
        lines += ["", "[solver]", "steps = %s" % _toml_value(steps)]
    if axes:
        lines += ["", "[axes]"] + ["%s = %s" % (_toml_key(k), _toml_value(v)) for k, v in axes.items()]
    if fixed:
        lines += ["", "[fixed]"] + ["%s = %s" % (_toml_key(k), _toml_value(v)) for k, v in fixed.items()]
    return "\n".join(lines) + "\n"


def sweep(scenes=None, steps=None, name="python", fixed=None, resources=None, progress=False, jobs=None, **axes):
    """A sweep, in one of two forms. With only `rc2000sim sweep`'s options (sweep_options() lists them:
    scene, faces, face_levels, patch_levels, patch_size, steps, convergence, lanes, banks, bits, devices,
    concurrent, paper_faithful, cards, card_split, card_bus, host, visibility, form_factor, full_banks,
    resources, configs), the command's own table parses and checks them: the study `rc2000sim sweep` would
    run, with its defaults and words. Otherwise a study (docs/studies.md) made from the arguments
    (study_text shows the file): scenes as [[scenes]] tables (None: the paper's scene), axes as a study
    file spells them (devices, bits, lanes, "banks.clock_mhz", ...), `fixed` and `name`. jobs: as --jobs
    (None: the rule's). Returns a SweepResult (its warnings: a profile axis that changed nothing)."""
    command = dict(axes, steps=steps, resources=resources)
    command = {k: v for k, v in command.items() if v is not None}
    known = sweep_options()
    if scenes is None and fixed is None and name == "python" and all(k in known for k in command):
        kwargs = {"args": _command_args("sweep", known, command), "progress": progress, "jobs": jobs}
        return SweepResult.from_core(_submit_all([("sweep", kwargs)], False, "studies", progress)[0])
    # The study form: a name only the command's form has (scene, faces, ...) cannot be one of its axes.
    study_names = {"lanes", "banks", "bits", "devices", "concurrent", "cards", "steps", "resources"}
    command_only = sorted(k for k in command if k in known and k not in study_names)
    if command_only:
        other = sorted(set(k for k in command if k not in known) | {k for k, v in (("scenes", scenes), ("fixed", fixed))
                                                                      if v is not None} | ({"name"} if name != "python" else set()))
        raise TypeError("rc2000tlm.sweep(): %s %s `rc2000sim sweep`'s option form, but %s %s not (the study form: "
                        "scenes=, fixed=, name=, profile-path axes, or a name of neither form); use one form: the "
                        "study form spells the workload in scenes=[{...}]"
                        % (", ".join(command_only), "is of" if len(command_only) == 1 else "are of", ", ".join(other),
                           "is" if len(other) == 1 else "are"))
    text = study_text(scenes=scenes, steps=steps, name=name, fixed=fixed, resources=resources, **axes)
    kwargs = {"text": text, "name": "rc2000tlm.sweep(%s)" % name, "progress": progress, "jobs": jobs}
    return SweepResult.from_core(_submit_all([("study_text", kwargs)], False, "studies", progress)[0])


def paper(host="athlon-mp-2600-calibrated", progress=False, jobs=None):
    """Table 2 predicted as `rc2000sim paper` does (the paper's table, the calibrated host profile and its
    driver-model variants); a PaperResult. Minutes of work: progress shows its phases on stderr. jobs:
    as `rc2000sim paper --jobs` (None: RC2000SIM_JOBS, else the cores this process may use)."""
    kwargs = {"host": host, "progress": progress, "jobs": jobs}
    return PaperResult(_submit_all([("paper_table", kwargs)], False, "paper", progress)[0])


def _design_value(v):
    """A value as the C++ side reads it: a list or tuple joined as the command line lists it ("1,2,4"),
    a number that JSON cannot hold (NaN, infinity) as its text, so that it is refused by name."""
    if isinstance(v, (list, tuple)):
        return ",".join(str(_design_value(x)) for x in v)
    if hasattr(v, "item") and not isinstance(v, (str, bytes)):  # a numpy or pandas scalar
        v = v.item()
    if isinstance(v, float) and not math.isfinite(v):
        return repr(v)
    return v


def design(progress=False, **options):
    """A design search as `rc2000sim design` runs it (docs/design.md): the fastest feasible design of one
    device for one workload and the Pareto front of time, energy, banks and error, every figure simulated.
    The options are the command's, by the same names in snake_case (scene, faces, face_levels,
    patch_levels, patch_size, steps, culled, form_factor, device, host, lanes, banks, bank_clocks,
    results, bits, multipliers, resources, cards, concurrent, offset_lsb, neighbour_rings, coordinate_bits (the
    segment fixes as axes, 0 for off), ray_split, max_banks, min_bits, max_energy, max_power,
    max_error, max_error_max, fidelity ('on', 'off' or a bool), exhaustive, jobs, configs), with the command's defaults (design_defaults() lists them); an axis takes the
    command's text ("1-4"), a list ([1, 2, 4]) or one value. An option the command does not have is a
    TypeError; a value it refuses is a ValueError with its message. progress: the search's phases on
    stderr. Returns a DesignResult."""
    given = {k: _design_value(v) for k, v in options.items() if v is not None}
    kwargs = {"options": json.dumps(given), "progress": progress}
    response = _submit_all([("design", kwargs)], False, "design", progress)[0]
    return DesignResult(response["design"], response["best_device"])


def design_defaults():
    """The design search's defaults by option name, from the C++ options (the command line's); None
    where the command's rule applies (lanes: 1 .. the most that fit; banks: 5 .. max_banks; bank
    clocks: the profile's; steps: Table 2's for a paper scene, else to convergence; max_banks: the
    profile's count; no energy, power or error cap)."""
    return _submit_all([("design_defaults", {})], False, "design")[0]
