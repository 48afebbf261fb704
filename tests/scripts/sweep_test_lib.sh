# Sourced by the sweep script tests (sweep_slurm_test.sh, sweep_parallel_test.sh): their arguments,
# step/fail/skip messages, a run() that a signal can interrupt, the output comparison, and a
# simulator that fails for one shard. Each test defines its own cleanup() and traps.
#   source sweep_test_lib.sh "$@"   ->  sim, study (absolute), repo, t0; exits 2 on bad arguments

if [ $# -ne 3 ]; then
  echo "usage: $0 RC2000SIM STUDY_FILE REPO_ROOT" >&2
  exit 2
fi
sim="$1"; study="$2"; repo="$3"

t0="$EPOCHREALTIME"
step() { echo "[$(awk -v a="${EPOCHREALTIME/,/.}" -v b="${t0/,/.}" 'BEGIN { printf "%6.1f s", a - b }')] $*"; }
fail() { echo "FAIL: $*"; exit 1; }
skip() { echo "SKIP: $*"; exit 77; }

[[ "$sim" = /* ]] || fail "RC2000SIM must be an absolute path, not '$sim'"
[ -f "$sim" ] && [ -x "$sim" ] || fail "RC2000SIM is not an executable file: $sim"
[ -f "$study" ] || fail "study file not found: $study"
study="$(realpath "$study")"
export SYSTEMC_DISABLE_COPYRIGHT_MESSAGE=1

child=""  # the command run() is waiting for
run() {  # COMMAND...: runs it in the background and waits, so that a signal reaches the trap at once
  "$@" &
  child=$!
  local rc=0
  wait "$child" || rc=$?
  child=""
  return "$rc"
}
stop_child() {  # for cleanup(): the command run() was waiting for, if any
  if [ -n "$child" ]; then kill -TERM "$child" 2>/dev/null || true; wait "$child" 2>/dev/null || true; fi
}

remove_work_folder_and_exit() {  # RC: the end of every cleanup()
  rm -rf "$tmp"
  step "done (exit $1)"
  exit "$1"
}
trap_cleanup() {  # cleanup() on exit, and an interrupt or TERM is an exit
  trap cleanup EXIT
  trap 'exit 130' INT
  trap 'exit 143' TERM
}

compare_trees() {  # SHARDED SINGLE: SHARDED (less its shards/ and logs/) and SINGLE are identical
  local nested files
  nested="$(find "$2" \( -name shards -o -name logs \) -print -quit)"
  [ -z "$nested" ] || fail "the single-machine output has an entry named like the scripts' own folders: $nested"
  nested="$(find "$1" -mindepth 2 \( -name shards -o -name logs \) -print -quit)"
  [ -z "$nested" ] || fail "the sharded output has a nested entry named shards or logs: $nested"
  files="$(find "$2" -type f | wc -l)"
  [ "$files" -gt 0 ] || fail "the single-machine run wrote no files into $2"
  if ! diff -r -q -x shards -x logs "$1" "$2"; then
    fail "the outputs differ (lines above: $1 against $2)"
  fi
  step "identical: $files files"
}

write_failing_simulator() {  # PATH TEST-NAME: a simulator that fails for shard 1 of 3, else runs $sim
  cat > "$1" <<SCRIPT
#!/bin/sh
# Fails for shard 1 of 3, otherwise runs the real simulator.
for a in "\$@"; do
  if [ "\$a" = 1/3 ]; then echo "deliberate failure of shard 1 ($2)" >&2; exit 7; fi
done
exec $(printf '%q' "$sim") "\$@"
SCRIPT
  chmod +x "$1"
}
