#!/usr/bin/env bash
# The README's test command and what CI runs. Stages, in order (fastest failure feedback first):
#   setup        scripts/setup.sh (Debian packages and npm ci; only checks when all is installed)
#   build        scripts/build.sh: the plain Release build in build/
#   ctest        every test in build/ (GoogleTest, CLI, the page in Node and headless Chromium)
#   package      scripts/test-package.sh: the Debian package built, unpacked into a scratch root, run from there
#   attacks      scripts/test-attacks.sh: the attack suite against a real `softtune serve`
#   asan-build   scripts/build-asan.sh: clang ASan+UBSan build of the suite and the fuzz harnesses, build-asan/
#   asan-ctest   every test in build-asan/ under ASan+UBSan (LSan on)
#   fuzz         scripts/test-fuzz-short.sh: regressions replayed, then each harness 30 s, two at a time
#   tsan         the server and render-pool tests built and run under TSan, build-tsan/
# Any sanitizer report fails its stage. At the end (also after a failure) it prints each stage's wall
# time and the load average when the stage ended.
# `scripts/test.sh --quick`: the edit-and-test loop, only the build stage and the ctest tests labelled
# unit (CMakePresets.json "quick"; labels: cmake/TestLabels.cmake), no setup.
set -euo pipefail
cd "$(dirname "$0")/.."
quick=0
case ${1:-} in
  --quick) quick=1 ;;
  "") ;;
  *) echo "usage: scripts/test.sh [--quick]" >&2; exit 2 ;;
esac

summary=()
current=""
report() {
  local rc=$?
  ((${#summary[@]})) && printf 'test.sh: %s\n' "${summary[@]}"
  if ((rc)); then echo "test.sh: FAILED in stage $current (exit $rc)"; else echo "test.sh: all stages passed"; fi
}
trap report EXIT

# stage NAME COMMAND...: runs the command, records its wall time and the load average after it.
stage() {
  current=$1
  shift
  echo "test.sh: == $current"
  local started=$SECONDS
  "$@"
  summary+=("$(printf '%-10s %5d s   load %s' "$current" $((SECONDS - started)) "$(cut -d' ' -f1-3 /proc/loadavg)")")
}

started=$SECONDS
if ((quick)); then
  stage build scripts/build.sh
  stage unit ctest --preset quick -j"$(nproc)"
  summary+=("$(printf '%-10s %5d s' total $((SECONDS - started)))")
  exit 0
fi
stage setup scripts/setup.sh
stage build scripts/build.sh
stage ctest ctest --preset dev -j"$(nproc)"
stage package scripts/test-package.sh
stage attacks scripts/test-attacks.sh
stage asan-build scripts/build-asan.sh
stage asan-ctest scripts/test-sanitizers.sh asan
stage fuzz scripts/test-fuzz-short.sh
stage tsan scripts/test-sanitizers.sh tsan
summary+=("$(printf '%-10s %5d s' total $((SECONDS - started)))")
