#!/usr/bin/env bash
# The end-to-end test of the host link (ctest board_stream_*): `contour
# board-sim` on a pseudo-terminal, `contour stream PROGRAM --port` into it,
# as a user runs them. Checks, against `contour gcode PROGRAM --pulses`
# (the golden two-stage model):
#   - the board's STEP/DIR pins gave exactly the model's pulses, in order;
#   - the position the host read back equals the net of the model's pulses;
#   - stream exited 0.
# (stream gets --timeout 60: the simulated board runs ~10x slower than a
# real one, so a cut of 0.2 s on its wire lasts seconds of the host's time.)
# usage: stream_e2e.sh CONTOUR PROGRAM WORKDIR [board-sim options: faults]
set -euo pipefail
contour=$1 prog=$2 work=$3
shift 3
rm -rf "$work" && mkdir -p "$work"
"$contour" board-sim --pulses "$work/pins.txt" --port-file "$work/port" --max-time 60 "$@" >"$work/sim.log" &
sim=$!
trap 'kill $sim 2>/dev/null || true' EXIT
for _ in $(seq 200); do [ -s "$work/port" ] && break; sleep 0.05; done
[ -s "$work/port" ] || { echo "board-sim printed no port"; exit 1; }
rc=0
timeout 600 "$contour" stream "$prog" --port "$(cat "$work/port")" --quiet --timeout 60 >"$work/stream.log" 2>&1 || rc=$?
wait $sim
trap - EXIT
cat "$work/stream.log" "$work/sim.log"
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
echo "PASS: $(wc -l <"$work/pins.seq") pulses equal to the model's, position $read_back"
