#!/usr/bin/env bash
# Runs scripts/slurm-array.sh on a real one-node Slurm cluster started here, and checks that the
# sharded, killed-and-requeued run gives the same rows as an unsharded run.
#
#   scripts/slurm-test.sh                        # also runs the unsharded CI suite itself
#   MOWMILL_SLURM_REFERENCE=DIR scripts/slurm-test.sh   # compares with that CI suite run instead
#
# Steps: install slurm-wlm and munge if missing; write a slurm.conf for this host into a temporary
# directory; start munged, slurmctld and slurmd from it (stopped again on any exit); submit the
# CI suite (experiments/ci.toml) as a 4-task array with `sbatch --wait scripts/slurm-array.sh`;
# once one task has written some rows, freeze it and requeue it, so that Slurm kills it and runs
# it again with SLURM_RESTART_COUNT=1 (the script must resume: keep the rows already written,
# write none twice); then `mowmill merge` the 4 shards and compare with the unsharded run
# (scripts/compare-runs.py: every row apart from seconds and run_id, and stats.csv).
#
# Knobs: MOWMILL_SLURM_REFERENCE (see above); MOWMILL_SLURM_KILL_TASK, the task to requeue
# (0-3, default 1; `none` runs the array without killing anything); MOWMILL_SLURM_TIMEOUT,
# the seconds the array may take (default 900); MOWMILL_SLURM_KEEP=1 keeps the temporary
# directory and the shard directories on success too (they are always kept on failure).
# Needs target/release/mowmill (cargo build --release) and python3.
set -euo pipefail
cd "$(dirname "$0")/.."
export PATH="$PATH:/usr/sbin:/sbin"
started=$(date +%s)
# Messages carry the seconds since the start, so that a log shows where the time went.
say() { echo "slurm-test [$(( $(date +%s) - started ))s]: $*" >&2; }
bin=target/release/mowmill
[ -x "$bin" ] || { say "$bin missing: run cargo build --release first"; exit 2; }
ref=${MOWMILL_SLURM_REFERENCE:-}
[ -z "$ref" ] || [ -f "$ref/results.csv" ] || { say "MOWMILL_SLURM_REFERENCE=$ref has no results.csv"; exit 2; }
kill_task=${MOWMILL_SLURM_KILL_TASK:-1}
timeout=${MOWMILL_SLURM_TIMEOUT:-900}
ntasks=4
case $kill_task in
  none | [0-3]) ;;
  *) say "MOWMILL_SLURM_KILL_TASK=$kill_task: expected 0 to $((ntasks - 1)) or none"; exit 2 ;;
esac

# --- Install what is missing (same style as scripts/setup.sh: apt-get, sudo only if not root).
need=()
for c in munged slurmctld slurmd sbatch scontrol squeue; do
  command -v "$c" >/dev/null 2>&1 || need+=("$c")
done
if ((${#need[@]})); then
  sudo=""
  [ "$(id -u)" = 0 ] || sudo="sudo"
  say "missing ${need[*]}: installing slurm-wlm and munge"
  $sudo apt-get update -qq
  # policy-rc.d / no systemd in containers: the packages' own services may not start, and are
  # not used either way; this script starts its own daemons from its own configuration.
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends slurm-wlm munge
fi

# --- The cluster: one node (this host), all state, logs and sockets in a temporary directory.
# Under /tmp, not $TMPDIR: the munge socket's path must stay short (a Unix socket path has at
# most 107 bytes).
tmp=$(mktemp -d /tmp/mowmill-slurm.XXXXXX)
# munged wants every folder above its socket reachable by every user.
chmod 755 "$tmp"
job=""
sbatch_pid=""
ok=0
# Stops everything this script started, in reverse order, whatever the exit path.
cleanup() {
  local rc=$?
  set +e
  # A job whose sbatch --wait has not returned may still run: cancel it, and give its processes
  # (children of slurmstepd, not of this script) time to go.
  if [ -n "$job" ] && [ -n "$sbatch_pid" ]; then
    scancel "$job" 2>/dev/null
    for _ in $(seq 50); do
      [ -z "$(squeue -h -j "$job" -t PD,R,S,CG,CF -o %A 2>/dev/null)" ] && break
      sleep 0.2
    done
  fi
  [ -z "$sbatch_pid" ] || kill "$sbatch_pid" 2>/dev/null
  # The two Slurm daemons stop together (each takes 1-2 s), then munged, which they use.
  local group name pid pids
  for group in "slurmd slurmctld" munged; do
    pids=()
    for name in $group; do
      [ -f "$tmp/$name.pid" ] || continue
      pid=$(cat "$tmp/$name.pid")
      kill "$pid" 2>/dev/null && pids+=("$pid")
    done
    for pid in "${pids[@]}"; do
      for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.2; done
      kill -0 "$pid" 2>/dev/null && kill -KILL "$pid" 2>/dev/null
    done
  done
  if [ "$ok" = 1 ] && [ "${MOWMILL_SLURM_KEEP:-0}" != 1 ]; then
    rm -rf "$tmp"
    [ -z "$job" ] || rm -rf "results/ci-slurm$job"
  else
    say "kept $tmp (config, daemon logs, task logs)$([ -d "results/ci-slurm$job" ] && echo " and results/ci-slurm$job")"
    for f in "$tmp"/logs/*.log; do
      [ "$ok" = 1 ] || { echo "--- last lines of $f" >&2; tail -n 15 "$f" >&2; }
    done
  fi
  say "wall time $(( $(date +%s) - started )) s"
  exit "$rc"
}
trap cleanup EXIT
trap 'exit 130' INT
trap 'exit 143' TERM

host=$(hostname -s)
user=$(id -un)
# At most two CPUs, so that at most two tasks (each --cpus-per-task=1, hence --jobs 1) run at
# once on a machine shared with others.
cpus=$(nproc)
((cpus <= 2)) || cpus=2
mem=$(awk '/^MemTotal:/ {print int($2 / 1024)}' /proc/meminfo)
# Free TCP ports rather than Slurm's fixed 6817/6818, so that the test never meets another
# cluster (or a second copy of itself) on this machine.
read -r ctld_port slurmd_port < <(python3 -c '
import socket
s = [socket.socket() for _ in range(2)]
for x in s: x.bind(("127.0.0.1", 0))
print(*[x.getsockname()[1] for x in s])')
# Job ids start at a value derived from the clock so that results/ci-slurm<JOBID>/ (written by
# slurm-array.sh into the checkout) cannot be a leftover of an earlier test run.
first_job=$(( $(date +%s) % 50000000 + 1000000 ))
# The key is private to this user; the socket's folder must be reachable by every user.
mkdir -p "$tmp/munge" "$tmp/munge-key" "$tmp/state" "$tmp/spool" "$tmp/logs"
chmod 700 "$tmp/munge-key"
conf=$tmp/slurm.conf
cat >"$conf" <<EOF
# Written by scripts/slurm-test.sh: a one-node cluster on $host for one test run.
ClusterName=mowmilltest
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
SlurmUser=$user
SlurmdUser=$user
AuthType=auth/munge
CredType=cred/munge
# cred_expire is also how long a requeued job waits before it may start again (default 120 s).
AuthInfo=socket=$tmp/munge/munge.socket,cred_expire=10
StateSaveLocation=$tmp/state
SlurmdSpoolDir=$tmp/spool
SlurmctldPidFile=$tmp/slurmctld.pid
SlurmdPidFile=$tmp/slurmd.pid
SlurmctldLogFile=$tmp/logs/slurmctld.log
SlurmdLogFile=$tmp/logs/slurmd.log
# No cgroups: processes are tracked through their parents, and tasks are not bound to CPUs.
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
# The node's CPUs and memory as written here, whatever slurmd detects.
SlurmdParameters=config_overrides
MpiDefault=none
# A killed task may be requeued (the test does exactly that).
JobRequeue=1
ReturnToService=2
FirstJobId=$first_job
# No accounting database.
AccountingStorageType=accounting_storage/none
JobAcctGatherType=jobacct_gather/none
JobCompType=jobcomp/none
# A signalled task is killed after 5 s. sbatch --wait polls after 2, 8, 32, 32... s, growing
# only while the interval is below MinJobAge/2: a 16 s MinJobAge keeps it at 8 s (finished job
# records then go after 16-76 s, so the test reads the requeued task's record while it runs).
KillWait=5
MinJobAge=16
# The builtin scheduler looks at pending jobs on events and every sched_interval seconds (default
# 60): a requeued task becomes eligible without an event, so look often.
SchedulerType=sched/builtin
SchedulerParameters=sched_interval=2
NodeName=$host NodeAddr=127.0.0.1 CPUs=$cpus RealMemory=$mem State=UNKNOWN
PartitionName=test Nodes=$host Default=YES MaxTime=INFINITE State=UP
EOF
export SLURM_CONF=$conf
say "$(sbatch --version), $(munged --version 2>&1 | awk '{print $1; exit}')"

# Waits up to $1 seconds for the command $2... to succeed.
wait_for() {
  local secs=$1; shift
  local end=$(( $(date +%s) + secs ))
  until "$@"; do
    (( $(date +%s) < end )) || return 1
    sleep 0.2
  done
}

# munged with its own key and socket: the machine's /etc/munge is neither needed nor touched.
dd if=/dev/urandom of="$tmp/munge-key/munge.key" bs=1024 count=1 status=none
chmod 400 "$tmp/munge-key/munge.key"
munged --key-file="$tmp/munge-key/munge.key" --socket="$tmp/munge/munge.socket" \
  --pid-file="$tmp/munged.pid" --log-file="$tmp/logs/munged.log" \
  --seed-file="$tmp/munge-key/seed"
wait_for 10 test -S "$tmp/munge/munge.socket" || { say "munged did not start"; exit 1; }
slurmctld -f "$conf"
wait_for 30 scontrol ping >/dev/null 2>&1 || { say "slurmctld did not answer"; exit 1; }
slurmd -f "$conf"
node_idle() { sinfo -h -n "$host" -o %T 2>/dev/null | grep -qx idle; }
wait_for 60 node_idle || { say "node $host never became idle: $(sinfo -h -N -o '%N %T %E')"; exit 1; }
say "cluster up: node $host, $cpus CPUs, ${mem} MB, slurmctld :$ctld_port, slurmd :$slurmd_port ($tmp)"

# --- Submit the CI suite as a 4-task array through the worked example, unchanged.
# --cpus-per-task=1 overrides the script's 4 (a 2-CPU node could never run it) and becomes its
# --jobs; --output overrides its log name so that the checkout gets no log files; append mode
# keeps the killed run's log above the requeued run's.
MOWMILL_CONFIG=experiments/ci.toml sbatch --wait --parsable --array=0-$((ntasks - 1)) \
  --cpus-per-task=1 --output="$tmp/logs/task-%A_%a.log" --open-mode=append \
  scripts/slurm-array.sh >"$tmp/sbatch.out" 2>"$tmp/sbatch.err" &
sbatch_pid=$!
has_job() { [ -s "$tmp/sbatch.out" ] || ! kill -0 "$sbatch_pid" 2>/dev/null; }
wait_for 30 has_job || { say "sbatch printed no job id within 30 s"; exit 1; }
job=$(head -n 1 "$tmp/sbatch.out" | cut -d';' -f1)
[ -n "$job" ] || { say "sbatch failed: $(cat "$tmp/sbatch.err")"; exit 1; }
run_dir=results/ci-slurm$job
shard=$run_dir/shard-$kill_task-of-$ntasks
say "submitted array job $job ($ntasks tasks); task to requeue: $kill_task"

if [ "$kill_task" != none ]; then
  # --- Kill task $kill_task midway. Rows are flushed per instance and a shard takes seconds, so
  # the task is frozen (SIGSTOP) the moment its first rows appear: the requeue then certainly
  # lands midway, not after the task has finished.
  rows_in() { [ -f "$1" ] && echo $(( $(wc -l <"$1") - 1 )) || echo 0; }
  deadline=$(( $(date +%s) + 300 ))
  pid=""
  while :; do
    if (( $(rows_in "$shard/results.csv") > 0 )); then
      pid=$(pgrep -f "mowmill bench .*$shard( |\$)" | head -n 1 || true)
      [ -z "$pid" ] || { kill -STOP "$pid"; break; }
    fi
    kill -0 "$sbatch_pid" 2>/dev/null || { say "the array ended before task $kill_task could be frozen midway"; exit 1; }
    (( $(date +%s) < deadline )) || { say "task $kill_task wrote no rows within 300 s"; exit 1; }
    sleep 0.01
  done
  # The frozen task must not have finished: its manifest has no end time until the run is done.
  if ! python3 -c 'import json, sys; sys.exit(json.load(open(sys.argv[1])).get("end") is not None)' \
    "$shard/manifest.json"; then
    kill -CONT "$pid"
    say "task $kill_task had already finished its run when frozen; nothing midway to requeue"
    exit 1
  fi
  # A row cut in half by the SIGSTOP is not written yet (resume drops it), so it is left out.
  python3 -c 'import sys; t = open(sys.argv[1]).read(); open(sys.argv[2], "w").write(t[:t.rfind("\n") + 1])' \
    "$shard/results.csv" "$tmp/before-requeue.csv"
  before=$(rows_in "$tmp/before-requeue.csv")
  task_job=$(squeue -h -j "${job}_$kill_task" -o %A)
  say "task $kill_task (job $task_job, pid $pid) frozen after $before rows; requeueing it"
  scontrol requeue "${job}_$kill_task"
  # The requeue kills the frozen process (SIGCONT, SIGTERM, then SIGKILL after KillWait).
  wait_for 30 bash -c "! kill -0 $pid 2>/dev/null" || { say "pid $pid survived the requeue"; exit 1; }
  say "task $kill_task killed: $(squeue -h -j "${job}_$kill_task" -o '%T %r' 2>/dev/null || true)"
fi

# --- Wait for the whole array, requeued task included, noting the requeued task's restarts.
end=$(( $(date +%s) + timeout ))
restarts=0
while kill -0 "$sbatch_pid" 2>/dev/null; do
  if (( $(date +%s) >= end )); then say "the array did not finish within $timeout s"; exit 1; fi
  if [ "$kill_task" != none ]; then
    r=$(scontrol show job "${job}_$kill_task" 2>/dev/null | grep -oE 'Restarts=[0-9]+' | cut -d= -f2 || true)
    (( ${r:-0} <= restarts )) || restarts=$r
  fi
  sleep 1
done
set +e
wait "$sbatch_pid"
sbatch_rc=$?
set -e
sbatch_pid=""
say "array $job finished: sbatch --wait exited $sbatch_rc"
for k in $(seq 0 $((ntasks - 1))); do
  state=$(scontrol show job "${job}_$k" 2>/dev/null | grep -oE '(JobState|Restarts|ExitCode)=[^ ]*' | tr '\n' ' ' || true)
  echo "--- task $k: ${state:-(record already purged)}" >&2
  # Each attempt's summary line, the kill and any error (the full log stays in $tmp/logs).
  grep -E 'rows written|CANCELLED|error:|lock' "$tmp/logs/task-${job}_$k.log" >&2 || true
done
[ "$sbatch_rc" = 0 ] || { say "sbatch --wait exited $sbatch_rc: a task failed (logs above)"; exit 1; }
if [ "$kill_task" != none ]; then
  r=$(scontrol show job "${job}_$kill_task" 2>/dev/null | grep -oE 'Restarts=[0-9]+' | cut -d= -f2 || true)
  (( ${r:-0} <= restarts )) || restarts=$r
  ((restarts >= 1)) || { say "task $kill_task was never requeued (Restarts=$restarts)"; exit 1; }

  # --- Resume check: the requeued task kept the rows written before the kill (same timings, so not
  # recomputed) and wrote no row twice.
  python3 - "$tmp/before-requeue.csv" "$shard/results.csv" <<'EOF' || { say "task $kill_task did not resume correctly"; exit 1; }
import csv, sys
key = lambda r: (r["instance"], r["algorithm"], r["objective"])
# Timings compared as numbers: the final sort rewrites results.csv.
rows = lambda p: [{**r, "seconds": float(r["seconds"])} for r in csv.DictReader(open(p, newline=""))]
before, after = rows(sys.argv[1]), rows(sys.argv[2])
seen, bad = {}, []
for r in after:
    if key(r) in seen:
        bad.append(f"row {key(r)} written twice")
    seen[key(r)] = r
for r in before:
    a = seen.get(key(r))
    if a is None:
        bad.append(f"row {key(r)} written before the kill is gone")
    elif a != r:
        bad.append(f"row {key(r)} written before the kill was recomputed: {r['seconds']} s then {a['seconds']} s")
print("\n".join(bad) or f"resume: {len(before)} rows from before the kill kept, {len(after) - len(before)} added, none twice")
sys.exit(1 if bad else 0)
EOF
fi

# --- Merge the shards, and compare with an unsharded run.
"$bin" merge "$run_dir"/shard-*-of-$ntasks --out "$tmp/merged"
if [ -z "$ref" ]; then
  ref=$tmp/unsharded
  say "running the unsharded CI suite into $ref (log: $tmp/logs/unsharded.log)"
  "$bin" bench --config experiments/ci.toml --out "$ref" --jobs "$cpus" >"$tmp/logs/unsharded.log" 2>&1
fi
python3 scripts/compare-runs.py "$tmp/merged" "$ref"
ok=1
if [ "$kill_task" != none ]; then
  say "passed: task $kill_task killed after $before rows, requeued and resumed; the $ntasks shards merge to the unsharded run"
else
  say "passed (no task killed): the $ntasks shards merge to the unsharded run"
fi
