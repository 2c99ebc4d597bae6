#!/usr/bin/env bash
# Builds the libFuzzer programs (clang 14, address + undefined sanitizers, adsd's own code
# coverage-instrumented) and runs each from its seed corpus and regression inputs, in one of two
# modes (tests/fuzz/README.md):
#
#   tests/fuzz/run_fuzzers.sh --ci [--build-dir DIR] [--parallel P] [TARGET...]
#   tests/fuzz/run_fuzzers.sh --runs N [--seed S] [--build-dir DIR] [--parallel P] [TARGET...]
#   tests/fuzz/run_fuzzers.sh --seconds N [--build-dir DIR] [--parallel P] [TARGET...]
#
#   --ci             what tests/check.sh runs: --runs with each target's count from ci_runs
#                    below (about a minute per target on the 2-core team machine) and --seed 1
#   --runs N         deterministic: each target runs in one process (no fork) for exactly N
#                    executions with -seed=S, from an empty run corpus, the committed seeds and the
#                    regression inputs; the same commit gives the same inputs on every machine, so a
#                    finding in CI shows on a developer's machine too. The first finding ends that
#                    target's run.
#   --seed S         the libFuzzer seed of --runs/--ci (default 1)
#   --seconds N      random long runs: N seconds per target in libFuzzer's fork mode, which goes on
#                    after a finding; a different search every time
#   --build-dir DIR  the fuzz build (default build-fuzz); DIR/fuzz-runs/TARGET holds the corpus
#                    grown by the run, the log, and any crash-/timeout-/leak-/oom- artifact
#   --parallel P     targets fuzzed at once (default: the number of cores)
#   TARGET           mesh_loader, problem_file, pose_file, distance, motion_bench_maker (default: all five)
#
# Exit status 0 when no target found anything new; 1 when one did (each finding is printed with
# its artifact and the command that reproduces it), or when a fuzzer ended without finishing its
# runs and without an artifact (printed with its log's tail); 2 for a usage error. Artifacts of
# findings already reported to another owner (tests/fuzz/regressions-pending) are counted, not
# failed. New findings become regression inputs in tests/fuzz/regressions/TARGET (README.md).
set -euo pipefail
cd "$(dirname "$0")/../.."
source_dir=$PWD
trap 'echo "run_fuzzers.sh: FAILED at line $LINENO: $BASH_COMMAND (exit status $?)" >&2' ERR

# Executions per target for --ci: about 60 s each, calibrated with --runs on this machine (2 cores
# shared with other builds; README.md gives the measurement). The targets' speeds differ by two
# orders of magnitude (problem_file builds an OMPL problem per input, distance runs the oracle).
declare -A ci_runs=([mesh_loader]=10000 [problem_file]=10000 [pose_file]=500000 [distance]=3600
                    [motion_bench_maker]=160000)

build_dir=build-fuzz
mode=""
seconds=0
runs=0
seed=1
parallel=$(nproc)
targets=()
usage() { echo "run_fuzzers.sh: $1 (see --help)" >&2; exit 2; }
while [[ $# -gt 0 ]]; do
  case "$1" in
    --build-dir) build_dir=$2; shift 2 ;;
    --ci) [[ -z "$mode" ]] || usage "give one of --ci, --runs, --seconds"; mode=ci; shift ;;
    --runs) [[ -z "$mode" ]] || usage "give one of --ci, --runs, --seconds"; mode=runs; runs=$2; shift 2 ;;
    --seconds) [[ -z "$mode" ]] || usage "give one of --ci, --runs, --seconds"; mode=seconds; seconds=$2; shift 2 ;;
    --seed) seed=$2; shift 2 ;;
    --parallel) parallel=$2; shift 2 ;;
    -h|--help) sed -n '2,30p' "$0"; exit 0 ;;
    -*) usage "unknown option $1" ;;
    *) targets+=("$1"); shift ;;
  esac
done
[[ -n "$mode" ]] || usage "give one of --ci, --runs N, --seconds N"
[[ ${#targets[@]} -eq 0 ]] && targets=(mesh_loader problem_file pose_file distance motion_bench_maker)
for t in "${targets[@]}"; do
  [[ -n "${ci_runs[$t]:-}" ]] || usage "unknown target $t (mesh_loader, problem_file, pose_file, distance, motion_bench_maker)"
done
number='^[1-9][0-9]*$'
[[ "$mode" != runs || "$runs" =~ $number ]] || usage "--runs needs a positive whole number"
[[ "$mode" != seconds || "$seconds" =~ $number ]] || usage "--seconds needs a positive whole number"
[[ "$seed" =~ $number ]] || usage "--seed needs a positive whole number"
[[ "$parallel" =~ $number ]] || usage "--parallel needs a positive whole number"

# Every translation unit gets coverage and sanitizer instrumentation (fuzzer-no-link: without
# libFuzzer's main); only the fuzz_* programs link libFuzzer (ADSD_BUILD_FUZZERS in tests/fuzz).
flags="-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer"
# The oracle (tests/oracle, used by the distance target) includes GCC's quadmath.h, which lives in
# GCC's private include directory; clang is given that one header, not the directory (whose
# intrinsics headers are GCC's own).
mkdir -p "$build_dir/quadmath-include"
for h in quadmath.h quadmath_weak.h; do
  ln -sf "$(gcc -print-file-name=include/$h)" "$build_dir/quadmath-include/$h"
done
flags+=" -isystem $(cd "$build_dir/quadmath-include" && pwd)"
echo "=== fuzz build $build_dir"
CC=clang CXX=clang++ cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DADSD_BUILD_FUZZERS=ON \
  -DADSD_BUILD_BENCH=OFF -DCMAKE_CXX_FLAGS="$flags" >/dev/null
cmake --build "$build_dir" -j"$(nproc)" --target "${targets[@]/#/fuzz_}"

export LSAN_OPTIONS="suppressions=$source_dir/tests/fuzz/lsan.supp:print_suppressions=0"
export ASAN_OPTIONS="abort_on_error=0:detect_leaks=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"

# Options of both modes. -timeout: an input running longer is a hang. -rss_limit_mb: bad input
# must not take the machine's memory. -max_len: mesh and problem files of a few KB reach every
# grammar rule (and a fixed value keeps --runs independent of the corpus).
common=(-timeout=10 -rss_limit_mb=2048 -max_len=8192)

# Deterministic runs switch address-space randomization off (setarch -R): libFuzzer feeds the
# operands of recent comparisons back into its mutations, and pointer operands differ from run to
# run under ASLR, so with it the same seed gave a different corpus after a few thousand inputs.
fixed_addresses=()
if [[ "$mode" != seconds ]]; then
  if setarch "$(uname -m)" -R true 2>/dev/null; then
    fixed_addresses=(setarch "$(uname -m)" -R)
  else
    echo "run_fuzzers.sh: warning: setarch -R is not permitted here; with address randomization on, the" \
         "mutations after the seed inputs may differ from another machine's" >&2
  fi
fi

# fuzz TARGET: one target's run; its exit status is written to RUN/status.
fuzz() {
  local target=$1 run="$build_dir/fuzz-runs/$1"
  mkdir -p "$run/corpus"
  local inputs=("$run/corpus" "tests/fuzz/corpus/$target")
  [[ -d "tests/fuzz/regressions/$target" ]] && inputs+=("tests/fuzz/regressions/$target")
  local status=0
  if [[ "$mode" == seconds ]]; then
    # Fork mode goes on after a finding (-ignore_*: a known finding must not hide the next one).
    "$build_dir/tests/fuzz/fuzz_$target" -fork=1 -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1 \
      -max_total_time="$seconds" "${common[@]}" -artifact_prefix="$run/" "${inputs[@]}" >"$run/log" 2>&1 ||
      status=$?
  else
    local n=$runs
    [[ "$mode" == ci ]] && n=${ci_runs[$target]}
    # One process, a fixed seed and count: the same executions every time. The seeds and
    # regression inputs go in as one list in sorted order (-seed_inputs): libFuzzer orders its
    # starting corpus by size only, so equal sizes would keep the directory's order, which
    # differs between file systems. -reload=0: libFuzzer would otherwise re-read the corpus
    # directory on a timer, which depends on the machine's speed.
    find "${inputs[@]:1}" -type f ! -name '.*' | LC_ALL=C sort | paste -sd, >"$run/seed_inputs"
    "${fixed_addresses[@]}" "$build_dir/tests/fuzz/fuzz_$target" -seed="$seed" -runs="$n" -reload=0 -print_final_stats=1 \
      "${common[@]}" -artifact_prefix="$run/" -seed_inputs="@$run/seed_inputs" "$run/corpus" >"$run/log" 2>&1 ||
      status=$?
  fi
  echo "$status" >"$run/status"
  local execs
  execs=$(sed -n -e 's/^#\([0-9]*\): cov:.*/\1/p' -e 's/^#\([0-9]*\)[[:space:]]*\(DONE\|NEW\|REDUCE\|pulse\|INITED\).*/\1/p' \
    -e 's/^stat::number_of_executed_units: *\([0-9]*\)/\1/p' "$run/log" | tail -1)
  local what="${seconds} s"
  [[ "$mode" != seconds ]] && what="-seed=$seed -runs=${n}"
  echo "fuzz_$target ($what): ${execs:-?} executions, corpus $(find "$run/corpus" -type f | wc -l) new inputs, exit status $status"
}

# signature TARGET FILE: one line saying what FILE breaks (the property, sanitizer report or hang)
# followed by the stack frames of the report, so that a signature can name where it happens.
signature() {
  local report first
  report=$(timeout 120 "$build_dir/tests/fuzz/fuzz_$1" "${common[@]}" "$2" 2>&1 || true)
  first=$(grep -a -m1 -E 'property violated: |^SUMMARY: |ERROR: libFuzzer: (timeout|out-of-memory)' <<<"$report" ||
    echo "no report on replay")
  echo "$first" $(grep -a -E '^ +#[0-9]+ ' <<<"$report" | awk '{print $2, $3, $4}' | tr '\n' ' ')
}

for t in "${targets[@]}"; do rm -rf "$build_dir/fuzz-runs/$t"; done
case "$mode" in
  seconds) echo "=== fuzzing ${targets[*]} for ${seconds} s each (fork mode, random), ${parallel} at a time" ;;
  ci) echo "=== fuzzing ${targets[*]} deterministically (CI counts, -seed=$seed), ${parallel} at a time" ;;
  runs) echo "=== fuzzing ${targets[*]} deterministically (-runs=$runs -seed=$seed), ${parallel} at a time" ;;
esac
running=0
for t in "${targets[@]}"; do
  fuzz "$t" &
  running=$((running + 1))
  if [[ $running -ge $parallel ]]; then wait -n || true; running=$((running - 1)); fi
done
wait || true

# Triage: an artifact whose replay matches a signature in regressions-pending/TARGET (a finding
# already reported to the code's owner) is known; anything else fails the run.
new_findings=0
for t in "${targets[@]}"; do
  run="$build_dir/fuzz-runs/$t"
  known=0
  artifacts=0
  while IFS= read -r artifact; do
    artifacts=$((artifacts + 1))
    what=$(signature "$t" "$artifact")
    matched=""
    for sig in tests/fuzz/regressions-pending/"$t"/*.signature; do
      [[ -f "$sig" ]] && grep -aqEf "$sig" <<<"$what" && matched=$sig && break
    done
    if [[ -n "$matched" ]]; then
      known=$((known + 1))
    elif [[ "$what" == "no report on replay"* && "$mode" == seconds ]]; then
      # Fork mode writes the input a job was running when it is stopped at the end of the time as
      # a crash; an artifact that replays cleanly is listed, not failed.
      echo "fuzz_$t: $artifact does not reproduce (a job stopped at the time limit), ignored"
    else
      new_findings=$((new_findings + 1))
      echo "NEW FINDING fuzz_$t: $artifact"
      echo "    ${what:0:400}"
      echo "    reproduce: $build_dir/tests/fuzz/fuzz_$t ${common[*]} $artifact"
    fi
  done < <(find "$run" -maxdepth 1 -type f \( -name 'crash-*' -o -name 'timeout-*' -o -name 'leak-*' -o -name 'oom-*' \))
  [[ $known -gt 0 ]] && echo "fuzz_$t: $known artifact(s) of findings already reported (tests/fuzz/regressions-pending/$t)"
  # A deterministic run must end by finishing its runs (status 0) or with an artifact; a fuzzer
  # that died otherwise (killed, out of disk, a crash in libFuzzer itself) is a failure too.
  status=$(cat "$run/status" 2>/dev/null || echo "missing")
  if [[ "$mode" != seconds && "$status" != 0 && $artifacts -eq 0 ]]; then
    new_findings=$((new_findings + 1))
    echo "FAILED fuzz_$t: exit status $status without an artifact; the end of $run/log:"
    tail -20 "$run/log" | sed 's/^/    /'
  fi
done
if [[ $new_findings -gt 0 ]]; then
  echo "=== fuzzing FAILED: $new_findings new problem(s) (logs in $build_dir/fuzz-runs/TARGET/log)"
  exit 1
fi
echo "=== fuzzing found nothing new"
