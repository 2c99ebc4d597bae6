#!/usr/bin/env bash
# Runs the sharded benchmark through a real Slurm: starts a one-node cluster on this machine
# (munged, slurmctld and slurmd on localhost, from Debian's munge and slurm-wlm, with a generated
# slurm.conf in a fresh directory), submits bench/planning/slurm_array.sh as a job array through
# sbatch, waits for the shards and the merge job, checks that the merged database holds every run of
# every shard, and stops the daemons it started.
#
#   bench/planning/slurm_local_cluster.sh --adsd PROGRAM --problems DIR [--runs N] [--shards K] [--keep]
#
# --problems is the directory of the shipped problems (BUILD/problem_files); the benchmark is
# thin_wall.cfg with adsd's checker, both motion validators, 1 s per run. Everything (configuration,
# daemons' logs, job outputs, shards, database) goes into a new directory under ${TMPDIR:-/tmp},
# removed at the end unless --keep or a failure. Needs root (slurmd starts jobs as their user).
#
# Exit status: 0 when every run of every shard is in the merged database; 1 otherwise, including
# when Slurm cannot start (a failure, not a skip: the point is to run on a real Slurm); 2 for bad
# arguments.
set -euo pipefail

here=$(cd "$(dirname "$0")" && pwd)
adsd="" problems="" runs=6 shards=3 keep=0
# Seconds to wait for the node to come up, and for the jobs (shards one after another on two CPUs).
readonly node_timeout=30 jobs_timeout=150

usage() { sed -n '8,8p' "$0" | sed 's/^# \{0,1\}//' >&2; exit 2; }
while [[ $# -gt 0 ]]; do
  case "$1" in
    --adsd) adsd=${2:?}; shift 2 ;;
    --problems) problems=${2:?}; shift 2 ;;
    --runs) runs=${2:?}; shift 2 ;;
    --shards) shards=${2:?}; shift 2 ;;
    --keep) keep=1; shift ;;
    *) usage ;;
  esac
done
[[ -n "$adsd" && -n "$problems" ]] || usage
[[ "$runs" =~ ^[1-9][0-9]*$ && "$shards" =~ ^[1-9][0-9]*$ ]] || usage
problem=$(realpath "$problems/thin_wall.cfg")
adsd=$(realpath "$adsd")

say() { echo "slurm_local_cluster: $*"; }
failed() {
  say "FAILED: $*" >&2
  exit 1
}
cannot_start() {
  failed "Slurm cannot start: $* (this test needs root and the Debian packages slurm-wlm and munge: cmake/install-debian-deps.sh)"
}

[[ -x "$adsd" ]] || failed "no adsd program at $adsd"
[[ -f "$problem" ]] || failed "no $problem (build the target adsd_problems)"
[[ $(id -u) -eq 0 ]] || cannot_start "not root"
for tool in munged mungekey munge unmunge slurmctld slurmd sbatch squeue scontrol sinfo; do
  command -v "$tool" >/dev/null || cannot_start "$tool is not on PATH"
done
command -v ompl_benchmark_statistics >/dev/null || command -v ompl_benchmark_statistics.py >/dev/null ||
  cannot_start "ompl_benchmark_statistics is not on PATH"

work=$(mktemp -d "${TMPDIR:-/tmp}/adsd-slurm.XXXXXX")
chmod 0755 "$work"  # munged refuses directories that others may write to
mkdir -p "$work/munge" "$work/state" "$work/spool" "$work/logs" "$work/jobs"
say "working in $work"

# ---- stop what we started, whatever happens -----------------------------------------------------
stop_daemon() {  # NAME PIDFILE: by the id the daemon wrote, never by name
  local pid
  [[ -s "$2" ]] || return 0
  pid=$(<"$2")
  kill "$pid" 2>/dev/null || return 0
  for _ in $(seq 50); do
    kill -0 "$pid" 2>/dev/null || return 0
    sleep 0.1
  done
  say "$1 (pid $pid) did not stop on SIGTERM, killing it"
  kill -9 "$pid" 2>/dev/null || true
}
finish() {
  local status=$?
  stop_daemon slurmd "$work/slurmd.pid"
  stop_daemon slurmctld "$work/slurmctld.pid"
  stop_daemon munged "$work/munge/munged.pid"
  if [[ $status -ne 0 ]]; then
    for f in "$work"/logs/*.log; do
      echo "---- last lines of $f" >&2
      tail -n 15 "$f" >&2 || true
    done
    say "kept $work for a look" >&2
  elif [[ $keep -eq 0 ]]; then
    rm -rf "$work"
  else
    say "kept $work"
  fi
  exit "$status"
}
trap finish EXIT

# ---- munge: a fresh key and a daemon on our own socket --------------------------------------------
socket=$work/munge/munge.socket
mungekey --create --keyfile "$work/munge/munge.key" || cannot_start "mungekey could not create a key"
chmod 0600 "$work/munge/munge.key"
munged --key-file "$work/munge/munge.key" --socket "$socket" --pid-file "$work/munge/munged.pid" \
  --log-file "$work/logs/munged.log" --seed-file "$work/munge/munged.seed" ||
  cannot_start "munged did not start"
for _ in $(seq 50); do [[ -S "$socket" ]] && break; sleep 0.1; done
munge --socket "$socket" -n | unmunge --socket "$socket" >/dev/null ||
  cannot_start "munged runs but does not decode its own credential"

# ---- slurm.conf: this machine as the only node, two free ports ------------------------------------
read -r ctld_port slurmd_port < <(/usr/bin/python3 -c '
import socket
ports = []
held = []
for _ in range(2):
    s = socket.socket(); s.bind(("127.0.0.1", 0)); held.append(s); ports.append(s.getsockname()[1])
print(*ports)')
node=$(hostname -s)
# What slurmd finds on this machine (CPUs, sockets, cores, memory), as the node's definition.
hardware=$(slurmd -C | sed -n 's/^NodeName=[^ ]* //p')
[[ -n "$hardware" ]] || cannot_start "slurmd -C did not describe this machine"
conf=$work/slurm.conf
cat >"$conf" <<EOF
# Generated by bench/planning/slurm_local_cluster.sh: a one-node cluster on localhost.
ClusterName=adsd-local
SlurmctldHost=$node(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
AuthInfo=socket=$socket
CredType=cred/munge
StateSaveLocation=$work/state
SlurmdSpoolDir=$work/spool
SlurmctldPidFile=$work/slurmctld.pid
SlurmdPidFile=$work/slurmd.pid
SlurmctldLogFile=$work/logs/slurmctld.log
SlurmdLogFile=$work/logs/slurmd.log
# No cgroups in a container: plain process tracking, no task binding, no accounting.
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
MpiDefault=none
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_Core_Memory
ReturnToService=2
# Finished jobs stay visible to scontrol for the checks below.
MinJobAge=600
NodeName=$node NodeAddr=127.0.0.1 $hardware State=UNKNOWN
PartitionName=local Nodes=$node Default=YES MaxTime=INFINITE State=UP
EOF
export SLURM_CONF=$conf

slurmctld -f "$conf" -c || cannot_start "slurmctld did not start"
slurmd -f "$conf" || cannot_start "slurmd did not start"
say "munged, slurmctld (port $ctld_port) and slurmd (port $slurmd_port) started; waiting for node $node"
state=""
for _ in $(seq $((node_timeout * 2))); do
  state=$(sinfo -h -n "$node" -o %T 2>/dev/null || true)
  [[ "$state" == idle ]] && break
  sleep 0.5
done
[[ "$state" == idle ]] || cannot_start "node $node is '${state:-unknown}' after ${node_timeout} s, not idle"
sinfo

# ---- the sharded benchmark as a job array ---------------------------------------------------------
# The array script asks for 4 GB and 2 hours a task (sized for real problems); these tiny runs need
# far less, and a small machine may not have 4 GB to give (SBATCH_* override #SBATCH lines).
out=$work/benchmark
cd "$work/jobs"  # the jobs' output files land in the submission directory
submitted=$(SBATCH_MEM_PER_NODE=1G SBATCH_TIMELIMIT=10 ADSD=$adsd ADSD_SOURCE_DIR=$here \
  "$here/slurm_array.sh" submit "$problem" "$runs" "$shards" "$out" --checker adsd --time 1) ||
  failed "slurm_array.sh submit failed"
echo "$submitted"
array=$(sed -n 's/.*shards: job \([0-9]*\) .*/\1/p' <<<"$submitted")
merge=$(sed -n 's/.*merge: job \([0-9]*\).*/\1/p' <<<"$submitted")
[[ -n "$array" && -n "$merge" ]] || failed "no job ids in slurm_array.sh's answer"

waited=0
while [[ -n "$(squeue -h -j "$array,$merge" -o %i 2>/dev/null)" ]]; do
  ((waited < jobs_timeout)) || failed "jobs $array and $merge still queued or running after ${jobs_timeout} s: $(squeue -h -j "$array,$merge")"
  sleep 1
  ((waited += 1))
done
say "jobs finished after ${waited} s"

# Every array task and the merge job must have completed (exit 0).
states=$(scontrol -o show job "$array" | sed -n 's/^JobId=\([0-9]*\) .*ArrayTaskId=\([0-9]*\) .*JobState=\([A-Z_]*\) .*ExitCode=\([0-9:]*\).*/task \2 (job \1): \3 exit \4/p')
echo "$states"
[[ $(grep -c . <<<"$states") -eq $shards ]] || failed "expected $shards array tasks, scontrol shows: $states"
! grep -v "COMPLETED exit 0:0" <<<"$states" || failed "an array task did not complete"
merge_state=$(scontrol -o show job "$merge" | sed -n 's/.*JobState=\([A-Z_]*\) .*ExitCode=\([0-9:]*\).*/\1 exit \2/p')
say "merge job $merge: $merge_state"
[[ "$merge_state" == "COMPLETED exit 0:0" ]] || { cat "$work"/jobs/*.out >&2; failed "the merge job did not complete"; }

# ---- the merged database holds every run of every shard ------------------------------------------
/usr/bin/python3 - "$out" "$runs" "$shards" <<'EOF' || failed "the merged database does not match the shards"
import glob, os, re, sqlite3, sys

out, runs, shards = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
logs = sorted(glob.glob(os.path.join(out, "shards", "*.runs-*.log")))
dbs = glob.glob(os.path.join(out, "*.db"))
ok = True
def check(cond, message):
    global ok
    if not cond:
        print("  MISMATCH: " + message)
        ok = False
    return cond

check(len(logs) == shards, "%d shard logs, expected %d" % (len(logs), shards))
if not check(len(dbs) == 1, "databases in %s: %s" % (out, dbs)):
    sys.exit(1)
db = sqlite3.connect(dbs[0])
configs = [r[0] for r in db.execute("SELECT name FROM plannerConfigs ORDER BY name")]
expected_total = 0
for log in logs:
    first, end = map(int, re.search(r"\.runs-(\d+)-(\d+)\.log$", log).group(1, 2))
    text = open(log).read()
    seed = re.search(r"^(\d+) is the random seed$", text, re.M).group(1)
    # Each planner configuration's section of an OMPL log starts with "N runs" after its name.
    counts = [int(n) for n in re.findall(r"^(\d+) runs$", text, re.M)]
    check(counts and all(n == end - first for n in counts),
          "%s: run counts %s, expected %d per configuration" % (os.path.basename(log), counts, end - first))
    rows = db.execute("SELECT runs.run_index FROM runs JOIN experiments ON runs.experimentid = experiments.id "
                      "WHERE experiments.seed = ?", (seed,)).fetchall()
    indices = sorted(r[0] for r in rows)
    expected = sorted(list(range(first, end)) * len(counts))
    if check(indices == expected, "%s (seed %s): run indices %s in the database, expected %s"
             % (os.path.basename(log), seed, indices, expected)):
        print("  %s: seed %s, %d configurations x %d runs, all in the database"
              % (os.path.basename(log), seed, len(counts), end - first))
    expected_total += sum(counts)
total = db.execute("SELECT COUNT(*) FROM runs").fetchone()[0]
check(total == expected_total, "%d runs in the database, the shards' logs hold %d" % (total, expected_total))
covered = sorted(set(r[0] for r in db.execute("SELECT run_index FROM runs")))
check(covered == list(range(runs)), "run indices %s, expected 0..%d" % (covered, runs - 1))
print("  %s: %d runs over %d planner configurations (%s), run indices 0..%d"
      % (os.path.basename(dbs[0]), total, len(configs), ", ".join(configs), runs - 1))
sys.exit(0 if ok else 1)
EOF
plots=$(find "$out" -maxdepth 1 -name '*.png' | wc -l)
((plots > 0)) || failed "the merge job wrote no plot"
say "PASSED: $shards shards of $runs runs through sbatch on a one-node Slurm, merged database complete, $plots plots"
