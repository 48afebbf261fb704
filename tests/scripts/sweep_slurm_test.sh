#!/usr/bin/env bash
# Tests scripts/sweep-slurm on a private single-node Slurm cluster brought up for the test:
#   sweep_slurm_test.sh RC2000SIM STUDY_FILE REPO_ROOT      (RC2000SIM: absolute path to the binary)
# It starts its own munged (own key, socket, pid, log and seed files) and slurmctld + slurmd (a
# slurm.conf in a temporary folder via SLURM_CONF, free ports on 127.0.0.1, state, spool, pids and
# logs in that folder; nothing in /etc is read or written), then:
#   1. runs the study through scripts/sweep-slurm --shards 3 --wait and compares the outputs, byte for
#      byte, with the same study run on one machine (rc2000sim sweep --study STUDY --out DIR);
#   2. removes shard 2's file: the merge must fail naming it; re-running only that shard must make
#      the merge succeed and match again;
#   3. submits with a simulator that fails for shard 1: sweep-slurm --wait must exit non-zero, name
#      shard 1 with its stderr, and not merge.
# Exit 0 pass, 1 fail, 77 skipped (a "SKIP: reason" line on stdout): not root, Slurm or munge
# missing, or no free ports. On exit it stops the daemons by their pids and removes the folder.
set -euo pipefail
# shellcheck source=tests/scripts/sweep_test_lib.sh
source "$(dirname "${BASH_SOURCE[0]}")/sweep_test_lib.sh"
sweep_slurm="$repo/scripts/sweep-slurm"
[ -x "$sweep_slurm" ] || fail "not executable: $sweep_slurm"

# --- skip conditions --------------------------------------------------------------------------
[ "$(id -u)" -eq 0 ] || skip "not root (the test starts its own munged, slurmctld and slurmd)"
export PATH="$PATH:/usr/sbin:/sbin"
for tool in munged slurmctld slurmd sbatch squeue sinfo scancel; do
  command -v "$tool" >/dev/null || skip "$tool not installed (Debian packages slurm-wlm, munge)"
done

port_free() {  # PORT: nothing listens on it
  if command -v ss >/dev/null; then
    [ -z "$(ss -Htln "sport = :$1" 2>/dev/null)" ]
  else
    if (exec 3<>"/dev/tcp/127.0.0.1/$1") 2>/dev/null; then return 1; fi
  fi
}
ports=()
for _ in $(seq 1 100); do
  p=$((20000 + RANDOM % 40000))
  if port_free "$p" && [[ " ${ports[*]} " != *" $p "* ]]; then ports+=("$p"); fi
  [ ${#ports[@]} -eq 2 ] && break
done
[ ${#ports[@]} -eq 2 ] || skip "no two free TCP ports found in 20000-59999 on 127.0.0.1"
ctld_port="${ports[0]}"; slurmd_port="${ports[1]}"

# --- the private cluster ----------------------------------------------------------------------
base="${TMPDIR:-/tmp}"
[ ${#base} -le 60 ] || base=/tmp  # Unix socket paths (munged's, slurmstepd's) are limited to 107 bytes
tmp="$(mktemp -d "$base/sweep-slurm-test.XXXXXX")"
chmod 711 "$tmp"  # munged requires that every user can traverse the folder of its socket
daemon_pids=()    # pids of the daemons started here ($!), with those in their pid files

stop_pid() {  # PID NAME: TERM, wait up to 10 s, then KILL; only if it is still that daemon
  local pid="$1" name="$2" i
  [ -n "$pid" ] && [ -d "/proc/$pid" ] || return 0
  [ "$(cat "/proc/$pid/comm" 2>/dev/null)" = "$name" ] || return 0
  kill -TERM "$pid" 2>/dev/null || return 0
  for i in $(seq 1 50); do
    [ -d "/proc/$pid" ] && [ "$(awk '{print $3}' "/proc/$pid/stat" 2>/dev/null)" != Z ] || break
    sleep 0.2
  done
  if [ -d "/proc/$pid" ] && [ "$(awk '{print $3}' "/proc/$pid/stat" 2>/dev/null)" != Z ]; then
    echo "  $name ($pid) did not stop on SIGTERM; killing it"
    kill -KILL "$pid" 2>/dev/null || true
  fi
  wait "$pid" 2>/dev/null || true
}

cleanup() {
  local rc=$? pid name i
  trap - EXIT
  stop_child
  if [ -n "${SLURM_CONF:-}" ] && [ -f "$tmp/slurmctld.pid" ]; then
    # Jobs still queued or running on the private cluster (a failed or interrupted test).
    if [ -n "$(squeue -h -o %i 2>/dev/null)" ]; then
      echo "  cancelling the jobs left on the private cluster"
      # shellcheck disable=SC2046  # one argument per job id
      scancel --full --quiet $(squeue -h -o %A 2>/dev/null) 2>/dev/null || true
      for i in $(seq 1 25); do [ -z "$(squeue -h -o %i 2>/dev/null)" ] && break; sleep 0.4; done
    fi
  fi
  # A job's slurmstepd outlives it briefly; its socket in the spool folder goes when it ends.
  for i in $(seq 1 50); do
    [ -z "$(find "$tmp/spool" -type s 2>/dev/null)" ] && break
    sleep 0.2
  done
  step "stopping slurmd, slurmctld and munged"
  for name in slurmd slurmctld munged; do
    pid=""
    [ -s "$tmp/$name.pid" ] && pid="$(tr -dc 0-9 < "$tmp/$name.pid")"
    stop_pid "$pid" "$name"
    for pid in "${daemon_pids[@]}"; do stop_pid "$pid" "$name"; done
  done
  # Any slurmstepd still there that this cluster's slurmd started (it inherited our SLURM_CONF).
  for pid in /proc/[0-9]*; do
    pid="${pid#/proc/}"
    [ "$(cat "/proc/$pid/comm" 2>/dev/null)" = slurmstepd ] || continue
    tr '\0' '\n' 2>/dev/null < "/proc/$pid/environ" | grep -qx "SLURM_CONF=$tmp/slurm.conf" || continue
    echo "  stopping slurmstepd $pid left by the private slurmd"
    stop_pid "$pid" slurmstepd
  done
  remove_work_folder_and_exit "$rc"
}
trap_cleanup

show_logs() {
  local f
  for f in munged.log slurmctld.log slurmd.log munged.out slurmctld.out slurmd.out; do
    [ -s "$tmp/$f" ] || continue
    echo "--- last lines of $f:"; tail -n 25 "$tmp/$f" | sed 's/^/    /'
  done
}

wait_for_file() {  # FILE SECONDS
  local i
  for i in $(seq 1 $(($2 * 5))); do [ -s "$1" ] && return 0; sleep 0.2; done
  return 1
}

step "private munged in $tmp"
dd if=/dev/urandom of="$tmp/munge.key" bs=1024 count=1 status=none
chmod 400 "$tmp/munge.key"
munged --foreground --socket="$tmp/munge.socket" --key-file="$tmp/munge.key" --pid-file="$tmp/munged.pid" \
  --log-file="$tmp/munged.log" --seed-file="$tmp/munged.seed" > "$tmp/munged.out" 2>&1 &
daemon_pids+=($!)
wait_for_file "$tmp/munged.pid" 10 && [ -S "$tmp/munge.socket" ] ||
  { show_logs; fail "munged did not start (no pid file or socket after 10 s)"; }

node="$(hostname -s)"
export SLURM_CONF="$tmp/slurm.conf"
mkdir -p "$tmp/state" "$tmp/spool"
cat > "$SLURM_CONF" <<EOF
# A single-node cluster for sweep_slurm_test.sh; everything on 127.0.0.1 and in $tmp.
ClusterName=sweeptest
SlurmctldHost=$node(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
CommunicationParameters=NoInAddrAny,NoCtldInAddrAny
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$tmp/munge.socket
StateSaveLocation=$tmp/state
SlurmdSpoolDir=$tmp/spool
SlurmctldPidFile=$tmp/slurmctld.pid
SlurmdPidFile=$tmp/slurmd.pid
SlurmctldLogFile=$tmp/slurmctld.log
SlurmdLogFile=$tmp/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
MpiDefault=none
ReturnToService=2
MailProg=/bin/true
NodeName=$node NodeAddr=127.0.0.1 NodeHostname=$node CPUs=$(nproc) State=UNKNOWN
PartitionName=debug Nodes=$node Default=YES MaxTime=INFINITE State=UP
EOF

step "slurmctld on 127.0.0.1:$ctld_port, slurmd on 127.0.0.1:$slurmd_port (node $node)"
slurmctld -D -f "$SLURM_CONF" > "$tmp/slurmctld.out" 2>&1 &
daemon_pids+=($!)
slurmd -D -f "$SLURM_CONF" -N "$node" > "$tmp/slurmd.out" 2>&1 &
daemon_pids+=($!)
wait_for_file "$tmp/slurmctld.pid" 15 && wait_for_file "$tmp/slurmd.pid" 15 ||
  { show_logs; fail "slurmctld or slurmd did not start (no pid file after 15 s)"; }

state=""
for _ in $(seq 1 60); do
  state="$(sinfo -h -N -n "$node" -o %T 2>/dev/null || true)"
  [ "$state" = idle ] && break
  sleep 0.5
done
[ "$state" = idle ] || { show_logs; fail "node $node not idle after 30 s (sinfo says '${state:-nothing}')"; }
step "node $node idle"

# --- the comparison ----------------------------------------------------------------------------
out="$tmp/slurm-out"
single="$tmp/single"
step "scripts/sweep-slurm $(basename "$study") --shards 3 --wait"
rc=0
run timeout 150 "$sweep_slurm" "$study" "$out" --shards 3 --rc2000sim "$sim" --wait || rc=$?
if [ "$rc" -ne 0 ]; then
  show_logs
  [ "$rc" -eq 124 ] && fail "sweep-slurm did not finish within 150 s"
  fail "sweep-slurm exited with $rc"
fi
for i in 0 1 2; do
  [ -f "$out/shards/shard-$i-of-3.json" ] || fail "missing $out/shards/shard-$i-of-3.json after a successful run"
done

step "the same study on one machine"
run "$sim" sweep --study "$study" --out "$single" --quiet ||
  fail "rc2000sim sweep --study $study --out $single exited with $?"
step "comparing the Slurm outputs with the single-machine ones"
compare_trees "$out" "$single"

# --- a missing shard ---------------------------------------------------------------------------
# Shard 2 rather than 1: a message counting the missing shards ("1 shard missing") cannot pass for it.
step "removing shard 2 of 3: the merge must fail and name it"
rm "$out/shards/shard-2-of-3.json"
rc=0
run "$sim" sweep merge "$out/shards" --out "$tmp/merge-missing" --quiet 2> "$tmp/merge-missing.err" || rc=$?
sed 's/^/    stderr: /' "$tmp/merge-missing.err"
[ "$rc" -ne 0 ] || fail "the merge with shard 2 of 3 missing exited 0"
grep -i shard "$tmp/merge-missing.err" | grep -Eq '(^|[^0-9.])2([^0-9]|$)' ||
  fail "the merge's stderr does not name the missing shard 2 (no line with 'shard' and the number 2)"
step "re-running only shard 2, then merging"
run "$sim" sweep --study "$study" --shard 2/3 --out "$out/shards" --quiet ||
  fail "re-running shard 2/3 exited with $?"
run "$sim" sweep merge "$out/shards" --out "$tmp/remerged" --quiet ||
  fail "the merge after re-running shard 2 exited with $?"
compare_trees "$tmp/remerged" "$single"

# --- a failing shard through Slurm -------------------------------------------------------------
step "scripts/sweep-slurm with a simulator that fails for shard 1: must report it and not merge"
failing="$tmp/failing-rc2000sim"
write_failing_simulator "$failing" sweep_slurm_test.sh
rc=0
run timeout 150 "$sweep_slurm" "$study" "$tmp/slurm-fail" --shards 3 --rc2000sim "$failing" --wait \
  > "$tmp/slurm-fail.log" 2>&1 || rc=$?
sed 's/^/    | /' "$tmp/slurm-fail.log"
[ "$rc" -ne 124 ] || fail "sweep-slurm did not finish within 150 s"
[ "$rc" -ne 0 ] || fail "sweep-slurm exited 0 although shard 1 failed"
grep -q 'shard 1/3 failed' "$tmp/slurm-fail.log" || fail "the report does not name shard 1/3"
grep -q 'deliberate failure of shard 1' "$tmp/slurm-fail.log" || fail "the report does not show shard 1's stderr"
grep -q -- '--shard 1/3 ' "$tmp/slurm-fail.log" || fail "the report does not give the command re-running shard 1"
grep -q 'shard [02]/3 failed' "$tmp/slurm-fail.log" && fail "the report names a shard that succeeded"
extra="$(find "$tmp/slurm-fail" -mindepth 1 -maxdepth 1 ! -name shards ! -name logs -print -quit)"
[ -z "$extra" ] || fail "sweep-slurm merged although shard 1 failed ($extra exists)"

step "PASS"
