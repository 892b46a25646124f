#!/usr/bin/env bash
# libFuzzer run of the G-code reader on a copy of the seed corpus (the seeds
# in git are never written to).
#
#   fuzz_run.sh BIN SEEDS WORK [libFuzzer options...]
#
# ctest (gcode_fuzz_run) passes a fixed run count and seed, so the run is
# bounded by work, not time: -runs=N -seed=S -reload=0 (the corpus is not
# re-read on a timer): the same number of inputs from the same seed, on any
# machine. Not bit-exact: the mutations follow coverage feedback, and two
# runs differed by a few edges. Without options the run is time-boxed
# instead, FUZZ_SECONDS (default 20), for fuzzing by hand, e.g.
#   FUZZ_SECONDS=600 model/gcode/fuzz_run.sh build/model/gcode/gcode_fuzz model/gcode/corpus /tmp/fuzz
set -euo pipefail
bin=$(realpath "$1") seeds=$(realpath "$2") work=$3
shift 3
[ $# -gt 0 ] || set -- -max_total_time="${FUZZ_SECONDS:-20}"
rm -rf "$work" && mkdir -p "$work/corpus"
cp "$seeds"/* "$work/corpus/"
cd "$work"
exec "$bin" "$@" -max_len=512 -timeout=5 -print_final_stats=1 corpus
