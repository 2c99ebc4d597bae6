#!/usr/bin/env bash
# Builds the libFuzzer programs (clang 14, address + undefined sanitizers, adsd's own code
# coverage-instrumented) and runs each for a while from its seed corpus. tests/check.sh runs it
# for a minute per target; tests/fuzz/README.md gives the long-run command.
#
#   tests/fuzz/run_fuzzers.sh [--build-dir DIR] [--seconds N] [--parallel P] [TARGET...]
#
#   --build-dir DIR  the fuzz build (default build-fuzz); DIR/fuzz-runs/TARGET holds the corpus
#                    grown by the run, the log, and any crash-/timeout-/leak- artifact
#   --seconds N      fuzzing time per target (default 60)
#   --parallel P     targets fuzzed at once (default: the number of cores)
#   TARGET           mesh_loader, problem_file, pose_file, distance (default: all four)
#
# Exit status 0 when no target found anything new; otherwise 1, naming the artifacts, which become
# regression inputs in tests/fuzz/regressions/TARGET (README.md). Artifacts of findings already
# reported to another owner (tests/fuzz/regressions-pending) are counted, not failed.
set -euo pipefail
cd "$(dirname "$0")/../.."
source_dir=$PWD

build_dir=build-fuzz
seconds=60
parallel=$(nproc)
targets=()
while [[ $# -gt 0 ]]; do
  case "$1" in
    --build-dir) build_dir=$2; shift 2 ;;
    --seconds) seconds=$2; shift 2 ;;
    --parallel) parallel=$2; shift 2 ;;
    -h|--help) sed -n '2,16p' "$0"; exit 0 ;;
    -*) echo "run_fuzzers.sh: unknown option $1" >&2; exit 2 ;;
    *) targets+=("$1"); shift ;;
  esac
done
[[ ${#targets[@]} -eq 0 ]] && targets=(mesh_loader problem_file pose_file distance)

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

# fuzz TARGET: -max_total_time seconds in libFuzzer's fork mode, which goes on after a finding
# (-ignore_*: a known finding must not hide the next one); the grown corpus is kept in the build
# tree so the repository's seeds stay as committed.
fuzz() {
  local target=$1 run="$build_dir/fuzz-runs/$1"
  mkdir -p "$run/corpus"
  local inputs=("$run/corpus" "tests/fuzz/corpus/$target")
  [[ -d "tests/fuzz/regressions/$target" ]] && inputs+=("tests/fuzz/regressions/$target")
  # -timeout: an input running longer is a hang. -rss_limit_mb: bad input must not take the
  # machine's memory. -max_len: mesh and problem files of a few KB reach every grammar rule.
  "$build_dir/tests/fuzz/fuzz_$target" -fork=1 -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1 \
    -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=8192 -artifact_prefix="$run/" \
    "${inputs[@]}" >"$run/log" 2>&1 || true
  local execs
  execs=$(sed -n 's/^#\([0-9]*\): cov:.*/\1/p' "$run/log" | tail -1)
  echo "fuzz_$target: ${execs:-?} executions in ${seconds} s, corpus $(find "$run/corpus" -type f | wc -l) inputs"
}

# signature TARGET FILE: one line saying what FILE breaks (the property, sanitizer report or hang)
# followed by the stack frames of the report, so that a signature can name where it happens.
signature() {
  local report first
  report=$(timeout 120 "$build_dir/tests/fuzz/fuzz_$1" -timeout=10 -rss_limit_mb=2048 "$2" 2>&1 || true)
  first=$(grep -a -m1 -E 'property violated: |^SUMMARY: |ERROR: libFuzzer: (timeout|out-of-memory)' <<<"$report" ||
    echo "no report on replay")
  echo "$first" $(grep -a -E '^ +#[0-9]+ ' <<<"$report" | awk '{print $2, $3, $4}' | tr '\n' ' ')
}

rm -rf "$build_dir/fuzz-runs"
echo "=== fuzzing ${targets[*]} for ${seconds} s each, ${parallel} at a time"
running=0
for t in "${targets[@]}"; do
  fuzz "$t" &
  running=$((running + 1))
  if [[ $running -ge $parallel ]]; then wait -n; running=$((running - 1)); fi
done
wait

# Triage: an artifact whose replay matches a signature in regressions-pending/TARGET (a finding
# already reported to the code's owner) is known; anything else fails the run.
new_findings=0
for t in "${targets[@]}"; do
  run="$build_dir/fuzz-runs/$t"
  known=0
  while IFS= read -r artifact; do
    what=$(signature "$t" "$artifact")
    matched=""
    for sig in tests/fuzz/regressions-pending/"$t"/*.signature; do
      [[ -f "$sig" ]] && grep -aqEf "$sig" <<<"$what" && matched=$sig && break
    done
    if [[ -n "$matched" ]]; then
      known=$((known + 1))
    elif [[ "$what" == "no report on replay"* ]]; then
      # Fork mode writes the input a job was running when it is stopped at the end of the time as
      # a crash; an artifact that replays cleanly is listed, not failed.
      echo "fuzz_$t: $artifact does not reproduce (a job stopped at the time limit), ignored"
    else
      new_findings=$((new_findings + 1))
      echo "NEW FINDING fuzz_$t: $artifact"
      echo "    ${what:0:400}"
    fi
  done < <(find "$run" -maxdepth 1 -type f \( -name 'crash-*' -o -name 'timeout-*' -o -name 'leak-*' -o -name 'oom-*' \))
  [[ $known -gt 0 ]] && echo "fuzz_$t: $known artifact(s) of findings already reported (tests/fuzz/regressions-pending/$t)"
done
if [[ $new_findings -gt 0 ]]; then
  echo "=== fuzzing found $new_findings new problem(s) (logs in $build_dir/fuzz-runs/TARGET/log)"
  exit 1
fi
echo "=== fuzzing found nothing new"
