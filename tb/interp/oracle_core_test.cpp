// The Verilog core against the independent arc oracle (model/interp/
// arc_oracle.hpp): the block is built from the oracle's own q and k (not
// from Circular<W>::validate through make_block), and the core's pulses,
// quadrant and position after each are checked against the geometry.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "Vinterp_w24.h"
#include "Vinterp_w8.h"
#include "core_harness.hpp"
#include "interp/arc_oracle.hpp"
#include "interp/oracle_run.hpp"

namespace contour {
namespace {

using rtl::Block;
using rtl::CoreHarness;

// The block a host following the contract writes, from the oracle's plan.
Block oracle_block(const oracle::ArcExpect& a, std::int64_t xs, std::int64_t ys, std::int64_t xe, std::int64_t ye,
                   bool cw) {
  Block b;
  b.arc = true;
  b.cw = cw;
  b.q = static_cast<std::uint8_t>(a.q_start);
  b.k = static_cast<std::uint8_t>(a.k);
  const InOutMagnitudes io =
      inout_order(true, cw ? Sense::CW : Sense::CCW, a.q_start, a.k, static_cast<std::uint64_t>(oracle::mag(xs)),
                  static_cast<std::uint64_t>(oracle::mag(ys)), static_cast<std::uint64_t>(oracle::mag(xe)),
                  static_cast<std::uint64_t>(oracle::mag(ye)));
  b.ci = io.ci;
  b.co = io.co;
  b.ti = io.ti;
  b.to = io.to;
  return b;
}

// "" or what differs: the core's walk against the oracle's, and the
// production host's block (make_block, through validate) against the
// oracle's q and k.
template <class H>
std::string check_arc(H& h, std::int64_t xs, std::int64_t ys, std::int64_t xe, std::int64_t ye, bool cw) {
  const std::string name = "arc " + std::to_string(xs) + " " + std::to_string(ys) + " " + std::to_string(xe) + " " +
                           std::to_string(ye) + (cw ? " cw: " : " ccw: ");
  const oracle::ArcExpect a = oracle::expect_arc(xs, ys, xe, ye, cw);
  const Block host = rtl::make_block<H::kWidth>(Move::arc(xs, ys, xe, ye, cw ? Sense::CW : Sense::CCW));
  if (host.q != a.q_start || host.k != a.k)
    return name + "make_block gives q " + std::to_string(host.q) + " k " + std::to_string(host.k) + ", the oracle q " +
           std::to_string(a.q_start) + " k " + std::to_string(a.k);
  const RunResult r = h.run(oracle_block(a, xs, ys, xe, ye, cw), std::uint64_t(a.pulses) + 8);
  const std::string e = oracle::check_run(a, xs, ys, xe, ye, cw, r);
  return e.empty() ? e : name + e;
}

// Every arc between lattice points with |coordinates| <= 8 (ends to 9),
// both senses, at W = 8.
TEST(InterpCoreOracle, EverySmallArcBothSensesW8) {
  CoreHarness<Vinterp_w8, 8> h;
  const oracle::Sweep s = oracle::check_small_arcs(8, [&](auto... a) { return check_arc(h, a...); });
  EXPECT_EQ(s.failed, 0) << s.first;
  EXPECT_GT(s.runs, 8000);
}

// The arc, full circles of integer radius (8R pulses) and
// quarter arcs at W = 24.
TEST(InterpCoreOracle, ShortArcFullCirclesAndLargeQuartersW24) {
  CoreHarness<Vinterp_w24, 24> h;
  EXPECT_EQ(check_arc(h, 10, 0, 10, 2, false), "");
  EXPECT_EQ(check_arc(h, 10, 0, 10, -2, true), "");
  for (std::int64_t r : {2, 7, 300}) {
    EXPECT_EQ(check_arc(h, r, 0, r, 0, false), "");
    EXPECT_EQ(check_arc(h, 0, r, 0, r, true), "");
  }
  EXPECT_EQ(check_arc(h, 3000, 4000, -4000, 3000, false), "");
  EXPECT_EQ(check_arc(h, -3000, 4000, 4000, -3000, true), "");
}

}  // namespace
}  // namespace contour
