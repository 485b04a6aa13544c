#!/usr/bin/env bash
# Builds the five libFuzzer harnesses into build-asan/ (scripts/build-asan.sh: clang++-14, ASan+UBSan,
# every library the harnesses run instrumented for coverage with -fsanitize=fuzzer-no-link).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build-asan.sh tune_request_fuzz request_decode_fuzz simulate_request_fuzz accuracy_request_fuzz \
  preset_load_fuzz
