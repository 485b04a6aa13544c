#!/usr/bin/env bash
# Builds the five libFuzzer harnesses (scripts/fuzz-dirs.sh names them) into build-asan/
# (scripts/build-asan.sh: clang++-14, ASan+UBSan, every library the harnesses run instrumented for coverage
# with -fsanitize=fuzzer-no-link).
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/fuzz-dirs.sh
scripts/build-asan.sh "${fuzz_names[@]/%/_fuzz}"
