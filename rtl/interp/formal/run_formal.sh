#!/usr/bin/env bash
# Formal check of interp_core (block prep, queue, datapath) at a small
# width with yosys' SAT solver: a bounded model check from reset of every
# move the host's validation accepts (interp_formal.v), the command held
# high. Every assertion of interp_formal.v and interp_dp.v (`ifdef FORMAL`)
# must hold in every clock.
#
#   run_formal.sh KIND [W] [DEPTH]
#     KIND  lines | arcs
#     W     coordinate width (default 3)
#     DEPTH clocks from reset (default: lines 2^(W+1) + 8, arcs 66)
#
# A move has at most 2 (2^W - 1) pulses (line) or 56 at W = 3 (arc,
# counted with the model), its first step comes 6 clocks after reset and
# nothing changes once it is done; so a depth above pulses + 7 covers every
# reachable state of every move at that width: a complete proof for the
# single-move harness, not for W = 24, arbitrary command gating or
# back-to-back moves (those are simulated).
set -euo pipefail
kind=${1:?lines or arcs}
w=${2:-3}
case "$kind" in
  lines) def=-DLINE_ONLY; depth=${3:-$(( (1 << (w + 1)) + 8 ))} ;;
  arcs) def=-DARC_ONLY; depth=${3:-66} ;;
  *) echo "run_formal.sh: KIND must be lines or arcs, not '$kind'" >&2; exit 2 ;;
esac
here=$(cd "$(dirname "$0")" && pwd)
core=$(cd "$here/.." && pwd)
srcs=$("$core/../filelist" "$core/interp.f" | tr '\n' ' ')
log=$(mktemp)
trap 'rm -f "$log"' EXIT
yosys -q -l "$log" -p "
  read_verilog -formal -DFORMAL $def -I$core $srcs $here/interp_formal.v
  chparam -set W $w interp_formal
  prep -top interp_formal
  memory_map
  opt -fast
  async2sync
  dffunmap
  flatten
  opt
  sat -seq $depth -prove-asserts -set-assumes -set-init-undef -set-def-inputs -show-inputs interp_formal" >/dev/null 2>&1 || true
if grep -q "SAT proof finished - no model found: SUCCESS" "$log"; then
  echo "formal: $kind at W = $w, $depth clocks from reset: every assertion holds"
  exit 0
fi
echo "formal: $kind at W = $w, $depth clocks: FAILED" >&2
grep -E "failed|FAIL|ERROR|Error|\\\\i_|assert" "$log" | head -40 >&2
exit 1
