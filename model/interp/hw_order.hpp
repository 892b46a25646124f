// The host's part of an interp_core / interp_top block: the four
// magnitudes in the order the hardware takes them (BLK_CI, BLK_CO, BLK_TI,
// BLK_TO of rtl/interp/regmap.def). An arc's start magnitudes go on the
// start quadrant's inward and outward axes, its end magnitudes on the end
// quadrant's (K crossings away); a line's targets are |Xe|, |Ye| and its
// starts 0 (interp_core requires them 0; interp_top's wb_regs zeroes
// them whatever the host wrote). The one place the hosts (the
// cosimulation, the board host, the test harnesses' block writers) make
// this choice; tests compare the pulses with the model, never with this.
#pragma once

#include <cstdint>

#include "interp/circular.hpp"

namespace contour {

struct InOutMagnitudes {
  std::uint64_t ci = 0, co = 0;  // start: inward, outward axis
  std::uint64_t ti = 0, to = 0;  // end (line: |Xe|, |Ye|)
};

// q: start quadrant, k: quadrant crossings (Circular<W>::validate); the
// magnitudes |xs|, |ys|, |xe|, |ye| (arc: relative to the centre).
constexpr InOutMagnitudes inout_order(bool arc, Sense s, int q, int k, std::uint64_t xs, std::uint64_t ys,
                                      std::uint64_t xe, std::uint64_t ye) {
  if (!arc) return {0, 0, xe, ye};
  const bool in_x0 = inward_is_x(q, s);
  const bool in_xe = in_x0 != ((k & 1) != 0);
  return {in_x0 ? xs : ys, in_x0 ? ys : xs, in_xe ? xe : ye, in_xe ? ye : xe};
}

}  // namespace contour
