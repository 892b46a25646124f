#!/usr/bin/env bash
# Formal proof of interp3_core (its `ifdef FORMAL properties) by temporal
# induction with yosys's SAT solver (`sat -tempinduct`, 1-induction: the
# properties hold in the clock after reset and every state satisfying them
# steps to one that does, for every input: any move, any command sequence,
# loads and resets at any time).
#
#   prove.sh OUTDIR [W...]     default widths: 2 3
#   Z3_WIDTHS="4" prove.sh ...  also prove these widths with yosys-smtbmc
#                               and z3 (base case + 1-induction); W = 4
#                               takes ~4 min of CPU (10 min on a loaded
#                               machine), so it is not in the default run.
#   PDR_WIDTHS="3 4" prove.sh ... also prove these widths unbounded with
#                               ABC's pdr (IC3) on an AIGER model of the
#                               core (its outputs demoted to wires, so
#                               that only the assertions are bad states);
#                               W = 3 takes ~1 min of CPU.
#
# Then the proof is checked to be able to fail: each mutant of the core
# (one deliberate bug, below) must be refuted at W = 2 by a counterexample
# from reset (yosys: "model found for base case").
#
# At W = 4 yosys's SAT solver does not finish the induction step (it has
# to multiply out the discriminant identities); z3 does (Z3_WIDTHS).
set -euo pipefail
out=${1:?output directory}
shift
widths=${*:-2 3}
here=$(cd "$(dirname "$0")" && pwd)
# The core's sources from its file list (one file: interp3_core.v, the
# one the mutants below change).
core=$("$here/../../filelist" "$here/../interp3.f")
[ "$(echo "$core" | wc -l)" -eq 1 ] || { echo "prove.sh: interp3.f must list one file" >&2; exit 2; }
mkdir -p "$out"

# MAXSTEPS bounds the search: the proof itself closes at induction length
# 1; a mutant's counterexample from reset needs the reset, the load, its
# three preparation clocks and a few steps.
prove() {  # prove FILE W LOG [MAXSTEPS] -> status of yosys
  yosys -q -l "$3" -p "
    read_verilog -formal $1
    chparam -set W $2 interp3_core
    prep -top interp3_core
    async2sync
    dffunmap
    sat -tempinduct -prove-asserts -set-assumes -seq 1 -maxsteps ${4:-4}" > /dev/null 2>&1
}

fails=0
for w in $widths; do
  t0=$(date +%s)
  if prove "$core" "$w" "$out/prove_w$w.log" && grep -q "Induction step proven: SUCCESS" "$out/prove_w$w.log"; then
    echo "interp3_formal: W = $w proved by 1-induction ($(( $(date +%s) - t0 )) s)"
  else
    echo "interp3_formal: W = $w FAILED (see $out/prove_w$w.log)"
    fails=$((fails + 1))
  fi
done

for w in ${Z3_WIDTHS:-}; do
  t0=$(date +%s)
  yosys -q -p "
    read_verilog -formal $core
    chparam -set W $w interp3_core
    prep -top interp3_core
    async2sync
    dffunmap
    write_smt2 -wires $out/interp3_w$w.smt2"
  if yosys-smtbmc -s z3 -t 2 "$out/interp3_w$w.smt2" > "$out/z3_base_w$w.log" 2>&1 &&
     yosys-smtbmc -s z3 -i -t 1 "$out/interp3_w$w.smt2" > "$out/z3_induct_w$w.log" 2>&1; then
    echo "interp3_formal: W = $w proved by 1-induction with z3 ($(( $(date +%s) - t0 )) s)"
  else
    echo "interp3_formal: W = $w FAILED with z3 (see $out/z3_*_w$w.log)"
    fails=$((fails + 1))
  fi
done

for w in ${PDR_WIDTHS:-}; do
  t0=$(date +%s)
  yosys -q -l "$out/aig_w$w.log" -p "
    read_verilog -formal $core
    chparam -set W $w interp3_core
    prep -top interp3_core
    delete -output o:*
    flatten
    script $here/../../to_aiger.ys
    write_aiger -zinit $out/interp3_w$w.aig" > /dev/null 2>&1
  (ulimit -v 6000000; timeout "${PDR_TIMEOUT:-3600}" yosys-abc -c "read_aiger $out/interp3_w$w.aig; fold; orpos; pdr") \
    > "$out/pdr_w$w.log" 2>&1 || true
  if grep -q "Property proved" "$out/pdr_w$w.log"; then
    echo "interp3_formal: W = $w proved unbounded by pdr ($(( $(date +%s) - t0 )) s)"
  else
    echo "interp3_formal: W = $w NOT proved by pdr (see $out/pdr_w$w.log)"
    fails=$((fails + 1))
  fi
done

# Mutants: "description|sed expression". Each must make the proof fail.
mutants=(
  "initial Exy rounded with the low bit of C instead of B|s/cixy_q <= ~i_load | i_xe\[0\] | ~i_ye\[0\];/cixy_q <= ~i_load | i_xe[0] | ~i_ze[0];/"
  "X step leaves Exz unchanged|s/wire kxz1 = sx \& ~(gxy1 \& ~gyz0) \& ~fx_q;/wire kxz1 = 1'b0;/"
  "distance-left flag of X cleared one step late|s/rx_q <= ~lx_q;/rx_q <= x_q != a_q;/"
  "selection of Y after an X step ignores the sign of Eyz|s/(sx \& gxy1 \& ~gyz0)/(sx \& gxy1)/"
  "Y update of Exy adds 2B instead of 2A|s/o1xy = onb_q, o2xy = oa_q;/o1xy = onb_q, o2xy = ob_q;/"
  "split adder drops the pending carry of the low part|s/hi = d\[DW-1:K+1\] + o\[HW-1:K\] + {{(HW - K - 1) {1'b0}}, d\[K\]};/hi = d[DW-1:K+1] + o[HW-1:K];/"
  "preparation: d11 of Exy takes op1 after L1 too|s/(gxy_q \& ~p2_q) ? sxy1 : sxy2;/gxy_q ? sxy1 : sxy2;/"
)
n=0
for m in "${mutants[@]}"; do
  n=$((n + 1))
  desc=${m%%|*}
  expr=${m#*|}
  sed "$expr" "$core" > "$out/mutant$n.v"
  if cmp -s "$core" "$out/mutant$n.v"; then
    echo "interp3_formal: mutant $n ($desc) did not apply to the source"
    fails=$((fails + 1))
  elif prove "$out/mutant$n.v" 2 "$out/mutant$n.log" 12 && grep -q "model found for base case: FAIL" "$out/mutant$n.log"; then
    echo "interp3_formal: mutant $n ($desc) refuted from reset"
  else
    echo "interp3_formal: mutant $n ($desc) was NOT refuted (see $out/mutant$n.log)"
    fails=$((fails + 1))
  fi
done
exit $((fails > 0))
