#!/usr/bin/env bash
# `contour stream` to a port nobody answers on (ctest board_stream_noanswer):
# a pseudo-terminal held open by python3, never read or written; a port
# that does not exist; and a port where a python3 stand-in answers every
# frame with a REG refusal (its own SLIP and CRC-16/CCITT-FALSE, written
# here from the protocol's description in docs/board.md, not the host's
# code). Each: exit status 2, one line on stderr naming the port and what
# went wrong, within 10 s (--timeout 1: the host gives up after 1 s
# without a valid reply).
# usage: stream_noanswer.sh CONTOUR PROGRAM WORKDIR
set -euo pipefail
contour=$1 prog=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
python3 -c '
import os, pty, sys, time
m, s = pty.openpty()
open(sys.argv[1], "w").write(os.ttyname(s) + "\n")
time.sleep(60)' "$work/port" &
holder=$!
trap 'kill $holder 2>/dev/null || true' EXIT
for _ in $(seq 200); do [ -s "$work/port" ] && break; sleep 0.05; done
[ -s "$work/port" ] || { echo "no pty"; exit 1; }

expect_exit2() {  # expect_exit2 PORT WHAT: exit 2 and one stderr line naming PORT and saying WHAT
  local port=$1 what=$2 rc=0 t0 t1
  t0=$(date +%s.%N)
  timeout 30 "$contour" stream "$prog" --port "$port" --timeout 1 >"$work/out.log" 2>"$work/err.log" || rc=$?
  t1=$(date +%s.%N)
  echo "port $port: exit $rc after $(awk -v a="$t0" -v b="$t1" 'BEGIN {printf "%.2f", b - a}') s: $(cat "$work/err.log")"
  [ $rc -eq 2 ] || { echo "FAIL: exit $rc, not 2"; exit 1; }
  [ "$(wc -l <"$work/err.log")" -eq 1 ] || { echo "FAIL: not one line on stderr"; exit 1; }
  grep -qF "$port" "$work/err.log" || { echo "FAIL: the message does not name the port"; exit 1; }
  grep -q "$what" "$work/err.log" || { echo "FAIL: the message does not say '$what'"; exit 1; }
  awk -v a="$t0" -v b="$t1" 'BEGIN { exit !(b - a < 10) }' || { echo "FAIL: not within 10 s"; exit 1; }
}
expect_exit2 "$(cat "$work/port")" "does not answer"
expect_exit2 "$work/no-such-port" "cannot open"

python3 -c '
import os, pty, sys, tty
m, s = pty.openpty()
tty.setraw(s)
def crc16(b):
    c = 0xFFFF
    for x in b:
        c ^= x << 8
        for _ in range(8):
            c = ((c << 1) ^ 0x1021) & 0xFFFF if c & 0x8000 else (c << 1) & 0xFFFF
    return c
def slip(b):
    out = bytearray([0xC0])
    for x in b:
        out += {0xC0: b"\xdb\xdc", 0xDB: b"\xdb\xdd"}.get(x, bytes([x]))
    return bytes(out + b"\xc0")
open(sys.argv[1], "w").write(os.ttyname(s) + "\n")
frame = bytearray()
while True:
    for x in os.read(m, 256):
        if x != 0xC0:
            frame.append(x)
            continue
        if frame:  # seq, status REG, detail: byte 1, trailer of 16 bytes (next seq 0), CRC
            r = bytes([frame[0], 3, 1]) + bytes(16)
            os.write(m, slip(r + crc16(r).to_bytes(2, "big")))
        frame = bytearray()' "$work/port-reg" &
board=$!
trap 'kill $holder $board 2>/dev/null || true' EXIT
for _ in $(seq 200); do [ -s "$work/port-reg" ] && break; sleep 0.05; done
[ -s "$work/port-reg" ] || { echo "no pty"; exit 1; }
expect_exit2 "$(cat "$work/port-reg")" "refused frame 0: REG at byte 1"
echo "PASS"
