#!/usr/bin/env bash
# Configures and builds the AddressSanitizer + UndefinedBehaviorSanitizer build into build-asan/
# (CMakePresets.json "asan": clang++-14): the whole test suite and the libFuzzer harnesses in one build
# (SOFTTUNE_FUZZ), so the libraries compile once for both. Arguments name the targets to build (default: all).
# -O2 -gline-tables-only: clang compiles this build in half the CPU time of gcc -O2 -g, -O1 compiles no
# faster and runs the Eigen-heavy tests 1.7 times slower, and line tables are all a sanitizer report
# needs for its stack (file:line per frame).
set -euo pipefail
cd "$(dirname "$0")/.."
cmake --preset asan >/dev/null
targets=()
(($#)) && targets=(--target "$@")
cmake --build --preset asan -j"${SOFTTUNE_JOBS:-2}" "${targets[@]}"
