#!/usr/bin/env bash
# `make bench`, paper B part: blended corners, helix against plane arcs, and
# a long program of short lines (time and peak memory). Figures go to
# docs/paper-b.md with this command:
#   model/planner/bench_gcode.sh build/contour
set -euo pipefail
contour=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# 1000 G1 segments on a circle R 50 at F3000 (0.1 g, the defaults) against
# the same circle as one G2 block; G64 P0.01 and G61.
polygon() {  # mode n
  awk -v mode="$1" -v n="$2" 'BEGIN { printf "G21 G90 G17 %s\nG0 X50 Y0\nG1 F3000\n", mode;
    for (k = 1; k <= n; k++) printf "X%.4f Y%.4f\n", 50 * cos(2 * 3.14159265358979 * k / n), 50 * sin(2 * 3.14159265358979 * k / n) }'
}
polygon "G64 P0.01" 1000 > "$work/blend.ngc"
polygon "G61" 1000 > "$work/exact.ngc"
printf 'G21 G90 G17\nG0 X50 Y0\nG2 X50 Y0 I-50 J0 F3000\n' > "$work/g2.ngc"
circle_time() {  # file: the time of every block after the first (the rapid)
  "$contour" gcode "$1" --format json | grep -o '"time_s": [0-9.e+-]*' | tail -n +2 |
    awk '{ t += $2 } END { printf "%.4f", t }'
}
t_g2=$(circle_time "$work/g2.ngc"); t_blend=$(circle_time "$work/blend.ngc"); t_exact=$(circle_time "$work/exact.ngc")
echo "circle R50 F3000: one G2 ${t_g2} s; 1000 G1 G64 P0.01 ${t_blend} s ($(awk -v a="$t_blend" -v b="$t_g2" 'BEGIN { printf "%.3f", a / b }') x); G61 ${t_exact} s"

# Helix against plane arcs: 20 full circles R 10 at F3000, then the same
# with Z falling 1 mm per turn. Cycles per second of the whole command
# (read, plan, interpolate, measure every chord) and of --pulses (no
# measurement).
awk 'BEGIN { print "G21 G90 G17\nG0 X10 Y0\nG1 F3000"; for (k = 0; k < 20; k++) print "G2 X10 Y0 I-10 J0" }' > "$work/plane.ngc"
awk 'BEGIN { print "G21 G90 G17\nG0 X10 Y0\nG1 F3000"; for (k = 1; k <= 20; k++) printf "G2 X10 Y0 Z%d I-10 J0\n", -k }' > "$work/helix.ngc"
rate() {  # file [options]: cycles per second
  local f=$1; shift
  local cycles; cycles=$("$contour" gcode "$f" --format json | sed 's/.*"cycles": \([0-9]*\).*/\1/')
  local t0 t1; t0=$(date +%s.%N); "$contour" gcode "$f" "$@" > /dev/null; t1=$(date +%s.%N)
  awk -v c="$cycles" -v a="$t0" -v b="$t1" 'BEGIN { printf "%d cycles, %.0f cycles/s", c, c / (b - a) }'
}
echo "plane arcs, summary: $(rate "$work/plane.ngc")"
echo "helix,      summary: $(rate "$work/helix.ngc")"
echo "plane arcs, --pulses: $(rate "$work/plane.ngc" --pulses --steps-per-mm 10)"
echo "helix,      --pulses: $(rate "$work/helix.ngc" --pulses --steps-per-mm 10)"

# A long program of short G1 segments (0.05 to 0.5 mm, a CAM surface pass):
# time and peak resident memory of the whole command.
awk 'BEGIN { srand(1); print "G21 G90 G17 G64 P0.01\nG1 F3000"; x = 0; y = 0;
  for (k = 0; k < 200000; k++) { x += 0.3 * cos(k / 500); y += 0.3 * sin(k / 500) + 0.05 * (rand() - 0.5); printf "X%.4f Y%.4f Z%.4f\n", x, y, 0.01 * sin(k / 50) } }' > "$work/long.ngc"
size=$(wc -c < "$work/long.ngc")
/usr/bin/time -f "%e s %M KB" "$contour" gcode "$work/long.ngc" > "$work/long.out" 2> "$work/long.time" || true
echo "200000 short G1 lines ($((size / 1024 / 1024)) MB): $(grep -E '^total time|^program' "$work/long.out" | tr '\n' ' ') -- $(tail -1 "$work/long.time")"

# A 50 MB program of short G1 segments (1.87 M lines of 0.1 mm, F3000, G64
# P0.01): peak resident memory, cycles per second of the whole command, and
# the widest look-ahead window the planner used.
awk 'BEGIN { srand(1); print "G21 G90 G17 G64 P0.01\nG1 F3000"; x = 0; y = 0;
  for (k = 0; k < 1870000; k++) { x += 0.1 * cos(k / 500); y += 0.1 * sin(k / 500) + 0.02 * (rand() - 0.5); printf "X%.4f Y%.4f Z%.4f\n", x, y, 0.01 * sin(k / 50) } }' > "$work/long50.ngc"
size=$(wc -c < "$work/long50.ngc")
/usr/bin/time -f "%e %M" "$contour" gcode "$work/long50.ngc" > "$work/long50.out" 2> "$work/long50.time" || true
cycles=$(awk '/^program/ { for (i = 1; i <= NF; i++) if ($(i + 1) == "cycles") { print $i; exit } }' "$work/long50.out")
window=$(awk '/^look-ahead/ { print $4; exit }' "$work/long50.out")
read -r secs kb < <(tail -1 "$work/long50.time")
echo "1870000 short G1 lines ($((size / 1000000)) MB), summary: $cycles cycles in $secs s ($(awk -v c="$cycles" -v s="$secs" 'BEGIN { printf "%.2f", c / s / 1e6 }') M cycles/s), peak $((kb / 1024)) MB resident, look-ahead window at most $window blocks"
