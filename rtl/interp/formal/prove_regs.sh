#!/usr/bin/env bash
# Formal proof of wb_regs' `ifdef FORMAL properties (the Wishbone slave of
# interp_top: ACK two clocks after the access starts and only then, the
# read word of the clock before ACK, a write landing once with the
# access's data, PUSH / REJECT / ABORT / CLEAR only from their writes,
# the staged block's unused fields zero: a line's CI, CO, Q, K, an arc's
# SXN, SYN),
# for any master that keeps to Wishbone B4 classic and any status inputs.
# wb_regs is flattened to an AIGER model by yosys (W = 3, QAW = 2, TW = 2:
# the widths change no control) and proved unbounded by ABC's PDR.
#
#   prove_regs.sh OUTDIR
#
# Then each mutant (one deliberate bug, below, a sed on a copy of
# wb_regs.v) must be refuted: ABC reports a reachable assertion failure.
# Exit status 0 when the proof holds and every mutant is refuted.
# Cost: about a second of CPU per run; 4 GB and 300 s at most each.
set -euo pipefail
out=${1:?output directory}
here=$(cd "$(dirname "$0")" && pwd)
src=$(cd "$here/.." && pwd)
mkdir -p "$out"
ulimit -v 4000000

# aig NAME FILE: FILE (wb_regs.v or a mutant of it) to $out/NAME.aig, its
# outputs demoted to wires (the assertions are the bad states).
aig() {
  timeout 300 yosys -q -l "$out/$1.yosys.log" -p "
    read_verilog -formal -I$src $2
    chparam -set W 3 -set QAW 2 -set TW 2 wb_regs
    prep -top wb_regs
    flatten
    delete -output wb_regs/o:*
    script $src/../to_aiger.ys
    write_aiger -zinit -map $out/$1.map $out/$1.aig" > /dev/null 2>&1
}
pdr() {  # pdr NAME -> proved / failed / unknown
  timeout 300 yosys-abc -c "read_aiger $out/$1.aig; fold; orpos; pdr" > "$out/$1.abc.log" 2>&1 || true
  if grep -q "Property proved" "$out/$1.abc.log"; then echo proved
  elif grep -q "was asserted in frame" "$out/$1.abc.log"; then echo failed
  else echo unknown
  fi
}

fails=0
t0=$(date +%s)
if ! aig regs "$src/wb_regs.v"; then
  echo "interp_regs_formal: yosys FAILED (see $out/regs.yosys.log)"
  fails=$((fails + 1))
else
  r=$(pdr regs)
  if [ "$r" = proved ]; then
    echo "interp_regs_formal: wb_regs properties proved by PDR ($(( $(date +%s) - t0 )) s)"
  else
    echo "interp_regs_formal: wb_regs properties $r (see $out/regs.abc.log)"
    fails=$((fails + 1))
  fi
fi

# Mutants: "description|sed expression". Each must make the proof fail.
mutants=(
  "ACK one clock after the strobe|s/o_wb_ack <= st1_q;/o_wb_ack <= acc;/"
  "an access started again in its ACK clock|s/wire acc = i_wb_cyc \& i_wb_stb \& ~st1_q \& ~o_wb_ack;/wire acc = i_wb_cyc \& i_wb_stb \& ~st1_q;/"
  "a write repeated while STB is held|s/wr1_q <= acc \& i_wb_we;/wr1_q <= i_wb_cyc \& i_wb_stb \& i_wb_we;/"
  "a write lands in the ACK clock (the master may have moved on)|s/wire \[NWS-1:0\] wsel = {NWS{wr1_q}} \&/wire [NWS-1:0] wsel = {NWS{o_wb_ack \& i_wb_we}} \&/"
  "a PUSH into a full queue|s/o_push <= wsel\[S_PUSH\] \& ~i_full;/o_push <= wsel[S_PUSH];/"
  "DAT_O loaded as the access starts (the selects of the clock before)|s/always @(posedge i_clk) o_wb_dat <= rdata;/always @(posedge i_clk) if (acc) o_wb_dat <= rdata;/"
  "a line's staged CI not zeroed|s/assign o_blk\[BLK_CI +: W\] = arc_q ? ci_q : {W{1'b0}};/assign o_blk[BLK_CI +: W] = ci_q;/"
  "an arc's SXN kept|s/mode_used\[BLK_MODE_SXN\] = ~arc;/mode_used[BLK_MODE_SXN] = 1'b1;/"
)
n=0
for m in "${mutants[@]}"; do
  n=$((n + 1))
  desc=${m%%|*}
  expr=${m#*|}
  f="$out/mutant$n.v"
  sed "$expr" "$src/wb_regs.v" > "$f"
  if cmp -s "$f" "$src/wb_regs.v"; then
    echo "interp_regs_formal: mutant $n ($desc) did not apply"
    fails=$((fails + 1))
    continue
  fi
  if ! aig "mutant$n" "$f"; then
    echo "interp_regs_formal: mutant $n ($desc): yosys FAILED (see $out/mutant$n.yosys.log)"
    fails=$((fails + 1))
    continue
  fi
  r=$(pdr "mutant$n")
  if [ "$r" = failed ]; then
    echo "interp_regs_formal: mutant $n ($desc) refuted"
  else
    echo "interp_regs_formal: mutant $n ($desc) NOT refuted ($r)"
    fails=$((fails + 1))
  fi
done
exit $((fails > 0))
