#!/usr/bin/env bash
# HTTP throughput and latency of `softtune serve` against a bare cpp-httplib endpoint measured in the
# same run (bench/bare_http_server.cpp returns the same bytes without doing any work), with wrk on
# loopback only. Goals: POST /api/v1/tune with 8 connections >= 0.8x the bare throughput; with one
# keep-alive connection, p50 latency <= 2x the bare one.
#
#   bench/http_bench.sh [SECONDS_PER_RUN]     (default 5; needs build/ with -DSOFTTUNE_BENCH=ON and wrk)
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-5}
build=${BUILD_DIR:-build}
threads=8
for tool in wrk python3; do command -v "$tool" >/dev/null || { echo "http_bench: $tool is missing" >&2; exit 1; }; done
for bin in "$build/softtune" "$build/bare_http_server"; do
  [[ -x $bin ]] || { echo "http_bench: $bin not built (cmake -DSOFTTUNE_BENCH=ON)" >&2; exit 1; }
done

work=$(mktemp -d)
pids=()
cleanup() {
  for pid in "${pids[@]}"; do kill "$pid" 2>/dev/null || true; done
  wait 2>/dev/null || true
  rm -rf "$work"
}
trap cleanup EXIT

request='{"response_frames": 12, "oscillation": "some", "effective_mass": 2, "fps": 60, "mode": "exact"}'
# The bare server answers with the compact bytes softtune sends for this request.
echo "$request" | "$build/softtune" tune --request - |
  python3 -c 'import json,sys; sys.stdout.write(json.dumps(json.load(sys.stdin), separators=(",", ":")))' >"$work/body.json"
cat >"$work/post.lua" <<LUA
wrk.method = "POST"
wrk.headers["Content-Type"] = "application/json"
wrk.body = '$request'
LUA

wait_for_port() {  # FILE PATTERN: prints the port once the server wrote it
  for _ in $(seq 100); do
    if port=$(grep -oE "$2" "$1" 2>/dev/null | grep -oE '[0-9]+$'); then echo "$port"; return; fi
    sleep 0.05
  done
  echo "http_bench: server did not start" >&2
  exit 1
}

"$build/softtune" serve --port 0 --threads "$threads" >"$work/softtune.out" 2>/dev/null &
pids+=($!)
"$build/bare_http_server" "$work/body.json" "$threads" >"$work/bare.out" 2>/dev/null &
pids+=($!)
softtune_port=$(wait_for_port "$work/softtune.out" '127\.0\.0\.1:[0-9]+')
bare_port=$(wait_for_port "$work/bare.out" 'port [0-9]+')

server_pid() { [[ $1 == softtune* ]] && echo "${pids[0]}" || echo "${pids[1]}"; }
cpu_ticks() { awk '{print $14 + $15}' "/proc/$1/stat"; }  # user + system, clock ticks

# run NAME PORT CONNECTIONS THREADS -> wrk output in $work/NAME.txt, server CPU ticks in $work/NAME.cpu
run() {
  local pid before
  pid=$(server_pid "$1")
  before=$(cpu_ticks "$pid")
  wrk -t"$4" -c"$3" -d"${seconds}s" --latency -s "$work/post.lua" "http://127.0.0.1:$2/api/v1/tune" >"$work/$1.txt"
  echo $(( $(cpu_ticks "$pid") - before )) >"$work/$1.cpu"
  if grep -q "Non-2xx" "$work/$1.txt"; then
    echo "http_bench: $1 got error responses" >&2
    cat "$work/$1.txt" >&2
    exit 1
  fi
}
rps() { awk '/^Requests\/sec:/ {print $2}' "$work/$1.txt"; }
requests() { awk '/requests in/ {print $1}' "$work/$1.txt"; }
p50_us() {  # the 50% line of wrk's latency distribution, in microseconds
  awk '$1 == "50%" { v = $2; u = v; sub(/[0-9.]+/, "", u); sub(/[a-z]+$/, "", v);
                      f = (u == "us") ? 1 : (u == "ms") ? 1000 : (u == "s") ? 1e6 : 0; print v * f }' "$work/$1.txt"
}

# Warm up both, then alternate the two servers over several rounds so that load from other processes
# on the machine hits both alike; the medians are compared.
rounds=${ROUNDS:-3}
wrk -t1 -c1 -d1s -s "$work/post.lua" "http://127.0.0.1:$softtune_port/api/v1/tune" >/dev/null
wrk -t1 -c1 -d1s -s "$work/post.lua" "http://127.0.0.1:$bare_port/api/v1/tune" >/dev/null
results=()
ticks_per_s=$(getconf CLK_TCK)
for round in $(seq "$rounds"); do
  run "bare8_$round" "$bare_port" 8 2
  run "softtune8_$round" "$softtune_port" 8 2
  run "bare1_$round" "$bare_port" 1 1
  run "softtune1_$round" "$softtune_port" 1 1
  for name in bare8 softtune8 bare1 softtune1; do
    results+=("$name $(rps "${name}_$round") $(p50_us "${name}_$round") $(requests "${name}_$round") $(cat "$work/${name}_$round.cpu")")
  done
done

printf '%s\n' "${results[@]}" | python3 -c '
import statistics, sys
ticks, secs, rounds = float(sys.argv[1]), float(sys.argv[2]), int(sys.argv[3])
runs = {}
for line in sys.stdin:
    name, rps, p50, n, cpu = line.split()
    runs.setdefault(name, []).append((float(rps), float(p50), float(n), float(cpu)))
med = lambda name, i: statistics.median(r[i] for r in runs[name])
cpu_us = lambda name: statistics.median(r[3] / ticks * 1e6 / r[2] for r in runs[name])
s8, b8, s1, b1 = med("softtune8", 0), med("bare8", 0), med("softtune1", 1), med("bare1", 1)
print(f"POST /api/v1/tune, wrk on 127.0.0.1, {rounds} alternating rounds of {secs:g} s per run; medians")
print(f"  8 connections:  softtune {s8:8.0f} req/s   bare {b8:8.0f} req/s   ratio {s8 / b8:.2f}x  (goal >= 0.8x)")
cs, cb = cpu_us("softtune8"), cpu_us("bare8")
print(f"                  server CPU per request: softtune {cs:.1f} us, bare {cb:.1f} us")
print(f"  1 connection:   softtune p50 {s1:6.1f} us   bare p50 {b1:6.1f} us   ratio {s1 / b1:.2f}x  (goal <= 2x)")
print("  per round (8-conn req/s softtune/bare):", " ".join(f"{s[0]:.0f}/{b[0]:.0f}" for s, b in zip(runs["softtune8"], runs["bare8"])))
' "$ticks_per_s" "$seconds" "$rounds"
