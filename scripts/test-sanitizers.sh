#!/usr/bin/env bash
# The whole test suite under AddressSanitizer + UndefinedBehaviorSanitizer (build-asan/, scripts/build-asan.sh,
# which also builds the fuzz harnesses), then the server and render-pool tests under ThreadSanitizer
# (build-tsan/, only those targets and what they link). Both with clang++-14 -O2 -gline-tables-only
# (CMakePresets.json "asan" and "tsan").
# `asan` or `tsan` as the argument runs only that half (scripts/test.sh times them as separate stages).
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
jobs=${SOFTTUNE_JOBS:-2}
part=${1:-all}

if [[ $part == all || $part == asan ]]; then
  scripts/build-asan.sh
  # Leaks stay detected; scripts/lsan.supp lists the Mesa-internal ones suppressed and why.
  export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1
  export LSAN_OPTIONS=suppressions=$root/scripts/lsan.supp:print_suppressions=0
  export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
  # The longest tests first (cmake/TestLabels.cmake's COST), two at a time.
  ctest --preset asan -j"$jobs"
fi
[[ $part == all || $part == tsan ]] || exit 0

# What has threads: the HTTP service (unit and over real HTTP), the render pool, and the bad-input matrix
# against an in-process server. The fuzz replay in security_tests is single-threaded decoding: TSan has
# nothing to see there (it runs in the plain and the ASan suite), so it is filtered out here.
tsan_targets=(http_unit_tests http_integration_tests frame_pipeline_test security_tests)
declare -A tsan_filter=([security_tests]='-FuzzRegressions.*')
cmake --preset tsan >/dev/null
cmake --build --preset tsan -j"$jobs" --target "${tsan_targets[@]}"
export TSAN_OPTIONS=halt_on_error=1:second_deadlock_stack=1
# Two programs at a time (jobs): each is mostly one busy thread, and on 2 cores one at a time left one idle.
source scripts/parallel.sh
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
run_one() {
  local t=$1
  if (cd build-tsan && "./$t" --gtest_brief=1 --gtest_filter="${tsan_filter[$t]:-*}") >"$scratch/$t.log" 2>&1; then
    echo "tsan: $t passed"
  else
    echo "tsan: $t FAILED"
    cat "$scratch/$t.log"
    return 1
  fi
}
run_parallel "$jobs" run_one "${tsan_targets[@]}"
