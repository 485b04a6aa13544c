# Sourced by the test scripts: run_parallel JOBS FUNCTION ITEM... calls FUNCTION ITEM for every item, JOBS
# at a time (one per core: each libFuzzer or sanitizer process is mostly one busy thread), and returns 1
# when any call failed (after all have run).
run_parallel() {
  local jobs=$1 fn=$2 failed=0 running=0 item
  shift 2
  for item in "$@"; do
    if ((running >= jobs)); then
      wait -n || failed=1
      running=$((running - 1))
    fi
    "$fn" "$item" &
    running=$((running + 1))
  done
  while ((running > 0)); do
    wait -n || failed=1
    running=$((running - 1))
  done
  return "$failed"
}
