#!/usr/bin/env bash
# Runs `adsd benchmark` as independent shards with GNU parallel (Debian `parallel`) on this machine,
# merges the shards' logs into one database with ompl_benchmark_statistics, and plots it.
#
#   bench/planning/shard_parallel.sh PROBLEM.cfg RUNS SHARDS OUT_DIR [adsd benchmark options...]
#
# Shard k of SHARDS runs the runs [k*RUNS/SHARDS, (k+1)*RUNS/SHARDS) (`--run-range A:B`, seeded
# A+1) and writes OUT_DIR/shards/STEM.runs-A-B.log (`--log-only`). Then
#   ompl_benchmark_statistics OUT_DIR/shards/<those logs> -d OUT_DIR/STEM.db
#   /usr/bin/python3 bench/planning/plot_benchmark.py OUT_DIR/STEM.db --out OUT_DIR
# Options after OUT_DIR go to every shard (--checker, --motion, --time, --seed is not allowed: each
# shard's seed comes from its range).
#
# Environment: ADSD  the adsd program (default: build/planner/app/adsd in this repository)
#              JOBS  shards running at once (default: the number of cores). Shards that run at the
#                    same time share the cores: their times are those of a loaded machine; for
#                    timings to compare with a single run, keep JOBS × threads per planner within
#                    the cores (PRM plans on two threads).
set -euo pipefail

usage() {
  sed -n '2,8p' "$0" | sed 's/^# \{0,1\}//' >&2
  exit 2
}
[[ $# -ge 4 ]] || usage
problem=$1 runs=$2 shards=$3 out=$4
shift 4
[[ "$runs" =~ ^[1-9][0-9]*$ ]] || { echo "shard_parallel.sh: RUNS: expected a whole number > 0, got '$runs'" >&2; exit 2; }
[[ "$shards" =~ ^[1-9][0-9]*$ ]] || { echo "shard_parallel.sh: SHARDS: expected a whole number > 0, got '$shards'" >&2; exit 2; }
(( shards <= runs )) || { echo "shard_parallel.sh: SHARDS ($shards) is more than RUNS ($runs)" >&2; exit 2; }
for option in "$@"; do
  case "$option" in
    --seed|--runs|--run-range|--out|--log-only|--no-plots)
      echo "shard_parallel.sh: $option is set per shard by this script" >&2; exit 2 ;;
  esac
done
[[ -f "$problem" ]] || { echo "shard_parallel.sh: no problem file '$problem'" >&2; exit 2; }

here=$(cd "$(dirname "$0")" && pwd)
adsd=${ADSD:-$here/../../build/planner/app/adsd}
jobs=${JOBS:-$(nproc)}
[[ -x "$adsd" ]] || { echo "shard_parallel.sh: no adsd program at '$adsd' (set ADSD)" >&2; exit 2; }
command -v parallel >/dev/null || { echo "shard_parallel.sh: GNU parallel is missing (Debian package parallel)" >&2; exit 1; }
# OMPL's log-to-database script, by Debian's name or by the one OMPL's own install gives it.
statistics=$(command -v ompl_benchmark_statistics || command -v ompl_benchmark_statistics.py) ||
  { echo "shard_parallel.sh: ompl_benchmark_statistics is missing (Debian package ompl-demos)" >&2; exit 1; }

ranges=()
for ((k = 0; k < shards; ++k)); do
  ranges+=("$((k * runs / shards)):$(((k + 1) * runs / shards))")
done
mkdir -p "$out/shards"
record="$out/shards/parallel.out"

echo "shard_parallel.sh: $shards shards of $runs runs, $jobs at once: ${ranges[*]}"
# --halt now,fail=1: one failed shard stops the others (its message is in its output).
parallel --halt now,fail=1 -j "$jobs" \
  "$adsd" benchmark "$problem" --run-range {} --out "$out/shards" --log-only "$@" ::: "${ranges[@]}" | tee "$record"

# The logs these shards wrote, as each reported it ("log         PATH (N runs in S s)").
mapfile -t logs < <(sed -n 's/^log  *\(.*\) ([0-9]* runs in .*$/\1/p' "$record")
if [[ ${#logs[@]} -ne $shards ]]; then
  echo "shard_parallel.sh: expected $shards logs, the shards reported ${#logs[@]}" >&2
  exit 1
fi
stem=$(basename "${logs[0]}")
stem=${stem%.runs-*}
database="$out/$stem.db"
"$statistics" "${logs[@]}" -d "$database"
/usr/bin/python3 "$here/plot_benchmark.py" "$database" --out "$out"
