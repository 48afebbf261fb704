"""One call of the C++ core in a process of its own (SystemC elaborates once per process):
`python3 -m rc2000tlm._worker RESULT_FD PARENT_PID` reads {"function", "kwargs"} as JSON on stdin and
writes {"result": text} or {"error": exception class name, "message": text} to the inherited file
descriptor RESULT_FD (an unlinked temporary file of the caller; not stdout, where SystemC prints its own
notes). It dies with its caller: PR_SET_PDEATHSIG (Linux) sends it SIGKILL when the caller's thread
ends, and a caller already gone when it starts (PARENT_PID no longer its parent) ends it at once."""
import ctypes
import json
import os
import signal
import sys


def _die_with_parent(parent):
    try:
        libc = ctypes.CDLL(None, use_errno=True)
        PR_SET_PDEATHSIG = 1
        libc.prctl(PR_SET_PDEATHSIG, signal.SIGKILL, 0, 0, 0)
    except (OSError, AttributeError):  # not Linux: the caller's terminate_all still ends it
        pass
    if os.getppid() != parent:
        os._exit(128 + signal.SIGKILL)


def main():
    result_fd, parent = int(sys.argv[1]), int(sys.argv[2])
    _die_with_parent(parent)
    request = json.load(sys.stdin)
    try:
        from . import _core
        response = {"result": getattr(_core, request["function"])(**request["kwargs"])}
    except Exception as e:  # every error goes back to the caller, with its message
        response = {"error": type(e).__name__, "message": str(e)}
    with os.fdopen(result_fd, "w") as f:
        json.dump(response, f)


if __name__ == "__main__":
    main()
