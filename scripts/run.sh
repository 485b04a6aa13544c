#!/usr/bin/env bash
# Sets up, builds and starts softtune's main job. Arguments replace the default command.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
scripts/build.sh
if (($#)); then exec build/softtune "$@"; fi
exec build/softtune serve
