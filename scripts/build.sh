#!/usr/bin/env bash
# Configures and builds softtune into build/ (Release; CMakePresets.json "dev"). Extra arguments go to
# cmake's configure step.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake --preset dev "$@" >/dev/null
cmake --build --preset dev -j"$(nproc)"
