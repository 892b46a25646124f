#!/usr/bin/env bash
# Gate-level simulation of one core: yosys synthesizes it for iCE40 at
# width W (synth_ice40, the flow of rtl/synth), the netlist is renamed
# <core>_gate and simulated under Icarus with yosys' iCE40 cell models
# (cells_sim.v) beside the RTL, every output compared on every clock
# (tb/gate/<core>_gate_tb.v). Everything generated stays in WORK.
#
#   gate_sim.sh interp  W all    WORK GATE_MOVES                 every accepted move (W = 3)
#   gate_sim.sh interp  W random WORK GATE_MOVES CLOCKS SEED     random blocks, aborts, resets (W = 24)
#   gate_sim.sh interp3 W MODE   WORK - [CLOCKS SEED]            MODE all (every move at W <= 3) | random
#
# GATE_MOVES is the block writer (tb/gate/gate_moves.cpp). Environment:
# GATE_NETLIST=FILE simulates FILE instead of synthesizing (a netlist
# edited by hand, to see the check fail). Exit 0 and "PASS ..." when the
# netlist matches the RTL; exit 1 and the first differing clock otherwise.
set -euo pipefail
core=${1:?core: interp or interp3}
w=${2:?W}
mode=${3:?mode: all or random}
work=${4:?work dir}
moves_tool=${5:?gate_moves (or - for interp3)}
clocks=${6:-20000}
seed=${7:-1}
here=$(cd "$(dirname "$0")" && pwd)
rtl=$(cd "$here/../../rtl" && pwd)
case "$core" in
  interp) list=$rtl/interp/interp.f; top=interp_core ;;
  interp3) list=$rtl/interp3/interp3.f; top=interp3_core ;;
  *) echo "gate_sim.sh: core must be interp or interp3, not '$core'" >&2; exit 2 ;;
esac
for tool in yosys iverilog vvp; do
  command -v $tool >/dev/null || { echo "gate_sim.sh: $tool not found (make deps)" >&2; exit 2; }
done
cells=$(dirname "$(command -v yosys)")/../share/yosys/ice40/cells_sim.v
[ -f "$cells" ] || cells=$(yosys-config --datdir 2>/dev/null)/ice40/cells_sim.v
[ -f "$cells" ] || { echo "gate_sim.sh: yosys' ice40/cells_sim.v not found" >&2; exit 2; }

mkdir -p "$work"
tag=${core}_w${w}_${mode}
mapfile -t srcs < <("$rtl/filelist" "$list")
incs="-I$here $("$rtl/filelist" --incdirs "$list" | sed 's/^/-I/' | tr '\n' ' ')"

# 1. The netlist.
netlist=${GATE_NETLIST:-$work/${core}_w${w}_gate.v}
if [ -z "${GATE_NETLIST:-}" ]; then
  yosys -q -l "$work/${core}_w${w}_synth.log" -p "
    read_verilog $incs ${srcs[*]}
    chparam -set W $w $top
    synth_ice40 -top $top
    rename $top ${top}_gate
    tee -o $work/${core}_w${w}_stat.txt stat
    write_verilog -noattr $netlist" >/dev/null
fi

# 2. The stimulus.
args=(+mode=$mode +clocks=$clocks +seed=$seed)
if [ "$core" = interp ]; then
  memh=$work/${tag}.memh
  if [ "$mode" = all ]; then
    "$moves_tool" all "$w" "$memh"
  else
    "$moves_tool" random "$w" 300 "$seed" "$memh"
  fi
  args+=(+moves=$memh +n=$(wc -l <"$memh"))
fi

# 3. RTL and netlist side by side under Icarus.
iverilog -g2012 -o "$work/$tag.vvp" -P${core}_gate_tb.W=$w -DNO_ICE40_DEFAULT_ASSIGNMENTS $incs \
  "$cells" "$netlist" "${srcs[@]}" "$here/${core}_gate_tb.v" 2>"$work/$tag.iverilog.log" || {
  cat "$work/$tag.iverilog.log" >&2; exit 1; }
out=$(vvp -n "$work/$tag.vvp" "${args[@]}" 2>&1) || true
echo "$out"
if grep -q "^PASS ${core}_gate_tb" <<<"$out" && ! grep -q FAIL <<<"$out"; then
  exit 0
fi
exit 1
