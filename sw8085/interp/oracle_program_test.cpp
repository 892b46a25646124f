// The 8085 program (on the ISS) against the independent arc oracle
// (model/interp/arc_oracle.hpp): its pulses, read from OUT 10h, and the
// quadrant and position it publishes after each, checked against the
// geometry and the contract's rules, not against the golden model.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "interp/arc_oracle.hpp"
#include "interp/oracle_run.hpp"
#include "sw8085/interp/host.hpp"

namespace contour::sw8085 {
namespace {

std::string check_arc(Host& h, std::int64_t xs, std::int64_t ys, std::int64_t xe, std::int64_t ye, bool cw) {
  const std::string name = "arc " + std::to_string(xs) + " " + std::to_string(ys) + " " + std::to_string(xe) + " " +
                           std::to_string(ye) + (cw ? " cw: " : " ccw: ");
  const oracle::ArcExpect a = oracle::expect_arc(xs, ys, xe, ye, cw);
  RunResult r;
  try {
    r = h.run(Move::arc(xs, ys, xe, ye, cw ? Sense::CW : Sense::CCW), nullptr, std::uint64_t(a.pulses) + 8);
  } catch (const std::exception& e) {
    return name + "the run stopped: " + e.what();
  }
  const std::string e = oracle::check_run(a, xs, ys, xe, ye, cw, r);
  return e.empty() ? e : name + e;
}

// Every accepted arc between lattice points with |coordinates| <= 5 (ends
// to 6), both senses, and the short arc.
TEST(ProgramOracle, EverySmallArcBothSenses) {
  Host h;
  EXPECT_EQ(check_arc(h, 10, 0, 10, 2, false), "");
  EXPECT_EQ(check_arc(h, 10, 0, 10, -2, true), "");
  const oracle::Sweep s = oracle::check_small_arcs(5, [&](auto... a) { return check_arc(h, a...); });
  EXPECT_EQ(s.failed, 0) << s.first;
  EXPECT_GT(s.runs, 1500);
}

// Full circles of integer radius (8R pulses) and a large quarter across the
// program's multi-byte magnitudes.
TEST(ProgramOracle, FullCirclesAndALargeArc) {
  Host h;
  for (std::int64_t r : {2, 9, 200}) {
    EXPECT_EQ(check_arc(h, r, 0, r, 0, false), "");
    EXPECT_EQ(check_arc(h, 0, -r, 0, -r, true), "");
  }
  EXPECT_EQ(check_arc(h, 3000, 4000, -4000, 3000, false), "");
  EXPECT_EQ(check_arc(h, 70000, 0, 0, -70000, true), "");
}

}  // namespace
}  // namespace contour::sw8085
