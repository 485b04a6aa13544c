#!/usr/bin/env bash
# The whole test suite under AddressSanitizer + UndefinedBehaviorSanitizer (build-asan/, scripts/build-asan.sh,
# which also builds the fuzz harnesses), then the server and render-pool tests under ThreadSanitizer
# (build-tsan/, only those targets and what they link). Both with clang++-14 -O2 -gline-tables-only.
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
  (cd build-asan && ctest --output-on-failure -j"$jobs" --timeout 900)
fi
[[ $part == all || $part == tsan ]] || exit 0

tsan_targets=(http_unit_tests http_integration_tests frame_pipeline_test security_tests)
CXX=clang++-14 CC=clang-14 cmake -S . -B build-tsan -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -gline-tables-only -DNDEBUG" \
  -DSOFTTUNE_TSAN=ON -DSOFTTUNE_BENCH=OFF >/dev/null
cmake --build build-tsan -j"$jobs" --target "${tsan_targets[@]}"
export TSAN_OPTIONS=halt_on_error=1:second_deadlock_stack=1
for t in "${tsan_targets[@]}"; do
  echo "tsan: $t"
  (cd build-tsan && "./$t" --gtest_brief=1)
done
