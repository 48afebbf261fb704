#!/usr/bin/env bash
# report.json's settings record every `rc2000sim run` option that can change a figure (issue 39;
# docs/outputs.md, report.json): walks the options `run --help` lists, so a new option fails here
# until the report records it or the list below says why no figure depends on it. Then checks that the
# settings follow the options given (the CPU/FPGA split, the pipelined driver's chunks, lanes, banks).
#   report_settings_test.sh RC2000SIM
set -euo pipefail
sim="$1"
work="$(mktemp -d)"; trap 'rm -rf "$work"' EXIT
tiny=(--impl board --faces 70 --patch-levels 0 --steps 3 --image-size 16 --quiet)
"$sim" run --help > "$work/help.txt"
"$sim" run "${tiny[@]}" --out "$work/plain" > /dev/null
"$sim" run "${tiny[@]}" --cpu-share 0.25 --cpu-cores 2 --lanes 2 --banks 7 --out "$work/split" > /dev/null
"$sim" run "${tiny[@]}" --chunk-rays 64 --out "$work/chunks" > /dev/null
"$sim" run --faces 70 --patch-levels 0 --steps 3 --image-size 16 --quiet --out "$work/software" > /dev/null
python3 - "$work" <<'PY'
import json, re, sys
work = sys.argv[1]
# Options whose key in settings has another name.
RENAMED = {"--faces": "face_target", "--steps": "fixed_steps"}
# Options no figure depends on, each with the reason.
NO_FIGURE = {
    "--help": "prints the options",
    "--out": "where the files go",
    "--quiet": "progress on stderr only",
    "--jobs": "threads of the fast backend; outputs do not depend on them (TimingStudy.*ChangeNoOutcome)",
    "--trace": "writes a trace file of the run, no figure",
    "--trace-steps": "the steps the trace file holds",
    "--vcd": "writes a VCD of the run, no figure",
    "--configs": "where named profiles are looked for; the settings name the profiles (device, host)",
}
options = sorted(set(re.findall(r"^\s+(?:-\w,\s*)?(--[a-z][a-z0-9-]*)", open(work + "/help.txt").read(), re.M)))
assert len(options) > 30, options
reports = {name: json.load(open("%s/%s/report.json" % (work, name))) for name in ("plain", "split", "chunks", "software")}
missing = []
for option in options:
    if option in NO_FIGURE:
        continue
    key = RENAMED.get(option, option[2:].replace("-", "_"))
    for name, report in reports.items():
        if key not in report["settings"]:
            missing.append("%s (settings.%s, %s run)" % (option, key, name))
if missing:
    sys.exit("report.json's settings lack options that can change a figure: " + ", ".join(missing))
split, chunks, plain, software = (reports[n]["settings"] for n in ("split", "chunks", "plain", "software"))
assert (split["cpu_share"], split["cpu_cores"], split["lanes"], split["banks"]) == (0.25, 2, 2, 7), split
assert chunks["chunk_rays"] == 64 and plain["chunk_rays"] == 0 and plain["cpu_share"] is None, (chunks, plain)
assert plain["banks"] == reports["plain"]["board"]["device"]["banks"], "banks: the profile's count as used"
assert software["device"] is None and software["cpu_share"] is None, software
print("report.json's settings: %d options recorded, %d without a figure (%s)" %
      (len(options) - len(NO_FIGURE), len(NO_FIGURE), ", ".join(sorted(NO_FIGURE))))
PY
