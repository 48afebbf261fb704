"""rc2000tlm's worker processes never outlive a call (issue 39; python/rc2000tlm/workers.py):
  1. Ctrl-C (SIGINT) during a long run() raises KeyboardInterrupt within 2 s, with no worker left;
  2. a caller killed with SIGKILL leaves no worker (PR_SET_PDEATHSIG) and no result file (an unlinked
     temporary file carries the result);
  3. run_many(): the first option set that fails ends the call at once, named, and the finished
     runs are in the exception's `results`.
Prints "SKIP: <reason>" and exits 77 without the module.
usage: workers_test.py BUILD_DIR"""
import glob
import os
import signal
import subprocess
import sys
import tempfile
import threading
import time

build = sys.argv[1]
if not glob.glob(os.path.join(build, "python", "rc2000tlm", "_core*.so")):
    print("SKIP: the Python module was not built (RC_BUILD_PYTHON=OFF, or pybind11-dev / python3-dev missing)")
    sys.exit(77)
sys.path.insert(0, os.path.join(build, "python"))
os.environ["SYSTEMC_DISABLE_COPYRIGHT_MESSAGE"] = "1"
import rc2000tlm  # noqa: E402

LONG = dict(patch_levels=4, lanes=1)  # the box at 9,728 patches to convergence: far longer than the test waits


def workers_alive(caller):
    """The workers started by process `caller` (their command line names it: rc2000tlm._worker FD PID),
    so that other processes' workers on the machine are not counted."""
    out = subprocess.run(["pgrep", "-f", r"rc2000tlm\._worker [0-9]+ %d$" % caller], capture_output=True, text=True).stdout.split()
    return [p for p in out if int(p) != os.getpid()]


def result_files():
    return glob.glob(os.path.join(tempfile.gettempdir(), "rc2000tlm-*"))


files_before = set(result_files())
ME = os.getpid()

# 1. Ctrl-C.
sent = []
def interrupt():
    time.sleep(2)
    sent.append(time.monotonic())
    os.kill(os.getpid(), signal.SIGINT)
threading.Thread(target=interrupt, daemon=True).start()
try:
    rc2000tlm.run(**LONG)
    sys.exit("FAIL: the long run ended before the interrupt")
except KeyboardInterrupt:
    waited = time.monotonic() - sent[0]
assert waited < 2.0, "KeyboardInterrupt came %.2f s after SIGINT" % waited
assert not workers_alive(ME), "a worker outlived the interrupted call"
print("1. Ctrl-C: KeyboardInterrupt %.2f s after the signal, no worker left" % waited)

# 2. The caller killed.
caller = subprocess.Popen([sys.executable, "-c", "import sys; sys.path.insert(0, %r); import rc2000tlm; "
                           "rc2000tlm.run(patch_levels=4, lanes=1)" % os.path.join(build, "python")])
deadline = time.monotonic() + 30
while not workers_alive(caller.pid) and time.monotonic() < deadline:
    time.sleep(0.1)
assert workers_alive(caller.pid), "the caller started no worker"
caller.kill()
caller.wait()
deadline = time.monotonic() + 5
while workers_alive(caller.pid) and time.monotonic() < deadline:
    time.sleep(0.1)
assert not workers_alive(caller.pid), "a worker outlived its killed caller"
assert set(result_files()) <= files_before, "result files left: %s" % (set(result_files()) - files_before)
print("2. caller killed: no worker, no file left")

# 3. run_many fails fast, naming the set, keeping what finished.
start = time.monotonic()
try:
    rc2000tlm.run_many([dict(steps=1, patch_levels=1), dict(LONG), dict(steps=1, patch_levels=1, bits=99)],
                       progress=False, jobs=2)
    sys.exit("FAIL: run_many accepted bits=99")
except ValueError as e:
    took = time.monotonic() - start
    message = str(e)
    results = e.results
assert "option set 3 of 3" in message and "--bits: Value 99 not in range 7 to 31" in message, message
assert took < 20, "run_many took %.1f s to fail (it waited for the long run)" % took
assert len(results) == 3 and results[2] is None and results[1] is None, results
assert results[0] is None or results[0].steps == 1, results
assert not workers_alive(ME), "a worker outlived the failed run_many"
print("3. run_many: failed after %.1f s: %s; finished: %s" % (took, message[:80], [r is not None for r in results]))
print("PASS")
