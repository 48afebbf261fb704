#!/usr/bin/env bash
# Tests scripts/sweep-parallel on this machine:
#   sweep_parallel_test.sh RC2000SIM STUDY_FILE REPO_ROOT      (RC2000SIM: absolute path to the binary)
#   1. runs the study through scripts/sweep-parallel --shards 3 --jobs 2 and compares the outputs,
#      byte for byte, with the same study run on one machine (rc2000sim sweep --study STUDY --out DIR);
#   2. the same through --sshlogin : (GNU parallel's name for this machine), if parallel accepts it
#      here (otherwise that part is skipped with a message);
#   3. runs it with a simulator that fails for shard 1: sweep-parallel must exit non-zero, name
#      shard 1 with its stderr and the commands that re-run it, and not merge.
# Exit 0 pass, 1 fail, 77 skipped (a "SKIP: reason" line on stdout) when GNU parallel is missing.
set -euo pipefail
# shellcheck source=tests/scripts/sweep_test_lib.sh
source "$(dirname "${BASH_SOURCE[0]}")/sweep_test_lib.sh"
sweep_parallel="$repo/scripts/sweep-parallel"
[ -x "$sweep_parallel" ] || fail "not executable: $sweep_parallel"
command -v parallel >/dev/null || skip "GNU parallel not installed (Debian package parallel)"
parallel --will-cite --version 2>/dev/null | grep -q 'GNU parallel' ||
  skip "'parallel' is not GNU parallel (moreutils' parallel?): $(command -v parallel)"

tmp="$(mktemp -d "${TMPDIR:-/tmp}/sweep-parallel-test.XXXXXX")"
cleanup() {
  local rc=$?
  trap - EXIT
  stop_child
  remove_work_folder_and_exit "$rc"
}
trap_cleanup

step "the study on one machine ($(basename "$study"), work folder $tmp)"
single="$tmp/single"
run "$sim" sweep --study "$study" --out "$single" --quiet || fail "rc2000sim sweep --study $study --out $single exited with $?"

step "scripts/sweep-parallel --shards 3 --jobs 2"
out="$tmp/parallel-out"
run "$sweep_parallel" "$study" "$out" --shards 3 --jobs 2 --rc2000sim "$sim" || fail "sweep-parallel exited with $?"
for i in 0 1 2; do
  [ -f "$out/shards/shard-$i-of-3.json" ] || fail "missing $out/shards/shard-$i-of-3.json after a successful run"
done
[ -s "$out/logs/joblog" ] || fail "no joblog in $out/logs"
compare_trees "$out" "$single"

step "scripts/sweep-parallel --shards 3 --jobs 2 --sshlogin :"
if probe="$(parallel --will-cite --sshlogin : echo {} ::: ok 2>&1)" && [ "$probe" = ok ]; then
  out="$tmp/parallel-sshlogin-out"
  run "$sweep_parallel" "$study" "$out" --shards 3 --jobs 2 --sshlogin : --rc2000sim "$sim" ||
    fail "sweep-parallel --sshlogin : exited with $?"
  compare_trees "$out" "$single"
else
  echo "  skipping this part: 'parallel --sshlogin :' does not run here (${probe:-no output})"
fi

step "scripts/sweep-parallel with a simulator that fails for shard 1: must report it and not merge"
failing="$tmp/failing-rc2000sim"
write_failing_simulator "$failing" sweep_parallel_test.sh
out="$tmp/parallel-fail"
rc=0
run "$sweep_parallel" "$study" "$out" --shards 3 --jobs 2 --rc2000sim "$failing" > "$tmp/fail.log" 2>&1 || rc=$?
sed 's/^/    | /' "$tmp/fail.log"
[ "$rc" -ne 0 ] || fail "sweep-parallel exited 0 although shard 1 failed"
grep -q 'shard 1/3 failed' "$tmp/fail.log" || fail "the report does not name shard 1/3"
grep -q 'deliberate failure of shard 1' "$tmp/fail.log" || fail "the report does not show shard 1's stderr"
grep -q -- '--shard 1/3 ' "$tmp/fail.log" || fail "the report does not give the command re-running shard 1"
grep -q 'shard [02]/3 failed' "$tmp/fail.log" && fail "the report names a shard that succeeded"
for i in 0 2; do
  [ -f "$out/shards/shard-$i-of-3.json" ] || fail "shard $i's file is missing although only shard 1 failed"
done
extra="$(find "$out" -mindepth 1 -maxdepth 1 ! -name shards ! -name logs -print -quit)"
[ -z "$extra" ] || fail "sweep-parallel merged although shard 1 failed ($extra exists)"

step "PASS"
