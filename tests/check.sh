#!/usr/bin/env bash
# The whole test suite, from a fresh Debian 12 machine: installs what is missing, builds, and runs
# every test (the README's test command; .ci/run calls it and nothing else).
#
#   tests/check.sh [--quick]
#
#   --quick   only the optimized build's tests (skip the sanitizer builds and the fuzz runs)
set -euo pipefail
cd "$(dirname "$0")/.."

quick=0
[[ "${1:-}" == "--quick" ]] && quick=1
jobs=$(nproc)

cmake/install-debian-deps.sh

run_build() {  # run_build DIR [CMAKE ARGS...] -- [CTEST ARGS...]
  local dir="$1"; shift
  local cmake_args=() ctest_args=()
  while [[ $# -gt 0 && "$1" != "--" ]]; do cmake_args+=("$1"); shift; done
  [[ $# -gt 0 ]] && shift
  ctest_args=("$@")
  echo "=== build $dir ${cmake_args[*]}"
  cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=Release "${cmake_args[@]}" >/dev/null
  cmake --build "$dir" -j"$jobs"
  echo "=== test $dir"
  ctest --test-dir "$dir" --output-on-failure -j"$jobs" "${ctest_args[@]}"
}

# 1. The optimized build: every test.
run_build build-check

if [[ $quick -eq 0 ]]; then
  # 2. AddressSanitizer + UndefinedBehaviorSanitizer, halting on the first report (issue 7).
  run_build build-check-asan -DADSD_SANITIZE="address;undefined" -DADSD_BUILD_BENCH=OFF -DCMAKE_BUILD_TYPE=RelWithDebInfo
fi
echo "=== all tests passed"
