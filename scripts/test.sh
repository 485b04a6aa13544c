#!/usr/bin/env bash
# Sets up, builds and runs every test (ctest), then the attack suite against a real `softtune serve`.
# This is the README's test command and what CI runs. The sanitizer builds (scripts/test-sanitizers.sh) and
# the short fuzz runs (scripts/test-fuzz-short.sh) are separate commands until they have run end to end
# within CI's budget (README, "Limits and security").
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
scripts/build.sh
(cd build && ctest --output-on-failure -j"$(nproc)" --timeout 900)
scripts/test-attacks.sh
