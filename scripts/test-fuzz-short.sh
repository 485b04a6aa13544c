#!/usr/bin/env bash
# Each libFuzzer harness for a short bounded time (default 30 s, SOFTTUNE_FUZZ_SECONDS overrides; the test
# command keeps within its budget) after replaying fuzz/regressions/<name>: it starts from the seeds in
# fuzz/seeds/<name> and, where one exists, the grown corpus in the cache (scripts/fuzz-dirs.sh). Two
# harnesses at a time, one per core (each libFuzzer process is single-threaded). New inputs go to a scratch
# directory: neither the seeds nor the cache change. Called by scripts/test.sh.
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/fuzz-dirs.sh
source scripts/parallel.sh
seconds=${SOFTTUNE_FUZZ_SECONDS:-30}
parallel=${SOFTTUNE_JOBS:-2}
scripts/build-fuzz.sh
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT

# Every crash found before and fixed must stay fixed: replay them all before fuzzing anything.
for name in "${fuzz_names[@]}"; do
  if compgen -G "fuzz/regressions/$name/*" >/dev/null; then
    build-asan/${name}_fuzz -runs=0 fuzz/regressions/$name/* 2>"$scratch/$name.replay.log" ||
      { cat "$scratch/$name.replay.log"; exit 1; }
  fi
done

# One harness: fuzz it, then print its last status line (or the report when it found something).
fuzz_one() {
  local name=$1
  local inputs=("fuzz/seeds/$name")
  [[ -d $fuzz_cache/$name ]] && inputs+=("$fuzz_cache/$name")
  mkdir -p "$scratch/$name"
  if build-asan/${name}_fuzz -max_total_time="$seconds" -timeout=30 -rss_limit_mb=2048 -max_len=16384 \
    -artifact_prefix="$scratch/$name-" "$scratch/$name" "${inputs[@]}" 2>"$scratch/$name.log"; then
    echo "fuzz: $name: $(grep -E "^(Done|#[0-9]+ +DONE)" "$scratch/$name.log" | tail -n1)"
  else
    echo "fuzz: $name FAILED"
    tail -n 60 "$scratch/$name.log"
    return 1
  fi
}

echo "fuzz: ${#fuzz_names[@]} harnesses for ${seconds} s each, ${parallel} at a time"
run_parallel "$parallel" fuzz_one "${fuzz_names[@]}"
