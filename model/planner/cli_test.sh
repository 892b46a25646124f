#!/usr/bin/env bash
# `contour gcode` end to end: paper B's program, outputs, and every CLI error
# (exit status 2, exactly one line on stderr naming the problem).
set -uo pipefail
contour=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fails=0 passes=0
ok() { passes=$((passes + 1)); }
bad() { echo "FAIL: $*"; fails=$((fails + 1)); }

printf 'G00X50.Y0.Z0.\nG03X0.Y-47.246Z-16.366I-50J0.K0.F6000\nG00X0.Y0.Z0.\n' > "$work/paperb.ngc"
printf 'G1 X1 Y2 Z-3 F600\n' > "$work/line.ngc"

# Paper B: the arc block (segment 2) takes 2.46 s; all limits respected.
json=$("$contour" gcode "$work/paperb.ngc" --format json) || bad "paper B json exit $?"
arc_t=$(echo "$json" | sed 's/.*"kind": "3D arc", [^}]*"time_s": \([0-9.]*\).*/\1/')
awk -v t="$arc_t" 'BEGIN { exit !(t >= 2.45 && t <= 2.47) }' && ok || bad "3D arc time '$arc_t' is not 2.46 +- 0.01"
echo "$json" | grep -q '"total_time_s": [0-9]' && ok || bad "no total_time_s"
echo "$json" | grep -q '"all_ok": true' && ok || bad "limits not all respected: $json"

# The full circle: 100 pi mm at 100 mm/s plus one acceleration time.
printf 'G0 X50\nG03X50.Y0.I-50.J0.F6000\n' > "$work/circle.ngc"
t=$("$contour" gcode "$work/circle.ngc" --format json | sed 's/.*"kind": "full circle", [^}]*"time_s": \([0-9.]*\).*/\1/')
awk -v t="$t" 'BEGIN { exit !(t >= 3.23 && t <= 3.26) }' && ok || bad "full circle time '$t'"

# Summary text names every limit.
sum=$("$contour" gcode "$work/paperb.ngc" --tol 0.05 --chord b --cycle 2 --accel 1764000)
for w in "total time" "look-ahead     at most" "peak feed" "max chord err" "chord method b" "tolerance 0.05 um" "of 2 ms" "1764000"; do
  echo "$sum" | grep -q "$w" && ok || bad "summary lacks '$w'"
done

# Machine limits from a config file: X at 3000 mm/min, 0.05 g.
printf '# slow X\nvmax_x = 3000\namax_x = 1764000 # 0.05 g\nrapid=20000\n' > "$work/slow.cfg"
out=$("$contour" gcode "$work/paperb.ngc" --config "$work/slow.cfg") || bad "config run exit $?"
echo "$out" | grep -Eq '^X +[0-9.]+ +3000.0 +ok +[0-9]+ +1764000 +ok' && ok || bad "config limits not applied: $out"
xv=$(echo "$out" | awk '$1 == "X" { print $2 }')
awk -v v="$xv" 'BEGIN { exit !(v > 2900 && v <= 3000) }' && ok || bad "X peak velocity $xv with a 3000 limit"

# CSV: header and one row per cycle plus the start.
"$contour" gcode "$work/paperb.ngc" --csv "$work/p.csv" > /dev/null || bad "csv exit"
head -1 "$work/p.csv" | grep -qx 't_s,x_mm,y_mm,z_mm,feed_mm_min,vx_mm_min,vy_mm_min,vz_mm_min' && ok || bad "csv header"
cycles=$(echo "$json" | sed 's/.*"cycles": \([0-9]*\).*/\1/')
[ "$(wc -l < "$work/p.csv")" -eq $((cycles + 2)) ] && ok || bad "csv rows $(wc -l < "$work/p.csv") for $cycles cycles"

# The summary streams its samples (none kept) unless --csv or --svg keeps
# them: both ways measure the same.
printf 'G21 G64 P0.01\nG0 X50 Y0\nG1 F3000\n' > "$work/poly.ngc"
awk 'BEGIN { for (k = 1; k <= 200; k++) printf "X%.4f Y%.4f Z%.4f\n", 50 * cos(k / 40), 50 * sin(k / 40), k / 100 }' >> "$work/poly.ngc"
streamed=$("$contour" gcode "$work/poly.ngc" --format json) || bad "polyline json exit $?"
kept=$("$contour" gcode "$work/poly.ngc" --format json --csv "$work/poly.csv") || bad "polyline json+csv exit $?"
[ -n "$streamed" ] && [ "$streamed" = "$kept" ] && ok || bad "streamed summary differs from the kept one"

# SVG: the five plots, each with a title and axis labels.
"$contour" gcode "$work/paperb.ngc" --svg "$work/svg" > /dev/null || bad "svg exit"
for f in velocity xy yz zx uv-line2; do
  grep -q '<svg' "$work/svg/$f.svg" && grep -q '(mm' "$work/svg/$f.svg" && ok || bad "svg $f"
done

# Pulses: 1000 steps per mm, every step once, in time order.
"$contour" gcode "$work/line.ngc" --pulses --steps-per-mm 1000 --engine model > "$work/pulses.txt" || bad "pulses exit"
[ "$(grep -c ' +X$' "$work/pulses.txt")" -eq 1000 ] && [ "$(grep -c ' +Y$' "$work/pulses.txt")" -eq 2000 ] &&
  [ "$(grep -c ' -Z$' "$work/pulses.txt")" -eq 3000 ] && [ "$(wc -l < "$work/pulses.txt")" -eq 6000 ] && ok ||
  bad "pulse counts"
sort -s -g -k1,1 -c "$work/pulses.txt" && ok || bad "pulses not in time order"

# R arcs by LinuxCNC's rule: a semicircle whose end is rounded by 1 um runs
# on the half circle of its chord, within the tolerance (exit 0; it was
# interpolated at radius R about the midpoint and flagged EXCEEDED).
printf 'G21 G0 X10 Y0\nG3 X-10.001 Y0 R10 F600\n' > "$work/semi.ngc"
"$contour" gcode "$work/semi.ngc" > "$work/semi.out" && ok || bad "rounded semicircle exit $?: $(cat "$work/semi.out")"

# Blending: the corner error is reported against the blend tolerance.
printf 'G1 X10 F3000\nX20 Y0.1\nX30 Y0\n' > "$work/bend.ngc"
out=$("$contour" gcode "$work/bend.ngc" --blend-tol 5) || bad "bend exit $?"
echo "$out" | grep -Eq '^max corner err +[0-9.]+ um \(blend tolerance 5 um unless G64 P\): ok' && ok || bad "corner line: $out"
"$contour" gcode "$work/bend.ngc" --format json | grep -q '"blend_ok": true' && ok || bad "json blend_ok"

# Errors: exit 2, one line on stderr, naming the problem.
printf 'G1 X1 F10\nG2 X10.04 Y0 I5 J0\n' > "$work/radius.ngc"
printf 'G1 X1 F10\nG1 M98\n' > "$work/word.ngc"
printf 'vmax_x = 6000\nspeed = 3\n' > "$work/bad.cfg"
printf 'amax_x = -1\n' > "$work/neg.cfg"
expect_error() {  # want-substring args...
  local want=$1
  shift
  "$contour" gcode "$@" > "$work/out" 2> "$work/err"
  local rc=$?
  if [ $rc -ne 2 ]; then bad "exit $rc (want 2) for: $*"; return; fi
  if [ "$(wc -l < "$work/err")" -ne 1 ]; then bad "stderr is not one line for: $*: $(cat "$work/err")"; return; fi
  grep -qF -- "$want" "$work/err" && ok || bad "stderr '$(cat "$work/err")' lacks '$want'"
}
expect_error "cannot read '$work/none.ngc'" "$work/none.ngc"
expect_error "missing argument FILE"
expect_error "radius.ngc: line 2, column 1: radius to end of arc differs from radius to start: r1=5.0000 mm r2=4.0400 mm" "$work/radius.ngc"
expect_error "word.ngc: line 2, column 4: unsupported M code M98" "$work/word.ngc"
expect_error "--chord: unknown placement 'd'" "$work/line.ngc" --chord d
expect_error "--tol: must be > 0" "$work/line.ngc" --tol 0
expect_error "--cycle: 'fast' is not a number" "$work/line.ngc" --cycle fast
expect_error "--accel: must be > 0" "$work/line.ngc" --accel 0
expect_error "--format: unknown format 'xml'" "$work/line.ngc" --format xml
expect_error "bad.cfg:2: unknown key 'speed'" "$work/line.ngc" --config "$work/bad.cfg"
expect_error "neg.cfg:1: amax_x" "$work/line.ngc" --config "$work/neg.cfg"
expect_error "--config: cannot read" "$work/line.ngc" --config "$work/none.cfg"
expect_error "--engine needs --pulses" "$work/line.ngc" --engine model
expect_error "--steps-per-mm needs --pulses" "$work/line.ngc" --steps-per-mm 10
expect_error "--engine: unknown engine 'nope'" "$work/line.ngc" --pulses --engine nope
expect_error "--steps-per-mm: must be > 0" "$work/line.ngc" --pulses --steps-per-mm 0
expect_error "does not combine" "$work/line.ngc" --pulses --csv "$work/x.csv"
expect_error "unknown option '--bogus'" "$work/line.ngc" --bogus
expect_error "'$work' is a directory, not a file" "$work"
expect_error "--config: '$work' is a directory" "$work/line.ngc" --config "$work"
expect_error "--cycle: at most 1000 ms" "$work/line.ngc" --cycle 1000000000
expect_error "--cycle: '1e9' is not a number" "$work/line.ngc" --cycle 1e9
expect_error "--blend-tol: must be >= 0" "$work/line.ngc" --blend-tol -1
printf 'T1 P1 Z1\nT1 P2 Z2\n' > "$work/twice.tbl"
expect_error "--tool-table: $work/twice.tbl: line 2, column 1: tool table: tool 1 is listed twice" "$work/line.ngc" --tool-table "$work/twice.tbl"
printf 'G43 H1\n' > "$work/tlo.ngc"
expect_error "tlo.ngc: line 1, column 5: tool 1 is not in the tool table (give one with --tool-table)" "$work/tlo.ngc"
printf 'G0 X10 Y0\nG2 X-10 Y0 R9.975 F600\n' > "$work/rshort.ngc"
expect_error "rshort.ngc: line 2, column 12: arc radius too small to reach the end point: |R|=9.9750" "$work/rshort.ngc"
printf 'G1 X100000 F0.01\n' > "$work/long.ngc"
expect_error "more than this tool simulates" "$work/long.ngc"

echo "cli: $passes passed, $fails failed"
[ "$fails" -eq 0 ]
