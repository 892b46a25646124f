#!/usr/bin/env bash
# Short libFuzzer run of the G-code reader: FUZZ_SECONDS (default 20) on a
# copy of the seed corpus (the seeds in git are never written to).
set -euo pipefail
bin=$(realpath "$1") seeds=$(realpath "$2") work=$3
rm -rf "$work" && mkdir -p "$work/corpus"
cp "$seeds"/* "$work/corpus/"
cd "$work"
exec "$bin" -max_total_time="${FUZZ_SECONDS:-20}" -max_len=512 -timeout=5 -print_final_stats=1 corpus
