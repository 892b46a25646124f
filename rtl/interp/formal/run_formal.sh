#!/usr/bin/env bash
# Formal check of interp_core (block prep, queue, datapath) at a small
# width W: one move, chosen by the solver among every move the host's
# validation accepts (interp_formal.v), is pushed after reset and run with
# the command held high. Every assertion of interp_formal.v (the step-rule
# reference of docs/algorithm.md in lock step with the core, the pulse
# count, the end point) and of interp_dp.v (`ifdef FORMAL`) must hold.
#
# Flow: yosys flattens the harness to an AIGER model (assertions = bad
# states, assumptions = constraints), ABC checks it (`fold` folds the
# constraints into the property):
#   bmc3 -F DEPTH  bounded model check from reset to DEPTH clocks; with
#                  DEPTH >= the longest move's pulses + 7 (the first pulse
#                  comes 6 clocks after reset, nothing changes once the
#                  move is done) every reachable state of the one-move
#                  harness is covered: complete for that harness.
#   pdr            unbounded (IC3).
#
#   run_formal.sh OUTDIR [JOB...]
#     lines:W[:DEPTH]    every accepted line at width W, bmc3
#                        (default depth 2^(W+1) + 8)
#     arcs:W[:DEPTH]     every accepted arc at width W, bmc3
#                        (default depth: 66 at W = 3, 140 at W = 4)
#     lines-pdr:W        every accepted line at width W, pdr (unbounded)
#     covers:W           every cover of interp_formal.v must be reached
#                        (bmc3 -a on the cover model, W = 3, 66 clocks)
#     mutants:W          every mutant below must be refuted (W = 3)
#   default jobs: lines:3 lines:4 arcs:3 covers:3 mutants:3
#
# Exit status 0 only when every proof holds, every cover is reached and
# every mutant refuted. Each solver run: 4 GB of memory, TIMEOUT seconds of
# CPU (default 2400: arcs:3:66 took 611-846 s of CPU after D was split in
# two halves) and three times that of wall time, so that a loaded machine
# (arcs:3:66: 1842 s of wall time for 611 s of CPU) does not cut a proof.
set -euo pipefail
out=${1:?output directory}
shift
jobs=${*:-lines:3 lines:4 arcs:3 covers:3 mutants:3}
here=$(cd "$(dirname "$0")" && pwd)
core=$(cd "$here/.." && pwd)
# The core's sources, from its one file list.
sources=$("$core/../filelist" "$core/interp.f" | tr '\n' ' ')
mkdir -p "$out"
ulimit -v 4000000
cpu=${TIMEOUT:-2400}
ulimit -t "$cpu"
tmo=$((3 * cpu))

# aig NAME W DEFINES [FILE MUTANT]: the harness at width W flattened to
# $out/NAME.aig, with the source FILE (relative to rtl/interp) replaced by
# MUTANT if given.
aig() {
  local srcs=$sources extra=
  case "$3" in *-DCOVER*) extra="chformal -assert -remove" ;; esac
  [ $# -lt 5 ] || srcs=${srcs/$core\/$4/$5}
  timeout "$tmo" yosys -q -l "$out/$1.yosys.log" -p "
    read_verilog -formal -DFORMAL $3 -I$core $srcs $here/interp_formal.v
    chparam -set W $2 interp_formal
    prep -top interp_formal
    $extra
    flatten
    script $core/../to_aiger.ys
    write_aiger -zinit -map $out/$1.map $out/$1.aig" > /dev/null 2>&1
}

# abc NAME COMMAND: ABC on $out/NAME.aig; prints proved / failed / unknown.
abc() {
  timeout "$tmo" yosys-abc -c "read_aiger $out/$1.aig; fold; orpos; $2" \
    > "$out/$1.abc.log" 2>&1 || true
  if grep -q "Property proved" "$out/$1.abc.log"; then echo proved
  elif grep -q "No output asserted in" "$out/$1.abc.log"; then echo held
  elif grep -q "was asserted in frame" "$out/$1.abc.log"; then echo failed
  else echo unknown
  fi
}

cpu() { grep -o 'Time = *[0-9.]* sec' "$out/$1.abc.log" | tail -1 | tr -s ' '; }

fails=0
fail() { echo "interp_formal: $*"; fails=$((fails + 1)); }

# prove KIND W DEPTH|pdr
prove() {
  local kind=$1 w=$2 how=$3 def name t0 r
  case "$kind" in lines) def=-DLINE_ONLY ;; arcs) def="-DARC_ONLY -DFORMAL_REF_ONLY" ;; esac
  name=${kind}_w$w
  t0=$(date +%s)
  if ! aig "$name" "$w" "$def"; then fail "$kind at W = $w: yosys FAILED (see $out/$name.yosys.log)"; return; fi
  if [ "$how" = pdr ]; then
    r=$(abc "$name" "pdr")
    if [ "$r" = proved ]; then
      echo "interp_formal: every $kind at W = $w proved unbounded by pdr ($(cpu "$name"), $(( $(date +%s) - t0 )) s in all)"
    else fail "$kind at W = $w: pdr $r (see $out/$name.abc.log)"; fi
  else
    r=$(abc "$name" "bmc3 -F $how")
    if [ "$r" = held ]; then
      echo "interp_formal: every $kind at W = $w holds to $how clocks by bmc3 ($(cpu "$name"), $(( $(date +%s) - t0 )) s in all)"
    else fail "$kind at W = $w, bmc3 -F $how: $r (see $out/$name.abc.log)"; fi
  fi
}

# The covers of interp_formal.v (`ifdef COVER), output bit by bit.
covers=(
  "line step into the third quadrant (SX, SY negative)"
  "line end-point rule fires (A = 0)"
  "line Y step"
  "line tie D = 0 moves X"
  "arc of k = 4 done"
  "arc load with k = 4"
  "arc load with k = 3"
  "arc load with k = 2"
  "arc load with k = 1"
  "arc load with k = 0"
  "arc crossing onto the end quadrant"
  "arc end-point rule: outward axis arrived, goes in"
  "arc end-point rule: inward axis arrived, goes out"
  "arc tie D = 0 goes in"
  "arc outward step"
  "arc inward step"
  "arc CCW step in Q1" "arc CCW step in Q2" "arc CCW step in Q3" "arc CCW step in Q4"
  "arc CW step in Q1" "arc CW step in Q2" "arc CW step in Q3" "arc CW step in Q4"
)

# cover W: the cover model (assertions removed; each cover an output of
# the AIG, found through write_aiger's map); for each, bmc3 on that output
# alone must find a trace from reset (a reachable cover = a "failed"
# output).
cover() {
  local w=$1 t0 i idx r
  t0=$(date +%s)
  if ! aig cover_w$w "$w" "-DCOVER -DFORMAL_REF_ONLY"; then fail "covers: yosys FAILED (see $out/cover_w$w.yosys.log)"; return; fi
  : > "$out/cover_w$w.abc.log"
  for i in "${!covers[@]}"; do
    idx=$(awk -v b="$i" '$1 == "output" && $3 == b && $4 == "o_cov" { print $2 }' "$out/cover_w$w.map")
    r=
    if [ -n "$idx" ]; then
      # (bmc3 -a crashes on this model: one output at a time, cone -O.)
      timeout "$tmo" yosys-abc -c "read_aiger $out/cover_w$w.aig; fold; cone -O $idx -s; bmc3 -F 66" \
        > "$out/cover_w$w.$i.abc.log" 2>&1 || true
      cat "$out/cover_w$w.$i.abc.log" >> "$out/cover_w$w.abc.log"
      r=$(grep -o 'was asserted in frame [0-9]*' "$out/cover_w$w.$i.abc.log" | grep -o 'frame [0-9]*' || true)
    fi
    if [ -n "$r" ]; then
      echo "interp_formal: cover $i reached ($r): ${covers[$i]}"
    else
      fail "cover $i NOT reached: ${covers[$i]} (see $out/cover_w$w.$i.abc.log)"
    fi
  done
  echo "interp_formal: covers at W = $w checked ($(( $(date +%s) - t0 )) s in all)"
}

# Mutants: "file|kind|description|sed expression". Each must make the
# proof of its kind (lines or arcs, bmc3 to the full depth) fail.
mutants=(
  "interp_dp.v|arcs|tie rule D > 0 instead of D >= 0|s/wire d_pos = ~dneg_q;/wire d_pos = ~dneg_q \& (d_q != 0);/"
  "interp_dp.v|lines|tie rule D > 0 instead of D >= 0 (line)|s/wire d_pos = ~dneg_q;/wire d_pos = ~dneg_q \& (d_q != 0);/"
  "interp_dp.v|arcs|crossing leaves k unchanged|s/k_q <= k_q - 1'b1;/k_q <= k_q;/"
  "interp_dp.v|arcs|end-point rule compares co with to - 1|s/wire inw = kz ? (d_pos ? ~in_ex_q : out_ex_q) : d_pos;/wire inw = kz ? (d_pos ? ~in_ex_q : out_one_q) : d_pos;/"
  "interp_dp.v|lines|D's high half drops the low half's pending carry|s/wire \[DH-1:0\] cpx = {{(DH-1){1'b0}}, cp_q};/wire [DH-1:0] cpx = {DH{1'b0}};/"
  "blk_prep.v|lines|a line's F_IN_ONE from the arc's test|s/flags2_q\[2\] <= arc ? \\&t_in_one : (h_ti == 1);/flags2_q[2] <= \\&t_in_one;/"
  "blk_prep.v|lines|line flag 'no X distance left' from the Y target|s/flags2_q\[0\] <= (h_ci == h_ti);/flags2_q[0] <= (h_ci == h_to);/"
  "interp_core.v|lines|the queue level ignores a pop|s/level_q <= pop ? level_q - 1'b1 : level_q + 1'b1;/level_q <= pop ? level_q : level_q + 1'b1;/"
  "interp_core.v|lines|the queue full one block early|s/(level_q == DEPTH - 1'b1)/(level_q == DEPTH - 2'd2)/"
  "interp_dp.v|arcs|co == ti - 1 tested as ti + 1 == co|s/wire c_co_tim1 = \\&inc_terms({1'b0, co_q}, {1'b0, ti_q});/wire c_co_tim1 = \\&inc_terms({1'b0, ti_q}, {1'b0, co_q});/"
  "interp_dp.v|arcs|ci's copy of xing_q loads without the inward enable|s/if (ce_in) xing_ci_q <= xing_n;/xing_ci_q <= xing_n;/"
  "interp_dp.v|arcs|co's small flag not set by a crossing (co = 0)|s/: inw | co_hz;/: co_hz;/"
  "interp_dp.v|lines|co == to - 2 tested without bit 0|s/wire c_co_to2 = (co_q\\[0\\] == to_q\\[0\\])/wire c_co_to2 = 1'b1/"
)

mutant_run() {
  local w=$1 n=0 m file rest kind desc expr def depth r
  for m in "${mutants[@]}"; do
    n=$((n + 1))
    file=${m%%|*}; rest=${m#*|}
    kind=${rest%%|*}; rest=${rest#*|}
    desc=${rest%%|*}; expr=${rest#*|}
    sed "$expr" "$core/$file" > "$out/mutant$n.v"
    if cmp -s "$core/$file" "$out/mutant$n.v"; then
      fail "mutant $n ($desc) did not apply to the source"
      continue
    fi
    case "$kind" in
      lines) def=-DLINE_ONLY; depth=$(( (1 << (w + 1)) + 8 )) ;;
      arcs) def="-DARC_ONLY -DFORMAL_REF_ONLY"; depth=66 ;;
    esac
    r=unknown
    aig "mutant$n" "$w" "$def" "$file" "$out/mutant$n.v" && r=$(abc "mutant$n" "bmc3 -F $depth")
    if [ "$r" = failed ]; then
      echo "interp_formal: mutant $n ($file: $desc) refuted, $kind W = $w: $(grep -o 'asserted in frame [0-9]*' "$out/mutant$n.abc.log" | head -1) ($(cpu "mutant$n"))"
    else
      fail "mutant $n ($file: $desc) was NOT refuted: $r (see $out/mutant$n.abc.log)"
    fi
  done
}

for j in $jobs; do
  IFS=: read -r what w depth <<< "$j"
  w=${w:-3}
  case "$what" in
    lines) prove lines "$w" "${depth:-$(( (1 << (w + 1)) + 8 ))}" ;;
    arcs)
      if [ -z "$depth" ]; then
        # The longest arc: 4 (2 ceil(R) + 2) pulses, R < 2^W; + 7 clocks.
        depth=$(( 4 * (2 * (1 << w) + 2) + 8 )); [ "$w" -ne 3 ] || depth=66
      fi
      prove arcs "$w" "$depth" ;;
    lines-pdr) prove lines "$w" pdr ;;
    covers) cover "$w" ;;
    mutants) mutant_run "$w" ;;
    *) echo "run_formal.sh: unknown job '$j'" >&2; exit 2 ;;
  esac
done
exit $((fails > 0))
