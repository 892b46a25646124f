#!/usr/bin/env bash
# Runs the benchmarks of BUILD_DIR (after `cmake --build BUILD_DIR --target
# benches`): model/bench/run.sh BUILD_DIR [Google Benchmark flags...]
# e.g. --benchmark_filter='Plan|Chord|TwoStage' for paper B's figures only.
set -euo pipefail
build=${1:-build}
shift || true
bin="$build/model/bench/contour_bench"
[ -x "$bin" ] || { echo "run.sh: $bin not built (cmake --build $build --target benches)" >&2; exit 2; }
"$bin" --benchmark_counters_tabular=true "$@"
if [ $# -eq 0 ] && [ -x "$build/model/bench/interp_ipp" ]; then "$build/model/bench/interp_ipp"; fi
