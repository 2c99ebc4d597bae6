#!/usr/bin/env bash
# `adsd benchmark` as a Slurm array job: one shard per array task, then one job that merges the
# shards' logs into a database and plots it. bench/planning/slurm_local_cluster.sh runs it on a
# one-node Slurm started on this machine (the test slurm_local_cluster).
#
# On the login node, from a checkout with a built adsd:
#   bench/planning/slurm_array.sh submit PROBLEM.cfg RUNS SHARDS OUT_DIR [adsd benchmark options...]
# which runs
#   sbatch --array=0-(SHARDS-1) slurm_array.sh shard PROBLEM.cfg RUNS SHARDS OUT_DIR [options...]
#   sbatch --dependency=afterok:<array job> slurm_array.sh merge OUT_DIR
# Array task k runs the runs [k*RUNS/SHARDS, (k+1)*RUNS/SHARDS) (`--run-range A:B`, seeded A+1)
# and writes OUT_DIR/shards/STEM.runs-A-B.log; the merge job runs
#   ompl_benchmark_statistics OUT_DIR/shards/*.log -d OUT_DIR/STEM.db
#   /usr/bin/python3 bench/planning/plot_benchmark.py OUT_DIR/STEM.db --out OUT_DIR
# OUT_DIR must be on a file system every node sees, and OUT_DIR/shards must not exist yet (the
# merge takes every log in it). Environment: ADSD, the adsd program (default:
# build/planner/app/adsd in this repository); SBATCH_* variables and the #SBATCH lines below set
# the job's resources (a task needs 2 CPUs when the problem benchmarks PRM, which plans on two
# threads; --time must cover RUNS/SHARDS runs × planners × combinations × the time limit).
#
#SBATCH --job-name=adsd-benchmark
#SBATCH --cpus-per-task=2
#SBATCH --mem=4G
#SBATCH --time=02:00:00
#SBATCH --output=adsd-benchmark-%A_%a.out
set -euo pipefail

fail() { echo "slurm_array.sh: $*" >&2; exit 2; }

# Under sbatch the script runs from Slurm's spool directory; the checkout is where it was submitted.
here=${ADSD_SOURCE_DIR:-$(cd "$(dirname "$0")" && pwd)}
adsd=${ADSD:-$here/../../build/planner/app/adsd}

mode=${1:-}
shift || true
case "$mode" in
  submit)
    [[ $# -ge 4 ]] || fail "usage: slurm_array.sh submit PROBLEM.cfg RUNS SHARDS OUT_DIR [options...]"
    problem=$(realpath "$1") runs=$2 shards=$3 out=$(realpath -m "$4")
    shift 4
    [[ "$runs" =~ ^[1-9][0-9]*$ ]] || fail "RUNS: expected a whole number > 0, got '$runs'"
    [[ "$shards" =~ ^[1-9][0-9]*$ ]] || fail "SHARDS: expected a whole number > 0, got '$shards'"
    (( shards <= runs )) || fail "SHARDS ($shards) is more than RUNS ($runs)"
    for option in "$@"; do
      case "$option" in
        --seed|--runs|--run-range|--out|--log-only|--no-plots) fail "$option is set per shard by this script" ;;
      esac
    done
    [[ -f "$problem" ]] || fail "no problem file '$problem'"
    [[ -x "$adsd" ]] || fail "no adsd program at '$adsd' (set ADSD)"
    [[ ! -e "$out/shards" ]] || fail "$out/shards exists: the merge would take its old logs too"
    mkdir -p "$out/shards"
    ADSD=$(realpath "$adsd")
    export ADSD_SOURCE_DIR=$here ADSD
    array=$(sbatch --parsable --export=ALL --array=0-$((shards - 1)) "$0" shard "$problem" "$runs" "$shards" "$out" "$@")
    array=${array%%;*}
    # afterok on an array job waits for every one of its tasks to succeed.
    merge=$(sbatch --parsable --export=ALL --dependency=afterok:"$array" "$0" merge "$out")
    echo "slurm_array.sh: shards: job $array (array 0-$((shards - 1))), merge: job ${merge%%;*}"
    ;;
  shard)
    problem=$1 runs=$2 shards=$3 out=$4
    shift 4
    k=${SLURM_ARRAY_TASK_ID:?slurm_array.sh shard runs as an array task (SLURM_ARRAY_TASK_ID)}
    first=$((k * runs / shards)) end=$(((k + 1) * runs / shards))
    exec "$adsd" benchmark "$problem" --run-range "$first:$end" --out "$out/shards" --log-only "$@"
    ;;
  merge)
    out=$1
    shopt -s nullglob
    logs=("$out"/shards/*.runs-*.log)
    [[ ${#logs[@]} -gt 0 ]] || fail "no shard log in $out/shards"
    stem=$(basename "${logs[0]}")
    stem=${stem%.runs-*}
    # OMPL's log-to-database script, by Debian's name or by the one OMPL's own install gives it.
    statistics=$(command -v ompl_benchmark_statistics || command -v ompl_benchmark_statistics.py) ||
      fail "ompl_benchmark_statistics is not on PATH (Debian package ompl-demos)"
    "$statistics" "${logs[@]}" -d "$out/$stem.db"
    /usr/bin/python3 "$here/plot_benchmark.py" "$out/$stem.db" --out "$out"
    ;;
  *)
    fail "usage: slurm_array.sh submit PROBLEM.cfg RUNS SHARDS OUT_DIR [adsd benchmark options...]"
    ;;
esac
