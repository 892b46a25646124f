#!/usr/bin/env bash
# Ctrl-C in `contour stream` (ctest board_stream_sigint): board-sim on a
# pty, stream PROGRAM into it with --progress (forced: stderr is a file),
# SIGINT once the progress line shows AFTER chords sent. Checks:
#   - stream exits 130 and says it was stopped;
#   - the pins' pulses are a prefix (shorter) of the model's
#     (`contour gcode --pulses`): nothing lost, doubled or half given;
#   - the position read back equals the pins' net;
#   - the board came to rest along a ramp: the time scale (the model's time
#     per board time over the pins' pulses) is about 1 60 ms before the last
#     pulse, about 0.5 25 ms before, near 0 in the last 2 ms (the hold's
#     linear ramp of 65536 x 9 clocks = 49 ms), never a jump to rest.
# usage: stream_sigint.sh CONTOUR PROGRAM WORKDIR AFTER
set -euo pipefail
contour=$1 prog=$2 work=$3 after=$4
rm -rf "$work" && mkdir -p "$work"
"$contour" board-sim --pulses "$work/pins.txt" --port-file "$work/port" --max-time 60 >"$work/sim.log" &
sim=$!
trap 'kill $sim 2>/dev/null || true; [ -z "${host:-}" ] || kill $host 2>/dev/null || true' EXIT
for _ in $(seq 200); do [ -s "$work/port" ] && break; sleep 0.05; done
[ -s "$work/port" ] || { echo "board-sim printed no port"; exit 1; }
: >"$work/progress.log"  # the loop below may read it before the background stream opens it
"$contour" stream "$prog" --port "$(cat "$work/port")" --progress --timeout 60 >"$work/stream.log" 2>"$work/progress.log" &
host=$!
sent=0
for _ in $(seq 6000); do  # up to 600 s
  sent=$(sed -n 's/.*\] *[0-9]*% \([0-9]*\)\/.*/\1/p' "$work/progress.log" | tail -1)
  [ "${sent:-0}" -ge "$after" ] && break
  kill -0 $host 2>/dev/null || break
  sleep 0.1
done
[ "${sent:-0}" -ge "$after" ] || { echo "FAIL: the progress line never showed $after chords sent"; cat "$work/progress.log"; exit 1; }
kill -INT $host
rc=0
wait $host || rc=$?
host=
wait $sim
trap - EXIT
cat "$work/stream.log" "$work/sim.log"
[ $rc -eq 130 ] || { echo "FAIL: contour stream exited $rc after SIGINT, not 130"; tail -3 "$work/progress.log"; exit 1; }
grep -q "STOPPED by Ctrl-C" "$work/stream.log" || { echo "FAIL: stream did not say it was stopped"; exit 1; }
"$contour" gcode "$prog" --pulses >"$work/model.txt"
n=$(wc -l <"$work/pins.txt")
m=$(wc -l <"$work/model.txt")
[ "$n" -gt 0 ] && [ "$n" -lt "$m" ] || { echo "FAIL: $n pulses on the pins, the model has $m: not a stop mid-program"; exit 1; }
if ! cmp -s <(awk '{print $2}' "$work/pins.txt") <(head -n "$n" "$work/model.txt" | awk '{print $2}'); then
  echo "FAIL: the pins' $n pulses are not the model's first $n"
  exit 1
fi
net=$(awk '{s=substr($2,1,1)=="-"?-1:1; a=substr($2,2,1); n[a]+=s} END {printf "%d %d %d", n["X"], n["Y"], n["Z"]}' "$work/pins.txt")
read_back=$(sed -n 's/^stream: position \([-0-9]*\) \([-0-9]*\) \([-0-9]*\) steps.*/\1 \2 \3/p' "$work/stream.log")
[ "$net" = "$read_back" ] || { echo "FAIL: position read back '$read_back', the pins' net '$net'"; exit 1; }
# The time scale over the board's window [end - a, end - b] (ms before the last pulse).
scale() {
  paste -d' ' <(awk '{print $1}' "$work/pins.txt") <(head -n "$n" "$work/model.txt" | awk '{print $1}') |
    awk -v a="$1" -v b="$2" -v end="$(tail -1 "$work/pins.txt" | awk '{print $1}')" '
      { t = $1; if (t >= end - a / 1000 && t <= end - b / 1000) { if (!k++) { t0 = t; m0 = $2 } t1 = t; m1 = $2 } }
      END { if (k < 2 || t1 == t0) print 0; else printf "%.3f", (m1 - m0) / (t1 - t0) }'
}
full=$(scale 62 60) half=$(scale 26 24) last=$(scale 2 0)
echo "time scale before the rest: $full (60 ms), $half (25 ms), $last (last 2 ms)"
awk -v f="$full" -v h="$half" -v l="$last" 'BEGIN { exit !(f > 0.9 && h > 0.35 && h < 0.65 && l < 0.15) }' ||
  { echo "FAIL: not a ramp to rest"; exit 1; }
echo "PASS: stopped after $n of $m pulses, exit 130, position $read_back, ramp $full / $half / $last"
