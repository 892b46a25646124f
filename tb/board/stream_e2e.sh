#!/usr/bin/env bash
# The end-to-end test of the host link (ctest board_stream_*): `contour
# board-sim` on a pseudo-terminal, `contour stream PROGRAM --port` into it,
# as a user runs them. Checks, against `contour gcode PROGRAM --pulses`
# (the golden two-stage model):
#   - the board's STEP/DIR pins gave exactly the model's pulses, in order;
#   - the position the host read back equals the net of the model's pulses
#     and of the pins';
#   - stream exited 0; with faults (board-sim options), it sent frames again;
#   - with --progress (first option): the progress lines (forced, stderr a
#     file) reach 100 %, and each position they show (the replies') is, on
#     each axis, the pins' net after some prefix of the pulses.
# (stream gets --timeout 60: the simulated board runs ~10x slower than a
# real one, so a cut of 0.2 s on its wire lasts seconds of the host's time.)
# usage: stream_e2e.sh CONTOUR PROGRAM WORKDIR [--progress] [board-sim options: faults]
set -euo pipefail
contour=$1 prog=$2 work=$3
shift 3
show=--quiet
if [ "${1:-}" = --progress ]; then show=--progress; shift; fi
rm -rf "$work" && mkdir -p "$work"
"$contour" board-sim --pulses "$work/pins.txt" --port-file "$work/port" --max-time 60 "$@" >"$work/sim.log" &
sim=$!
trap 'kill $sim 2>/dev/null || true' EXIT
for _ in $(seq 200); do [ -s "$work/port" ] && break; sleep 0.05; done
[ -s "$work/port" ] || { echo "board-sim printed no port"; exit 1; }
rc=0
timeout 600 "$contour" stream "$prog" --port "$(cat "$work/port")" $show --timeout 60 >"$work/stream.log" 2>"$work/progress.log" || rc=$?
wait $sim
trap - EXIT
cat "$work/stream.log" "$work/sim.log"
[ $show = --progress ] || cat "$work/progress.log"
[ $rc -eq 0 ] || { echo "FAIL: contour stream exited $rc"; exit 1; }
"$contour" gcode "$prog" --pulses >"$work/model.txt"
awk '{print $2}' "$work/pins.txt" >"$work/pins.seq"
awk '{print $2}' "$work/model.txt" >"$work/model.seq"
if ! cmp -s "$work/pins.seq" "$work/model.seq"; then
  echo "FAIL: the pins differ from the model: $(wc -l <"$work/pins.seq") pulses vs $(wc -l <"$work/model.seq")"
  diff "$work/pins.seq" "$work/model.seq" | head -5
  exit 1
fi
# The net of the model's pulses per axis, and the host's readback.
net=$(awk '{s=substr($2,1,1)=="-"?-1:1; a=substr($2,2,1); n[a]+=s} END {printf "%d %d %d", n["X"], n["Y"], n["Z"]}' "$work/model.txt")
read_back=$(sed -n 's/^stream: position \([-0-9]*\) \([-0-9]*\) \([-0-9]*\) steps.*/\1 \2 \3/p' "$work/stream.log")
[ "$net" = "$read_back" ] || { echo "FAIL: position read back '$read_back', model's net '$net'"; exit 1; }
pins_net=$(awk '{s=substr($2,1,1)=="-"?-1:1; a=substr($2,2,1); n[a]+=s} END {printf "%d %d %d", n["X"], n["Y"], n["Z"]}' "$work/pins.txt")
[ "$pins_net" = "$read_back" ] || { echo "FAIL: position read back '$read_back', the pins' net '$pins_net'"; exit 1; }
if [ $# -gt 0 ]; then  # faults on the wire: the host must have sent frames again
  resends=$(sed -n 's/^stream: link [0-9]* frames, \([0-9]*\) resends.*/\1/p' "$work/stream.log")
  [ "${resends:-0}" -gt 0 ] || { echo "FAIL: faults on the wire ($*) and no resend"; exit 1; }
fi
if [ $show = --progress ]; then
  lines=$(grep -c 'chords  X' "$work/progress.log" || true)
  grep -q '100% ' "$work/progress.log" || { echo "FAIL: no progress line at 100 %"; tail -3 "$work/progress.log"; exit 1; }
  # Positions shown (mm at 1000 steps/mm) against every prefix net of the pins, axis by axis.
  bad=$(awk 'NR == FNR { s = substr($2,1,1) == "-" ? -1 : 1; a = substr($2,2,1); n[a] += s; seen[a, n[a]] = 1; next }
             FNR == 1 { seen["X", 0] = seen["Y", 0] = seen["Z", 0] = 1 }
             /chords  X/ { for (i = 1; i <= NF; i++) if ($i == "X" || $i == "Y" || $i == "Z") {
                             v = sprintf("%.0f", $(i + 1) * 1000); if (!seen[$i, v + 0]) { print $i, v; exit } } }' \
        "$work/pins.txt" "$work/progress.log")
  [ -z "$bad" ] || { echo "FAIL: progress shows $bad steps, never the pins' net"; exit 1; }
  echo "progress: $lines lines, every position shown is one the pins passed"
fi
echo "PASS: $(wc -l <"$work/pins.seq") pulses equal to the model's, position $read_back"
