#!/usr/bin/env bash
# Formal proof of the 8085 CPU's `ifdef FORMAL properties (cpu8085.v,
# cpu8085_decode.vh; docs/cpu8085.md, "Formal"):
#   - the decoder's classes are one-hot for every opcode (proved on the
#     decode function alone by yosys `sat`, all 256 opcodes; in the CPU,
#     the registered classes are the decode of the instruction register),
#   - the sequencer stays in range (T1..T6, at most 5 cycles, later cycles
#     of 3 T at most, idle units one cycle),
#   - at most one bus strobe (o_rd o_wr o_inta) at a time,
#   - every unit ends after the data sheet's T-states: an instruction by its
#     class (MOV r,r 4, MVI r 7, LXI 10, CALL 18, Jcc 7 / 10, ...), a TRAP /
#     RST x.5 acknowledge 12, an idle unit 1,
# from reset, for any pins, bus data and debug loads at unit boundaries.
# The CPU is flattened to an AIGER model by yosys and proved unbounded by
# ABC's PDR (IC3): `read_aiger; fold; orpos; pdr` (fold turns the
# assumptions into the property, orpos makes all asserts one output).
#
#   prove.sh OUTDIR            the proof, then the mutants
#   prove.sh OUTDIR proof      the proof only
#   prove.sh OUTDIR mutants    the mutants only
#
# Each mutant (one deliberate bug, below, a sed on a copy of the source)
# must be refuted: ABC reports a reachable assertion failure. Exit status 0
# when everything is proved and every mutant refuted.
#
# Cost: a few seconds of CPU per run (yosys ~4 s, PDR ~2 s); the solver is
# limited to 4 GB of memory and 300 s per run.
set -euo pipefail
out=${1:?output directory}
what=${2:-all}
here=$(cd "$(dirname "$0")" && pwd)
src=$(cd "$here/.." && pwd)
# The CPU's sources, from its one file list.
sources=$("$src/../filelist" "$src/cpu8085.f" | tr '\n' ' ')
incdirs=$("$src/../filelist" --incdirs "$src/cpu8085.f" | sed 's/^/-I/' | tr '\n' ' ')
mkdir -p "$out"
ulimit -v 4000000

# aig NAME [FILE MUTANT]: flatten the CPU to $out/NAME.aig (no outputs:
# the assertions are the AIGER bad states, the assumptions its constraints),
# with the source FILE of the list replaced by MUTANT if given (an included
# .vh file: a copy of cpu8085.v next to copies of the includes, MUTANT as
# FILE, since an include is looked for first next to the file that has it).
aig() {
  local srcs=$sources
  if [ $# -ge 3 ]; then
    case "$2" in
      *.vh)
        mkdir -p "$out/$1.inc"
        cp "$src"/*.vh "$src/cpu8085.v" "$out/$1.inc/"
        cp "$3" "$out/$1.inc/$2"
        srcs=${srcs/$src\/cpu8085.v/$out/$1.inc/cpu8085.v} ;;
      *) srcs=${srcs/$src\/$2/$3} ;;
    esac
  fi
  timeout 300 yosys -q -l "$out/$1.yosys.log" -p "
    read_verilog -formal $incdirs $srcs
    prep -top cpu8085
    flatten
    delete -output cpu8085/o:*
    script $src/../to_aiger.ys
    write_aiger -zinit -map $out/$1.map $out/$1.aig" > /dev/null 2>&1
}

# pdr NAME: ABC's PDR on $out/NAME.aig; prints proved / failed / unknown.
pdr() {
  timeout 300 yosys-abc -c "read_aiger $out/$1.aig; fold; orpos; pdr" \
    > "$out/$1.abc.log" 2>&1 || true
  if grep -q "Property proved" "$out/$1.abc.log"; then echo proved
  elif grep -q "was asserted in frame" "$out/$1.abc.log"; then echo failed
  else echo unknown
  fi
}

# decoder NAME: the decode function alone (a module around it that
# asserts its classes one-hot and decode_of equal to decode_all's of6,
# of_only and Rcc), all opcodes, by yosys sat.
decoder() {
  cat > "$out/$1.v" <<'EOF'
module decode_onehot (input wire [7:0] i_ir);
`include "cpu8085_decode.vh"
  wire [42:0] all = decode_all(i_ir);
  wire [38:0] cls = all[42:4];
  // decode_of's bit patterns: decode_all's of6, of_only and Rcc (bit 20).
  wire [2:0] of_bits = decode_of(i_ir);
  always @* begin
    assert (cls != 39'd0);
    assert ((cls & (cls - 39'd1)) == 39'd0);
    assert (of_bits == {all[3], all[2], all[20]});
  end
endmodule
EOF
  timeout 300 yosys -q -l "$out/$1.yosys.log" -p "
    read_verilog -formal $incdirs $out/$1.v
    prep -top decode_onehot
    sat -prove-asserts -verify" > /dev/null 2>&1
}

fails=0
if [ "$what" = all ] || [ "$what" = proof ]; then
  t0=$(date +%s)
  if decoder decoder; then
    echo "cpu8085_formal: decoder classes one-hot, decode_of = decode_all, for all 256 opcodes ($(( $(date +%s) - t0 )) s)"
  else
    echo "cpu8085_formal: decoder FAILED (see $out/decoder.yosys.log)"
    fails=$((fails + 1))
  fi
  t0=$(date +%s)
  if ! aig cpu; then
    echo "cpu8085_formal: yosys FAILED (see $out/cpu.yosys.log)"
    fails=$((fails + 1))
  else
    r=$(pdr cpu)
    if [ "$r" = proved ]; then
      echo "cpu8085_formal: CPU properties proved by PDR ($(( $(date +%s) - t0 )) s)"
    else
      echo "cpu8085_formal: CPU properties $r (see $out/cpu.abc.log)"
      fails=$((fails + 1))
    fi
  fi
fi

# Mutants: "file|description|sed expression". Each must make the proof fail.
mutants=(
  "cpu8085_decode.vh|PUSH fetched in 4 T instead of 6|s/(f_sss == 3'd7) | (low == 4'b0101))) |/(f_sss == 3'd7))) |/"
  "cpu8085_decode.vh|MVI r also matches MVI M (classes overlap)|s/dc_mvi_r = g0 \& sss_m \& ~ddd_m;/dc_mvi_r = g0 \& sss_m;/"
  "cpu8085.v|LXI ends after its first operand byte|s/C_LXI: last = at_2;/C_LXI: last = at_1;/"
  "cpu8085.v|Jcc not taken reads the high address byte too|s/C_JCC: last = at_2 || !cond_ir(o_dbg_op\[5:3\]);/C_JCC: last = at_2;/"
  "cpu8085.v|XTHL runs one cycle too many|s/last = at_4;  \/\/ XTHL/last = (mc == 3'd5);  \/\/ XTHL/"
  "cpu8085.v|write strobe also in memory reads|s/o_wr <= (o_cycle == CY_MW/o_wr <= (o_cycle == CY_MR || o_cycle == CY_MW/"
)
if [ "$what" = all ] || [ "$what" = mutants ]; then
  n=0
  for m in "${mutants[@]}"; do
    n=$((n + 1))
    file=${m%%|*}
    rest=${m#*|}
    desc=${rest%%|*}
    expr=${rest#*|}
    sed "$expr" "$src/$file" > "$out/mutant$n.v"
    if cmp -s "$src/$file" "$out/mutant$n.v"; then
      echo "cpu8085_formal: mutant $n ($desc) did not apply to the source"
      fails=$((fails + 1))
      continue
    fi
    r=unknown
    aig "mutant$n" "$file" "$out/mutant$n.v" && r=$(pdr "mutant$n")
    if [ "$r" = failed ]; then
      echo "cpu8085_formal: mutant $n ($desc) refuted: $(grep -o 'asserted in frame [0-9]*' "$out/mutant$n.abc.log")"
    else
      echo "cpu8085_formal: mutant $n ($desc) was NOT refuted: $r (see $out/mutant$n.abc.log)"
      fails=$((fails + 1))
    fi
  done
fi
exit $((fails > 0))
