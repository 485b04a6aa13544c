#!/usr/bin/env bash
# The long fuzz: each harness (arguments name some; default all) for SOFTTUNE_FUZZ_RUNS executions (default
# one million) or SOFTTUNE_FUZZ_MAX_SECONDS (default 3600), whichever comes first, from fuzz/seeds/<harness>
# and the grown corpus in the cache (scripts/fuzz-dirs.sh), which it grows and then merges down to the inputs
# that add coverage (libFuzzer -merge=1). The grown corpus never enters git; fuzz/seeds/ does, picked by hand
# from it when a run finds new ground. Crashes land in fuzz/artifacts/ (ignored by git); once fixed, copy
# each into fuzz/regressions/<harness>/ under a name that says what it broke. Prints executions and exec/s.
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/fuzz-dirs.sh
runs=${SOFTTUNE_FUZZ_RUNS:-1000000}
max_seconds=${SOFTTUNE_FUZZ_MAX_SECONDS:-3600}
scripts/build-fuzz.sh
mkdir -p fuzz/artifacts
names=("$@")
((${#names[@]})) || names=("${fuzz_names[@]}")
for name in "${names[@]}"; do
  cache=$fuzz_cache/$name
  mkdir -p "$cache"
  echo "fuzz-long: $name (corpus: $cache, $(ls "$cache" | wc -l) inputs)"
  build-asan/${name}_fuzz -runs="$runs" -max_total_time="$max_seconds" -timeout=30 -rss_limit_mb=2048 \
    -max_len=16384 -print_final_stats=1 -artifact_prefix="fuzz/artifacts/$name-" "$cache" "fuzz/seeds/$name" \
    2>"fuzz/artifacts/$name.log" || echo "fuzz-long: $name FOUND A CRASH (fuzz/artifacts/$name.log)"
  grep -E "stat::number_of_executed_units|stat::average_exec_per_sec|stat::peak_rss_mb" "fuzz/artifacts/$name.log"
  merged=$(mktemp -d)
  build-asan/${name}_fuzz -merge=1 -max_len=16384 -rss_limit_mb=2048 "$merged" "$cache" 2>"fuzz/artifacts/$name.merge.log"
  rm -rf "$cache" && mv "$merged" "$cache"
  echo "fuzz-long: $name merged to $(ls "$cache" | wc -l) inputs"
done
