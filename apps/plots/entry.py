"""The command line every plot script shares.

  SCRIPT INPUT OUTPUT   draws once.
  SCRIPT -              reads INPUT<TAB>OUTPUT lines from stdin and draws each: rc2000sim starts the
                        interpreter (and matplotlib's import, ~0.4 s) while it is still computing on
                        the other core, and sends the request when the CSV is written (apps/plot.h).

A SIGTERM or SIGINT (rc2000sim interrupted: studies/child_guard.h) stops the drawing at once; the
picture being saved is removed, never renamed into place, and the script exits 128 + the signal.
"""
import os
import signal
import sys


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


def run(main, usage):
    for signum in (signal.SIGTERM, signal.SIGINT, signal.SIGHUP):
        signal.signal(signum, _interrupted)
    try:
        _run(main, usage)
    except Interrupted as stop:
        sys.stdout.flush()
        os._exit(128 + stop.args[0])


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
