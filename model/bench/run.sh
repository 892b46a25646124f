#!/usr/bin/env bash
# Runs the benchmarks: model/bench/run.sh BUILD_DIR [benchmark flags...]
# (`make bench` builds target `benches` first).
set -euo pipefail
build=${1:-build}
shift || true
bin="$build/model/bench/contour_bench"
[ -x "$bin" ] || { echo "run.sh: $bin not built (cmake --build $build --target benches)" >&2; exit 2; }
exec "$bin" --benchmark_counters_tabular=true "$@"
