#!/usr/bin/env bash
# Soak (issue 7 item 5, outside CI): one process plans a shipped problem over and over for N
# minutes while this script reads its resident memory (VmRSS from /proc) every few seconds, then
# reports the growth from minute 5 to minute N (the first minutes fill allocator pools, OMPL's
# caches and the per-thread scratch: that is warm-up, not a leak).
#
#   tests/reliability/soak.sh [--minutes N] [--build-dir DIR] [--problem NAME.cfg]
#                             [--seconds-per-run S] [--workload benchmark|loop]
#                             [--sample-seconds T]
#
# Defaults: 30 minutes, build dir build-soak (Release), office.cfg, 1 s per planning run, a
# reading every 2 s.
# Workloads:
#   benchmark  `adsd benchmark PROBLEM --checker adsd --motion discrete --runs 10^6 --log-only`,
#              stopped after N minutes (the default). Each run's record goes to a spool file on
#              disk as the run ends, so nothing it keeps in memory grows with the run count.
#   loop       adsd_soak (soak_main.cpp): the same planners run after run on the loaded problem,
#              nothing kept between runs; it also writes DIR/soak-loop/heap.csv, one line per run:
#              glibc's heap bytes in use between runs (mallinfo2), the arenas' size and VmRSS.
# Per minute m, DIR/soak-WORKLOAD/rss.csv has
#   rss_kib   the reading at the end of minute m (the plain once-a-minute sample);
#   min_kib   the lowest reading during minute m: what the process holds between runs (retained);
#   max_kib   the highest: a run's transient peak (a planner's graph while it plans).
# The plain sample lands wherever the minute ends, inside a run or between runs, so it swings by
# a run's working memory (last session: 39 MB between runs, 56 MB inside some); the minimum does
# not. Growth is reported for both; the exit status (0 below 1 %) judges the retained memory
# (min_kib), because the question a soak answers is whether memory survives runs. The report
# says whether the plain samples meet 1 % too.
set -euo pipefail
cd "$(dirname "$0")/../.."

minutes=30
build_dir=build-soak
problem=office.cfg
seconds_per_run=1
workload_kind=benchmark
sample_seconds=2
while [[ $# -gt 0 ]]; do
  case "$1" in
    --minutes) minutes=$2; shift 2 ;;
    --build-dir) build_dir=$2; shift 2 ;;
    --problem) problem=$2; shift 2 ;;
    --seconds-per-run) seconds_per_run=$2; shift 2 ;;
    --workload) workload_kind=$2; shift 2 ;;
    --sample-seconds) sample_seconds=$2; shift 2 ;;
    -h|--help) sed -n '2,28p' "$0"; exit 0 ;;
    *) echo "soak.sh: unknown argument $1" >&2; exit 2 ;;
  esac
done
if (( minutes < 6 )); then echo "soak.sh: --minutes must be at least 6 (growth is measured from minute 5)" >&2; exit 2; fi
if ! [[ "$sample_seconds" =~ ^[1-9][0-9]*$ ]] || (( 60 % sample_seconds != 0 )); then
  echo "soak.sh: --sample-seconds must divide 60, got '$sample_seconds'" >&2; exit 2
fi

cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=Release -DADSD_BUILD_BENCH=OFF >/dev/null
cmake --build "$build_dir" -j2 --target adsd adsd_soak adsd_problems >/dev/null
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
    workload=("$build_dir/tests/reliability/adsd_soak" "$cfg" "$((minutes + 1))" "$seconds_per_run" "$out/heap.csv")
    ;;
  *) echo "soak.sh: --workload benchmark or loop, not $workload_kind" >&2; exit 2 ;;
esac
echo "workload: ${workload[*]} (stopped after $minutes min)"

"${workload[@]}" >"$out/workload.log" 2>&1 &
pid=$!
trap 'kill "$pid" 2>/dev/null || true' EXIT

rss_kib() { awk '/^VmRSS:/ {print $2}' "/proc/$pid/status" 2>/dev/null; }

# Readings at fixed times from the start (sleep to the next mark, so that the minutes do not
# drift by the time the readings take).
readings_per_minute=$((60 / sample_seconds))
start=$(date +%s.%N)
echo "minute,rss_kib,min_kib,max_kib" >"$out/rss.csv"
echo "second,rss_kib" >"$out/readings.csv"
for ((m = 1; m <= minutes; ++m)); do
  low='' high=''
  for ((k = 1; k <= readings_per_minute; ++k)); do
    mark=$(( (m - 1) * 60 + k * sample_seconds ))
    pause=$(awk -v s="$start" -v t="$mark" -v now="$(date +%s.%N)" 'BEGIN {d = s + t - now; print (d > 0 ? d : 0)}')
    sleep "$pause"
    rss=$(rss_kib)
    if [[ -z "$rss" ]]; then
      echo "soak.sh: the workload ended before minute $m:" >&2
      tail -5 "$out/workload.log" >&2
      exit 1
    fi
    echo "$mark,$rss" >>"$out/readings.csv"
    if [[ -z "$low" ]] || (( rss < low )); then low=$rss; fi
    if [[ -z "$high" ]] || (( rss > high )); then high=$rss; fi
  done
  echo "$m,$rss,$low,$high" >>"$out/rss.csv"
  echo "minute $m: resident $rss KiB (minute's lowest $low, highest $high)"
done
kill "$pid" 2>/dev/null || true
wait "$pid" 2>/dev/null || true
trap - EXIT

column() { awk -F, -v m="$1" -v c="$2" '$1 == m {print $c}' "$out/rss.csv"; }
growth() { awk -v a="$1" -v b="$2" 'BEGIN {printf "%+.3f", 100 * (b - a) / a}'; }
at5=$(column 5 2) atN=$(column "$minutes" 2)
low5=$(column 5 3) lowN=$(column "$minutes" 3)
peak=$(awk -F, 'NR > 1 && $4 > p {p = $4} END {print p}' "$out/rss.csv")
plain_growth=$(growth "$at5" "$atN")
retained_growth=$(growth "$low5" "$lowN")
echo "soak: ${workload[0]##*/} ${workload[1]##*/}, $minutes min:"
echo "  plain sample    $at5 KiB at minute 5, $atN KiB at minute $minutes: $plain_growth %"
echo "  retained (min)  $low5 KiB at minute 5, $lowN KiB at minute $minutes: $retained_growth %"
echo "  peak            $peak KiB"
if [[ -f "$out/heap.csv" ]]; then
  # The heap's bytes in use after the last run of minute 5 and of minute N (glibc mallinfo2).
  in_use() { awk -F, -v t="$1" 'NR > 1 && $2 < t {v = $3} END {print v}' "$out/heap.csv"; }
  heap5=$(in_use 300) heapN=$(in_use $((minutes * 60)))
  arenaN=$(awk -F, 'END {print $4}' "$out/heap.csv")
  echo "  heap in use     $heap5 bytes after minute 5, $heapN bytes after minute $minutes: $(growth "$heap5" "$heapN") %" \
       "(arenas $arenaN bytes at the end)"
fi
tail -1 "$out/workload.log"
awk -v g="$plain_growth" 'BEGIN {exit !(g < 1.0)}' || echo "soak.sh: note: the plain samples grew by $plain_growth %"
awk -v g="$retained_growth" 'BEGIN {exit !(g < 1.0)}'
