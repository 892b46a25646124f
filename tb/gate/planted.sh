#!/usr/bin/env bash
# The gate-level check seen failing: synthesizes interp3_core at W = 3
# (gate_sim.sh, which must pass), then complements the truth table of one
# LUT of the netlist (the first SB_LUT4, or the N-th: LUT=N) and simulates
# that netlist against the RTL again, which must report the first
# differing clock. Exit 0 when both happen.
#
#   planted.sh WORK
set -euo pipefail
work=${1:?work dir}
here=$(cd "$(dirname "$0")" && pwd)
nth=${LUT:-1}
"$here/gate_sim.sh" interp3 3 all "$work" - >/dev/null || {
  echo "planted.sh: the unplanted netlist does not pass" >&2; exit 1; }
good=$work/interp3_w3_gate.v
bad=$work/interp3_w3_gate_flipped.v
N=$nth perl -pe '
  if (/\.LUT_INIT\(16.h([0-9a-f]{4})\)/ && ++$seen == $ENV{N}) {
    my $new = sprintf("%04x", 0xffff ^ hex($1));
    print STDERR "planted.sh: LUT $ENV{N}: LUT_INIT 16'"'"'h$1 -> 16'"'"'h$new\n";
    s/16.h[0-9a-f]{4}/16'"'"'h$new/;
  }' "$good" >"$bad"
cmp -s "$good" "$bad" && { echo "planted.sh: no LUT_INIT $nth to flip" >&2; exit 1; }
if out=$(GATE_NETLIST=$bad "$here/gate_sim.sh" interp3 3 all "$work" -); then
  echo "$out"
  echo "planted.sh: the flipped netlist PASSED: the gate-level check cannot fail" >&2
  exit 1
fi
echo "$out"
grep -q "^FAIL interp3_gate_tb W = 3: clock" <<<"$out" || { echo "planted.sh: failed, but not on a difference" >&2; exit 1; }
echo "planted.sh: the flipped netlist fails, as it must"
