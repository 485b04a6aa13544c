#!/usr/bin/env bash
# Builds the libFuzzer harnesses into build-fuzz/ with clang++-14. Every library is instrumented too
# (fuzzer-no-link: coverage feedback from the codec and core, not only from the harness; address and
# undefined: reports from inside them).
set -euo pipefail
cd "$(dirname "$0")/.."
flags="-fsanitize=fuzzer-no-link,address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined"
CXX=clang++-14 CC=clang-14 cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSOFTTUNE_FUZZ=ON \
  -DSOFTTUNE_BENCH=OFF -DCMAKE_CXX_FLAGS="$flags" >/dev/null
cmake --build build-fuzz -j2 --target tune_request_fuzz request_decode_fuzz simulate_request_fuzz \
  accuracy_request_fuzz preset_load_fuzz
