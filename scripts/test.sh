#!/usr/bin/env bash
# Sets up, builds and runs every test (ctest). This is the README's test command and what CI runs.
# After the plain ctest: the attack suite against `softtune serve`, the whole suite under ASan+UBSan and
# the server/render-pool tests under TSan, and each fuzz harness for a short bounded time.
# SOFTTUNE_QUICK=1 stops after the plain ctest and the attacks (for a fast local loop).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
scripts/build.sh
(cd build && ctest --output-on-failure -j"$(nproc)" --timeout 900)
scripts/test-attacks.sh
[[ ${SOFTTUNE_QUICK:-0} == 1 ]] && exit 0
scripts/test-sanitizers.sh
scripts/test-fuzz-short.sh
