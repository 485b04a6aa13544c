#!/usr/bin/env bash
# Each libFuzzer harness for a short bounded time (default 40 s, SOFTTUNE_FUZZ_SECONDS overrides) from
# the committed corpus in fuzz/corpus/<name>, after replaying fuzz/regressions/<name>. New inputs go to
# a scratch directory, so the committed corpus stays as it is. Called by scripts/test.sh.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${SOFTTUNE_FUZZ_SECONDS:-40}
scripts/build-fuzz.sh
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
for name in tune_request request_decode simulate_request accuracy_request preset_load; do
  corpus=fuzz/corpus/$name
  mkdir -p "$scratch/$name"
  if compgen -G "fuzz/regressions/$name/*" >/dev/null; then
    build-fuzz/${name}_fuzz -runs=0 fuzz/regressions/$name/* 2>"$scratch/$name.replay.log" ||
      { cat "$scratch/$name.replay.log"; exit 1; }
  fi
  echo "fuzz: $name for ${seconds} s"
  build-fuzz/${name}_fuzz -max_total_time="$seconds" -timeout=30 -rss_limit_mb=2048 -max_len=16384 \
    -artifact_prefix="$scratch/$name-" "$scratch/$name" "$corpus" 2>"$scratch/$name.log" ||
    { tail -n 60 "$scratch/$name.log"; exit 1; }
  grep -E "^(Done|#[0-9]+ +DONE)" "$scratch/$name.log" | tail -n1
done
