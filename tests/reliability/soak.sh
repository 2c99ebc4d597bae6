#!/usr/bin/env bash
# Soak (issue 7 item 5, outside CI): one process plans a shipped problem over and over for N
# minutes while this script samples its resident memory (VmRSS from /proc) once a minute, then
# reports the growth from minute 5 to minute N (the first minutes fill allocator pools, OMPL's
# caches and the per-thread scratch: that is warm-up, not a leak).
#
#   tests/reliability/soak.sh [--minutes N] [--build-dir DIR] [--problem NAME.cfg]
#                             [--seconds-per-run S] [--workload benchmark|loop]
#
# Defaults: 30 minutes, build dir build-soak (Release), office.cfg, 1 s per planning run.
# Workloads:
#   benchmark  `adsd benchmark PROBLEM --checker adsd --motion discrete --runs 10^6 --log-only`,
#              stopped after N minutes (the default). Note that OMPL's Benchmark keeps every run's
#              properties in memory until it writes the log, by design: a few KB per run.
#   loop       adsd_soak (soak_main.cpp): the same planners run after run on the loaded problem,
#              nothing kept between runs, so any growth is memory our code (or OMPL's planners)
#              fails to give back.
# Samples go to DIR/soak-WORKLOAD/rss.csv. Exit status 0 when the growth is below 1 %.
set -euo pipefail
cd "$(dirname "$0")/../.."

minutes=30
build_dir=build-soak
problem=office.cfg
seconds_per_run=1
workload_kind=benchmark
while [[ $# -gt 0 ]]; do
  case "$1" in
    --minutes) minutes=$2; shift 2 ;;
    --build-dir) build_dir=$2; shift 2 ;;
    --problem) problem=$2; shift 2 ;;
    --seconds-per-run) seconds_per_run=$2; shift 2 ;;
    --workload) workload_kind=$2; shift 2 ;;
    -h|--help) sed -n '2,21p' "$0"; exit 0 ;;
    *) echo "soak.sh: unknown argument $1" >&2; exit 2 ;;
  esac
done
if (( minutes < 6 )); then echo "soak.sh: --minutes must be at least 6 (growth is measured from minute 5)" >&2; exit 2; fi

cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=Release -DADSD_BUILD_BENCH=OFF >/dev/null
cmake --build "$build_dir" -j"$(nproc)" --target adsd adsd_soak adsd_problems >/dev/null
cfg="$build_dir/problem_files/$problem"
[[ -f "$cfg" ]] || { echo "soak.sh: no $cfg" >&2; exit 2; }

out="$build_dir/soak-$workload_kind"
rm -rf "$out"
mkdir -p "$out"
adsd="$build_dir/planner/app/adsd"
case "$workload_kind" in
  benchmark)
    if ! "$adsd" --help | grep -q '^  benchmark '; then echo "soak.sh: adsd has no benchmark command" >&2; exit 2; fi
    workload=("$adsd" benchmark "$cfg" --checker adsd --motion discrete --runs 1000000 --time "$seconds_per_run"
              --log-only --out "$out/benchmark")
    ;;
  loop)
    workload=("$build_dir/tests/reliability/adsd_soak" "$cfg" "$((minutes + 1))" "$seconds_per_run")
    ;;
  *) echo "soak.sh: --workload benchmark or loop, not $workload_kind" >&2; exit 2 ;;
esac
echo "workload: ${workload[*]} (stopped after $minutes min)"

"${workload[@]}" >"$out/workload.log" 2>&1 &
pid=$!
trap 'kill "$pid" 2>/dev/null || true' EXIT

rss_kib() { awk '/^VmRSS:/ {print $2}' "/proc/$pid/status" 2>/dev/null; }

echo "minute,rss_kib" >"$out/rss.csv"
for ((m = 1; m <= minutes; ++m)); do
  sleep 60
  rss=$(rss_kib)
  if [[ -z "$rss" ]]; then
    echo "soak.sh: the workload ended before minute $m:" >&2
    tail -5 "$out/workload.log" >&2
    exit 1
  fi
  echo "$m,$rss" >>"$out/rss.csv"
  echo "minute $m: resident $rss KiB"
done
kill "$pid" 2>/dev/null || true
wait "$pid" 2>/dev/null || true
trap - EXIT

at5=$(awk -F, '$1 == 5 {print $2}' "$out/rss.csv")
atN=$(awk -F, -v n="$minutes" '$1 == n {print $2}' "$out/rss.csv")
peak=$(awk -F, 'NR > 1 && $2 > p {p = $2} END {print p}' "$out/rss.csv")
growth=$(awk -v a="$at5" -v b="$atN" 'BEGIN {printf "%.3f", 100 * (b - a) / a}')
echo "soak: ${workload[*]##*/}: resident $at5 KiB at minute 5, $atN KiB at minute $minutes (peak $peak KiB):" \
     "growth $growth % from minute 5 to minute $minutes"
tail -1 "$out/workload.log"
awk -v g="$growth" 'BEGIN {exit !(g < 1.0)}'
