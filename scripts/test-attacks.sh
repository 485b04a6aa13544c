#!/usr/bin/env bash
# The attack suite against the real `softtune serve` on 127.0.0.1 (scripts/attacks.py): chunked and
# declared 100 MB bodies, a gzip bomb, a 1 MB header line, 10 000 headers, path traversal variants,
# slowloris (1000 slow connections for SOFTTUNE_SLOWLORIS_SECONDS, default 20) and a slowloris flood
# (3000, more than the server holds, for half that), a preview flood, a Range header of 1000 ranges, slow
# bodies (20 and 200 clients), 500 clients at once, crowded scenes priced within budget that run to their
# run-time limit, and the memory after idle. Needs build/softtune (scripts/build.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
python3 scripts/attacks.py build/softtune --slowloris-seconds "${SOFTTUNE_SLOWLORIS_SECONDS:-20}" "$@"
