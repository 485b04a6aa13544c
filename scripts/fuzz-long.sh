#!/usr/bin/env bash
# The long fuzz: each harness for SOFTTUNE_FUZZ_RUNS executions (default one million) or
# SOFTTUNE_FUZZ_MAX_SECONDS (default 3600), whichever comes first, from the committed corpus. Crashes land in fuzz/artifacts/; copy each into
# fuzz/regressions/<harness>/ once fixed. Prints executions and exec/s per harness.
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${SOFTTUNE_FUZZ_RUNS:-1000000}
max_seconds=${SOFTTUNE_FUZZ_MAX_SECONDS:-3600}
scripts/build-fuzz.sh
mkdir -p fuzz/artifacts
names=("$@")
((${#names[@]})) || names=(tune_request request_decode simulate_request accuracy_request preset_load)
for name in "${names[@]}"; do
  corpus=fuzz/corpus/$name
  work=$(mktemp -d)
  echo "fuzz-long: $name"
  build-asan/${name}_fuzz -runs="$runs" -max_total_time="$max_seconds" -timeout=30 -rss_limit_mb=2048 \
    -max_len=16384 -print_final_stats=1 -artifact_prefix="fuzz/artifacts/$name-" "$work" "$corpus" \
    2>"fuzz/artifacts/$name.log" || echo "fuzz-long: $name FOUND A CRASH (fuzz/artifacts/$name.log)"
  grep -E "stat::number_of_executed_units|stat::average_exec_per_sec|stat::peak_rss_mb" "fuzz/artifacts/$name.log"
  rm -rf "$work"
done
