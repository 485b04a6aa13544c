#!/usr/bin/env bash
# Load and soak: `softtune serve` on 127.0.0.1 under wrk for SOFTTUNE_SOAK_SECONDS (default 60) with the
# mixed routes of bench/load_soak.lua (tune, health, previews and their frames, page, OpenAPI, metrics).
# Passes with zero errors (no 4xx/5xx, no socket errors or timeouts) and RSS growth under 10 % between
# the end of a 10 s warm-up and the end of the run; prints latency percentiles and RSS figures.
# Usage: bench/load_soak.sh [path/to/softtune]   (default build/softtune)
set -euo pipefail
cd "$(dirname "$0")/.."
softtune=${1:-build/softtune}
seconds=${SOFTTUNE_SOAK_SECONDS:-60}
connections=${SOFTTUNE_SOAK_CONNECTIONS:-16}
# The server's default 8 workers: idle keep-alive connections wait in the connection gate, not in a
# worker, so 16 connections need no more threads than requests being served at once.
threads=${SOFTTUNE_SOAK_THREADS:-8}
work=$(mktemp -d)
"$softtune" serve --host 127.0.0.1 --port 0 --threads "$threads" >"$work/serve.log" 2>&1 &
pid=$!
trap 'kill $pid 2>/dev/null || true; wait $pid 2>/dev/null || true; rm -rf "$work"' EXIT
for _ in $(seq 100); do grep -q serving "$work/serve.log" && break; sleep 0.1; done
port=$(sed -n 's|.*127.0.0.1:\([0-9]*\)/.*|\1|p' "$work/serve.log")
url=http://127.0.0.1:$port
rss() { awk -v k="$1:" '$1 == k {print $2}' /proc/$pid/status; }
# The raster processes (preview frames are drawn in children of the server that hold Mesa), apart.
raster_rss() {
  local total=0 child
  for child in $(cat /proc/$pid/task/*/children 2>/dev/null); do
    total=$((total + $(awk '$1 == "VmRSS:" {print $2}' /proc/$child/status 2>/dev/null || echo 0)))
  done
  echo "$total"
}

id=$(curl -sf -H 'Content-Type: application/json' -d '{"preset": "oscillator", "frames": 8, "size": "320x180"}' \
  "$url/api/v1/preview" | python3 -c 'import json,sys; print(json.load(sys.stdin)["id"])')
echo "soak: server pid $pid on $url ($threads threads, $connections connections), preview $id; rss at start $(rss VmRSS) kB"
wrk -t2 -c"$connections" -d10s -s bench/load_soak.lua "$url" -- "$id" >"$work/warmup.txt"
rss_warm=$(rss VmRSS)
raster_warm=$(raster_rss)
( while kill -0 $pid 2>/dev/null; do r=$(rss VmRSS); echo "$r"; sleep 0.5; done ) >"$work/rss.txt" &
sampler=$!
wrk -t2 -c"$connections" -d"${seconds}s" --latency -s bench/load_soak.lua "$url" -- "$id" | tee "$work/wrk.txt"
rss_end=$(rss VmRSS)
kill $sampler 2>/dev/null || true
peak=$(sort -n "$work/rss.txt" | tail -n1)
line=$(grep '^LOAD ' "$work/wrk.txt")
get() { sed -n "s/.* $1=\([0-9.]*\).*/\1/p" <<<"$line"; }
growth=$(python3 -c "print(f'{100.0 * ($rss_end - $rss_warm) / $rss_warm:.2f}')")
echo "soak: rss after warm-up ${rss_warm} kB, at end ${rss_end} kB (growth ${growth} %), peak ${peak} kB, VmHWM $(rss VmHWM) kB"
echo "soak: raster processes' rss after warm-up ${raster_warm} kB, at end $(raster_rss) kB (released after 30 s without a frame)"
errors=$(( $(get status4xx) + $(get status5xx) + $(get socket_errors) + $(get timeouts) ))
if (( errors > 0 )) || ! python3 -c "import sys; sys.exit(0 if $growth < 10 else 1)"; then
  echo "soak: FAIL (errors $errors, rss growth $growth %)"; exit 1
fi
echo "soak: PASS (zero errors, rss growth $growth % < 10 %)"
