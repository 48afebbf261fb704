"""The command line every plot script shares.

  SCRIPT INPUT OUTPUT   draws once.
  SCRIPT -              reads INPUT<TAB>OUTPUT lines from stdin and draws each: rc2000sim starts the
                        interpreter (and matplotlib's import, ~0.4 s) while it is still computing on
                        the other core, and sends the request when the CSV is written (apps/plot.h).

A SIGTERM or SIGINT (rc2000sim interrupted: studies/child_guard.h) stops the drawing at once; the
picture being saved is removed, never renamed into place, and the script exits 128 + the signal.

side_by_side() draws independent figures in forked copies of the interpreter (matplotlib already
loaded), one per core: `rc2000sim paper` waits for its four figures at its very end. A copy ends
with its parent (PR_SET_PDEATHSIG, and the parent's signal handler ends the copies before it
exits), so an interrupted command still leaves no script drawing.
"""
import ctypes
import os
import signal
import sys
import traceback

_copies = []  # pids of the forked copies still drawing


class Interrupted(BaseException):
    """Raised by the signal handlers; a BaseException, so no plot code's `except Exception` eats it."""


def _interrupted(signum, frame):
    raise Interrupted(signum)


def save(fig, path, **options):
    """fig.savefig(path), atomically: a temporary file beside it, then a rename, so a reader never
    sees half a picture and a drawing that fails leaves none (docs/outputs.md)."""
    temporary = f"{path}.partial-{os.getpid()}"
    try:
        fig.savefig(temporary, format="png", **options)
        os.replace(temporary, path)
    finally:
        if os.path.exists(temporary):
            os.remove(temporary)
    _list(path)


LISTING = "rc2000sim-outputs.txt"  # apps/outputs.h, kOutputListing


def _list(path):
    """Adds a saved picture to the listing of the command's output folder (RC2000SIM_OUTPUT_FOLDER,
    set by rc2000sim: apps/outputs.h, Outputs::own_folder), when the picture lies inside it and the
    command has written its listing: the next command into the folder then removes it unless it
    draws it again (docs/outputs.md, "Output folders own their files"). The file lines stay sorted
    (as rc2000sim writes them), so the listing does not depend on the order the pictures were drawn
    in; the forked copies drawing side by side take turns (a lock on the folder) and each rewrite
    is atomic."""
    folder = os.environ.get("RC2000SIM_OUTPUT_FOLDER")
    if not folder:
        return
    listing = os.path.join(folder, LISTING)
    relative = os.path.relpath(os.path.abspath(path), folder)
    if relative.startswith("..") or os.path.isabs(relative) or not os.path.isfile(listing):
        return
    import fcntl
    fd = os.open(folder, os.O_RDONLY)
    try:
        fcntl.flock(fd, fcntl.LOCK_EX)
        with open(listing, encoding="utf-8", errors="surrogateescape") as f:
            lines = f.read().splitlines()
        head = [line for line in lines if not line.startswith("file ")]
        files = sorted({line for line in lines if line.startswith("file ")} | {f"file {relative}"})
        temporary = f"{listing}.partial-{os.getpid()}"
        try:
            with open(temporary, "w", encoding="utf-8", errors="surrogateescape") as f:
                f.write("\n".join(head + files) + "\n")
            os.replace(temporary, listing)
        finally:
            if os.path.exists(temporary):
                os.remove(temporary)
    finally:
        os.close(fd)


def _die_with_parent():
    """The kernel sends this process SIGTERM when its parent ends (Linux; elsewhere nothing)."""
    try:
        libc = ctypes.CDLL(None, use_errno=True)
        libc.prctl(1, signal.SIGTERM)  # PR_SET_PDEATHSIG
    except (OSError, AttributeError):
        pass


def _end_copies():
    for pid in list(_copies):
        try:
            os.kill(pid, signal.SIGTERM)
            os.waitpid(pid, 0)
        except (ProcessLookupError, ChildProcessError):
            pass
        _copies.remove(pid)


def side_by_side(*groups):
    """Calls each group of drawings (a list of callables; empty groups are skipped) in its own
    process, at most one per core: the first group here, the others in forked copies. Each figure is what it would be drawn
    alone. Exits with an error when a copy failed."""
    groups = [group for group in groups if group]
    cores = max(1, min(len(groups), os.cpu_count() or 1))
    shares = [[task for group in groups[k::cores] for task in group] for k in range(cores)]
    started = []
    for share in shares[1:]:
        sys.stdout.flush()
        sys.stderr.flush()
        pid = os.fork()
        if pid == 0:
            code = 0
            try:
                _die_with_parent()
                for task in share:
                    task()
            except Interrupted as stop:
                code = 128 + stop.args[0]
            except BaseException:  # noqa: B036 - a copy reports every failure and exits
                traceback.print_exc()
                code = 1
            finally:
                sys.stdout.flush()
                sys.stderr.flush()
                os._exit(code)
        _copies.append(pid)
        started.append(pid)
    for task in shares[0]:
        task()
    failed = 0
    for pid in started:
        _, status = os.waitpid(pid, 0)
        _copies.remove(pid)
        failed += status != 0
    if failed:
        sys.exit(f"{failed} of the forked drawing processes failed")


def run(main, usage):
    for signum in (signal.SIGTERM, signal.SIGINT, signal.SIGHUP):
        signal.signal(signum, _interrupted)
    try:
        _run(main, usage)
    except Interrupted as stop:
        _end_copies()
        sys.stdout.flush()
        os._exit(128 + stop.args[0])
    # Done: every picture is saved and closed (save). The interpreter's own teardown (freeing
    # matplotlib's modules, ~0.07 s) would only delay the rc2000sim command waiting for this process.
    sys.stdout.flush()
    sys.stderr.flush()
    os._exit(0)


def _run(main, usage):
    if len(sys.argv) == 2 and sys.argv[1] == "-":
        for line in sys.stdin:
            fields = line.rstrip("\n").split("\t")
            if len(fields) != 2:
                sys.exit(f"{usage} (stdin lines: INPUT<TAB>OUTPUT)")
            main(*fields)
        return
    if len(sys.argv) != 3:
        sys.exit(usage)
    main(sys.argv[1], sys.argv[2])
