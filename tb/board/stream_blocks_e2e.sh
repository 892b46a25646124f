#!/usr/bin/env bash
# The end-to-end test of paper A mode (ctest board_stream_hw_arcs*):
# `contour board-sim` on a pseudo-terminal, `contour stream PROGRAM --port
# --hw-arcs` into it, as a user runs them. Checks:
#   - the board's STEP/DIR pins gave exactly the paper A model's pulses of
#     each block the host sent (`contour line|arc ... --format steps`, the
#     golden model, for every line of the host's --blocks file), in order;
#   - the position the host read back equals the net of the pins' pulses;
#   - it equals the net of `contour gcode PROGRAM --pulses` (paper B's
#     rounding of the program's end point to the grid, which the host's
#     conversion does not use): the program ends where the G-code says;
#   - stream exited 0.
# usage: stream_blocks_e2e.sh CONTOUR PROGRAM WORKDIR [board-sim options: faults]
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
timeout 600 "$contour" stream "$prog" --port "$(cat "$work/port")" --hw-arcs --blocks "$work/blocks.txt" --quiet \
  --timeout 60 >"$work/stream.log" 2>&1 || rc=$?
wait $sim
trap - EXIT
cat "$work/stream.log" "$work/sim.log"
[ $rc -eq 0 ] || { echo "FAIL: contour stream exited $rc"; exit 1; }
: >"$work/model.seq"
while read -r line; do
  args=${line%%#*}
  # shellcheck disable=SC2086  # the block's arguments, split
  "$contour" $args --format steps | tr ' ' '\n' | sed '/^$/d' >>"$work/model.seq"
done <"$work/blocks.txt"
awk '{print $2}' "$work/pins.txt" >"$work/pins.seq"
if ! cmp -s "$work/pins.seq" "$work/model.seq"; then
  echo "FAIL: the pins differ from the paper A model: $(wc -l <"$work/pins.seq") pulses vs $(wc -l <"$work/model.seq")"
  diff "$work/pins.seq" "$work/model.seq" | head -5
  exit 1
fi
net() { awk '{s=substr($2,1,1)=="-"?-1:1; a=substr($2,2,1); n[a]+=s} END {printf "%d %d %d", n["X"], n["Y"], n["Z"]}' "$1"; }
pins=$(net "$work/pins.txt")
read_back=$(sed -n 's/^stream: position \([-0-9]*\) \([-0-9]*\) \([-0-9]*\) steps.*/\1 \2 \3/p' "$work/stream.log")
[ "$pins" = "$read_back" ] || { echo "FAIL: position read back '$read_back', the pins' net '$pins'"; exit 1; }
"$contour" gcode "$prog" --pulses >"$work/gcode.txt"
program=$(net "$work/gcode.txt")
[ "$program" = "$read_back" ] || { echo "FAIL: position read back '$read_back', the program's end '$program'"; exit 1; }
echo "PASS: $(wc -l <"$work/pins.seq") pulses of $(wc -l <"$work/blocks.txt") blocks equal to the paper A model's, position $read_back"
