#!/bin/sh
# `make coverage`: line and toggle coverage of the interp_core regression
# (interp_rtl_cov: interp_rtl_test's sources on the coverage models of
# tb_interp_cov, W = 8 and W = 24). Usage: coverage.sh BUILD [gtest filter]
# Writes BUILD/coverage/: interp_core.dat.N (one per harness), merged.dat,
# merged.info (lcov), annotated/ (the sources; verilator_coverage flags a
# line '%00' when a point of it counts under 10), uncovered.txt (every point
# never hit: page, line, signal bits), and prints a line per module: line
# (v_line + v_branch) and toggle points covered, both widths together.
set -eu
build=$1
filter=${2:-*}
out=$build/coverage
rm -rf "$out"
mkdir -p "$out"
start=$(date +%s)
CONTOUR_COVERAGE=$out/interp_core.dat "$build/tb/interp/interp_rtl_cov" \
  --gtest_filter="$filter" --gtest_brief=1
echo "regression: $(( $(date +%s) - start )) s"
verilator_coverage --write "$out/merged.dat" "$out"/interp_core.dat.*
verilator_coverage --write-info "$out/merged.info" "$out/merged.dat"
verilator_coverage --annotate "$out/annotated" --annotate-all "$out/merged.dat"
# Per module: a point's page is v_line|v_branch|v_toggle/<module>__<params>.
awk -F'\001' '
  /^C / {
    cnt = $0; sub(/.*\047 /, "", cnt)
    page = ""; line = ""; what = ""
    for (i = 2; i <= NF; i++) {
      split($i, kv, "\002")
      if (kv[1] == "page") page = kv[2]
      if (kv[1] == "l") line = kv[2]
      if (kv[1] == "o") what = kv[2]
    }
    if (cnt + 0 == 0) print page, line, what > uncovered
    split(page, p, "/"); mod = p[2]; sub(/__.*/, "", mod)
    kind = (p[1] == "v_toggle") ? "t" : "l"
    mods[mod] = 1; all[mod, kind]++; if (cnt + 0 > 0) hit[mod, kind]++
    all["TOTAL", kind]++; if (cnt + 0 > 0) hit["TOTAL", kind]++
  }
  function pc(m, k) { return all[m, k] ? sprintf("%5.1f%% (%d/%d)", 100 * hit[m, k] / all[m, k], hit[m, k], all[m, k]) : "-" }
  END {
    printf "%-12s %-22s %s\n", "module", "lines", "toggles"
    for (m in mods) printf "%-12s %-22s %s\n", m, pc(m, "l"), pc(m, "t")
    printf "%-12s %-22s %s\n", "TOTAL", pc("TOTAL", "l"), pc("TOTAL", "t")
  }' uncovered="$out/uncovered.txt" "$out/merged.dat"
echo "never hit: $out/uncovered.txt; annotated sources: $out/annotated"

