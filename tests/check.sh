#!/usr/bin/env bash
# The whole test suite, from a fresh Debian 12 machine: installs what is missing, builds, and runs
# every test (the README's test command; .ci/run calls it and nothing else).
#
#   tests/check.sh [--quick]
#
#   --quick   only the optimized build's tests (skip the sanitizer builds and the fuzz runs)
#
# Stages (issue 7 item 1), each in its own build directory:
#   1. build-check        Release, every test
#   2. build-check-asan   AddressSanitizer + UndefinedBehaviorSanitizer, every test, halting on
#                         the first report
#   3. build-check-tsan   ThreadSanitizer, the thread tests only (tests/planner Threads.*,
#                         tests/reliability and tests/arm label "threads")
#   4. build-check-fuzz   clang/libFuzzer: a deterministic run of every fuzz target (tests/fuzz:
#                         fixed seed and execution count, about a minute per target)
set -euo pipefail
cd "$(dirname "$0")/.."

quick=0
[[ "${1:-}" == "--quick" ]] && quick=1
jobs=$(nproc)

cmake/install-debian-deps.sh
# The real arms of tests/arm (Debian's dart-doc, into ~/.cache/adsd/robots; nothing when cached).
problems/data/fetch_robots.sh

stage_started=$SECONDS
stage_done() { echo "=== $1 done in $((SECONDS - stage_started)) s (total $SECONDS s)"; stage_started=$SECONDS; }

build() {  # build DIR "TARGETS" [CMAKE ARGS...]   (TARGETS empty: everything)
  local dir="$1" targets="$2"; shift 2
  echo "=== build $dir $*"
  cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=Release "$@" >/dev/null
  if [[ -n "$targets" ]]; then
    # shellcheck disable=SC2086
    cmake --build "$dir" -j"$jobs" --target $targets
  else
    cmake --build "$dir" -j"$jobs"
  fi
}

run_tests() {  # run_tests DIR [CTEST ARGS...]
  local dir="$1"; shift
  echo "=== test $dir $*"
  ctest --test-dir "$dir" --output-on-failure -j"$jobs" "$@"
}

# 1. The optimized build: every test.
build build-check ""
run_tests build-check
stage_done "optimized build and tests"

if [[ $quick -eq 0 ]]; then
  # 2. AddressSanitizer + UndefinedBehaviorSanitizer, halting on the first report (issue 7). The
  #    thread load test runs a tenth of its calls here (a call costs ~3x more); TSan runs it too.
  build build-check-asan "" -DADSD_SANITIZE="address;undefined" -DADSD_BUILD_BENCH=OFF -DCMAKE_BUILD_TYPE=RelWithDebInfo
  ADSD_THREAD_CALLS=10000 ADSD_ARM_TUNNEL_MOTIONS=40 run_tests build-check-asan
  stage_done "ASan+UBSan build and tests"

  # 3. ThreadSanitizer on the thread tests: one checker under four threads (fewer calls: TSan
  #    slows a call 5-20x), and PRM and CForest with two threads on the thin wall and the maze.
  #    OMPL itself is not instrumented; a report anywhere fails the run (halt_on_error).
  build build-check-tsan "test_planner test_reliability_threads test_arm_threads adsd_problems" -DADSD_SANITIZE=thread \
    -DADSD_BUILD_BENCH=OFF -DCMAKE_BUILD_TYPE=RelWithDebInfo
  TSAN_OPTIONS="halt_on_error=1 second_deadlock_stack=1" ADSD_THREAD_CALLS=3000 ADSD_PLANNER_SECONDS=10 \
    run_tests build-check-tsan -R '^(Threads|ThreadsUnderLoad|ArmThreads)\.'
  stage_done "TSan build and thread tests"

  # 4. A short fuzz run, deterministic: each target in one process with a fixed -seed and -runs
  #    count (about a minute each), from the committed seeds and regression inputs. The same
  #    commit runs the same inputs everywhere, so what fails here fails on a developer's machine
  #    first; random time-bounded fuzzing (--seconds) is for long runs outside CI.
  tests/fuzz/run_fuzzers.sh --build-dir build-check-fuzz --ci
  stage_done "fuzz build and short fuzz runs"
fi
echo "=== all tests passed in $SECONDS s"
