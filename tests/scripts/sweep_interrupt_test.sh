#!/usr/bin/env bash
# An interrupted sweep takes its children with it, and the next run's folder holds only the next
# run's files (issue 27; docs/reliability.md, "Round three: commands"). Before, a sweep killed while
# its plot script drew kept that script writing PNGs for a minute, over the next run's pictures.
#   1. SIGTERM mid-plot: the sweep dies of SIGTERM (143) only after its plot script has ended; no
#      half-written picture (*.partial-*) is left.
#   2. The same study again into the same folder: every file there is newer than its start, and
#      nothing changes after it has exited.
#   3. SIGKILL mid-plot (no handler can run): the kernel ends the plot script (PR_SET_PDEATHSIG)
#      within seconds, and it leaves no half-written picture.
#   4. SIGINT while the study's worker processes compute: the workers end with the sweep.
# usage: sweep_interrupt_test.sh RC2000SIM REPO_ROOT
set -euo pipefail
set -m  # background jobs keep SIGINT (without job control a shell's & ignores it) in their own group
sim="$1"
work="$(mktemp -d "${TMPDIR:-/tmp}/sweep-interrupt-test.XXXXXX")"
sweep_pid=""
cleanup() {
  [ -z "$sweep_pid" ] || kill -KILL "$sweep_pid" 2>/dev/null || true
  rm -rf "$work"
}
trap cleanup EXIT
export SYSTEMC_DISABLE_COPYRIGHT_MESSAGE=1
fail() { echo "FAIL: $*" >&2; exit 1; }
[ -x /usr/bin/python3 ] && /usr/bin/python3 -c "import matplotlib" 2>/dev/null || { echo "SKIP: no python3-matplotlib"; exit 77; }

# 100 values of a profile axis: the sweep computes in seconds, then draws 40 of its 401 pictures (the cap).
cat > "$work/many.toml" <<'EOF'
name = "many"
[[scenes]]
paper = { faces = 70, patches = 280 }
[solver]
steps = 20
[axes]
devices = ["xc2v6000"]
lanes = [1, 2]
banks = [6]
"banks.clock_mhz" = { from = 50, to = 149, step = 1 }
EOF

start_sweep() {  # OUT: the sweep in the background; sets sweep_pid
  "$sim" sweep --study "$work/many.toml" --quiet --out "$1" > "$work/stdout.txt" 2> "$work/stderr.txt" &
  sweep_pid=$!
}
wait_for() {  # SECONDS TEST...: polls TEST every 10 ms
  local deadline=$((SECONDS + $1)); shift
  until "$@"; do
    [ "$SECONDS" -lt "$deadline" ] || return 1
    sleep 0.01
  done
}
has_png() { compgen -G "$1/*.png" > /dev/null; }
children() { pgrep -P "$sweep_pid" || true; }
alive() { local p; for p in "$@"; do kill -0 "$p" 2>/dev/null && return 0; done; return 1; }
none_alive() { ! alive "$@"; }
no_partial() { [ -z "$(find "$1" -name '*.partial-*')" ] || fail "a half-written picture was left: $(find "$1" -name '*.partial-*')"; }
finish() {  # EXPECTED-STATUS: waits for the sweep
  local rc=0
  wait "$sweep_pid" || rc=$?
  sweep_pid=""
  [ "$rc" -eq "$1" ] || { cat "$work/stderr.txt" >&2; fail "the sweep exited $rc, expected $1"; }
}

echo "1. SIGTERM while the plot script draws"
start_sweep "$work/o"
wait_for 120 has_png "$work/o" || fail "no picture within 120 s"
kids=$(children)
[ -n "$kids" ] || fail "the sweep has no child while it plots"
kill -TERM "$sweep_pid"
finish 143
# shellcheck disable=SC2086  # one pid per word
! alive $kids || fail "a child of the interrupted sweep is still running: $(ps -o pid,args -p "${kids//$'\n'/,}" | tail -n +2)"
no_partial "$work/o"
drawn=$(find "$work/o" -name '*.png' | wc -l)
[ "$drawn" -lt 40 ] || fail "the sweep had drawn all its pictures before the signal: the test did not interrupt it"
echo "   interrupted after $drawn of 40 pictures; its plot script ended with it"

echo "2. the same study again into the same folder"
sleep 1.1  # file times resolve to the second on some file systems
touch "$work/start"
start_sweep "$work/o"
finish 0
listing() { find "$work/o" -type f -printf '%P %s %T@\n' | sort; }
after=$(listing)
old=$(find "$work/o" -type f ! -newer "$work/start")
[ -z "$old" ] || fail "files of the interrupted run are mixed into the new one: $old"
[ "$(find "$work/o" -name '*.png' | wc -l)" -eq 40 ] || fail "the second run did not draw its 40 pictures"
sleep 2
[ "$(listing)" = "$after" ] || fail "files changed after the second run had exited"
no_partial "$work/o"

echo "3. SIGKILL while the plot script draws"
start_sweep "$work/k"
wait_for 120 has_png "$work/k" || fail "no picture within 120 s"
kids=$(children)
kill -KILL "$sweep_pid"
finish 137
# shellcheck disable=SC2086
wait_for 10 none_alive $kids || fail "the plot script outlived a killed sweep by 10 s"
no_partial "$work/k"

echo "4. SIGINT while the study's workers compute"
if [ "$(nproc)" -lt 2 ]; then
  echo "   one core: the study runs in one process, no workers to check"
else
  start_sweep "$work/w"
  # A worker is a fork of rc2000sim (the plot script, started later, is python3).
  workers() { kids=$(pgrep -P "$sweep_pid" -x rc2000sim || true); [ -n "$kids" ]; }
  wait_for 60 workers || fail "saw no worker process of the study within 60 s"
  kill -INT "$sweep_pid"
  finish 130
  # shellcheck disable=SC2086
  ! alive $kids || fail "a worker of the interrupted study is still running"
  [ ! -e "$work/w/sweep.csv" ] || fail "an interrupted study wrote sweep.csv"
  echo "   $(echo $kids | wc -w) worker(s) ended with the study"
fi
echo "PASS: interrupted sweeps end their children and leave no picture behind; the next run's files are its own"
