# Sourced by the fuzz scripts: where each harness's inputs live.
#   fuzz/seeds/<harness>/        in git: a few dozen readable inputs, picked to keep the grown corpus's coverage
#   fuzz/regressions/<harness>/  in git: every crash input found and fixed, named for what it broke
#   $SOFTTUNE_FUZZ_CACHE/<harness>/  outside the repository (default ~/.cache/softtune/fuzz): the corpus the
#                                long runs grow (scripts/fuzz-long.sh merges into it), read by the short runs
fuzz_names=(tune_request request_decode simulate_request accuracy_request preset_load)
fuzz_cache=${SOFTTUNE_FUZZ_CACHE:-${XDG_CACHE_HOME:-$HOME/.cache}/softtune/fuzz}
