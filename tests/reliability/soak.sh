#!/usr/bin/env bash
# Soak (issue 7 item 5, outside CI): one process plans a shipped problem over and over for N
# minutes while this script samples its resident memory (VmRSS from /proc) once a minute, then
# reports the growth from minute 5 to minute N (the first minutes fill allocator pools, OMPL's
# caches and the per-thread scratch: that is warm-up, not a leak).
#
#   tests/reliability/soak.sh [--minutes N] [--build-dir DIR] [--problem NAME.cfg] [--seconds-per-run S]
#
# Defaults: 30 minutes, build dir build-soak (Release), office.cfg, 1 s per planning run. The
# workload is `adsd benchmark PROBLEM` when the program has that command, else adsd_soak
# (soak_main.cpp: the same loop of fresh planners on a loaded problem). Samples go to
# DIR/soak/rss.csv. Exit status 0 when the growth is below 1 %.
set -euo pipefail
cd "$(dirname "$0")/../.."

minutes=30
build_dir=build-soak
problem=office.cfg
seconds_per_run=1
while [[ $# -gt 0 ]]; do
  case "$1" in
    --minutes) minutes=$2; shift 2 ;;
    --build-dir) build_dir=$2; shift 2 ;;
    --problem) problem=$2; shift 2 ;;
    --seconds-per-run) seconds_per_run=$2; shift 2 ;;
    -h|--help) sed -n '2,13p' "$0"; exit 0 ;;
    *) echo "soak.sh: unknown argument $1" >&2; exit 2 ;;
  esac
done
if (( minutes < 6 )); then echo "soak.sh: --minutes must be at least 6 (growth is measured from minute 5)" >&2; exit 2; fi

cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=Release -DADSD_BUILD_BENCH=OFF >/dev/null
cmake --build "$build_dir" -j"$(nproc)" --target adsd adsd_soak adsd_problems >/dev/null
cfg="$build_dir/problem_files/$problem"
[[ -f "$cfg" ]] || { echo "soak.sh: no $cfg" >&2; exit 2; }

out="$build_dir/soak"
mkdir -p "$out"
adsd="$build_dir/planner/app/adsd"
if "$adsd" --help | grep -q '^  benchmark '; then
  workload=("$adsd" benchmark "$cfg")
  echo "workload: adsd benchmark $cfg (runs until stopped after $minutes min)"
else
  workload=("$build_dir/tests/reliability/adsd_soak" "$cfg" "$((minutes + 1))" "$seconds_per_run")
  echo "workload: adsd_soak $cfg (adsd has no benchmark command yet), $seconds_per_run s per run"
fi

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
