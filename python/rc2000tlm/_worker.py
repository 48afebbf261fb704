"""One call of the C++ core in a process of its own (SystemC elaborates once per process):
`python3 -m rc2000tlm._worker RESULT_FILE` reads {"function", "kwargs"} as JSON on stdin and writes
{"result": text} or {"error": exception class name, "message": text} to RESULT_FILE (not stdout, where
SystemC prints its own notes)."""
import json
import sys


def main():
    request = json.load(sys.stdin)
    try:
        from . import _core
        response = {"result": getattr(_core, request["function"])(**request["kwargs"])}
    except Exception as e:  # every error goes back to the caller, with its message
        response = {"error": type(e).__name__, "message": str(e)}
    with open(sys.argv[1], "w") as f:
        json.dump(response, f)


if __name__ == "__main__":
    main()
