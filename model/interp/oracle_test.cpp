// The golden model against the independent arc oracle (arc_oracle.hpp):
// pulse counts, quadrant sequence and every pulse from geometry and the
// contract's rules, not from the model's own plan.
#include "interp/arc_oracle.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "interp/circular.hpp"

namespace contour {
namespace {

// The model's run as the oracle's steps, at most `limit` pulses.
template <unsigned W>
std::vector<oracle::Step> model_steps(std::int64_t xs, std::int64_t ys, std::int64_t xe, std::int64_t ye, bool cw,
                                      std::size_t limit) {
  Circular<W> c(xs, ys, xe, ye, cw ? Sense::CW : Sense::CCW);
  std::vector<oracle::Step> out;
  while (out.size() < limit) {
    const auto p = c.step();
    if (!p) break;
    const State s = c.state();
    out.push_back({p->axis == Axis::X ? 0 : 1, p->sign, int(s.quadrant), s.x, s.y});
  }
  return out;
}

template <unsigned W = 24>
std::string check(std::int64_t xs, std::int64_t ys, std::int64_t xe, std::int64_t ye, bool cw) {
  const oracle::ArcExpect a = oracle::expect_arc(xs, ys, xe, ye, cw);
  const auto steps = model_steps<W>(xs, ys, xe, ye, cw, std::size_t(a.pulses) + 8);
  const std::string e = oracle::check_walk(a, xs, ys, xe, ye, cw, steps);
  return e.empty() ? e : "arc " + std::to_string(xs) + " " + std::to_string(ys) + " " + std::to_string(xe) + " " +
                             std::to_string(ye) + (cw ? " cw: " : " ccw: ") + e;
}

bool model_accepts(std::int64_t xs, std::int64_t ys, std::int64_t xe, std::int64_t ye, bool cw) {
  try {
    Circular<24>::validate(xs, ys, xe, ye, cw ? Sense::CW : Sense::CCW);
    return true;
  } catch (const InputError&) {
    return false;
  }
}

// The arc: two pulses, not a full extra turn (82).
TEST(ArcOracle, ShortArcInTheStartQuadrantIsShort) {
  const oracle::ArcExpect a = oracle::expect_arc(10, 0, 10, 2, false);
  EXPECT_EQ(a.k, 0);
  EXPECT_EQ(a.pulses, 2);
  EXPECT_EQ(check(10, 0, 10, 2, false), "");
  EXPECT_EQ(check(10, 0, 10, -2, true), "");
}

// The oracle's closed form on hand-checked arcs: paper A's Fig. 5 is 12
// pulses (6 X, 6 Y); a full circle of integer radius is 8R.
TEST(ArcOracle, ClosedFormOnKnownArcs) {
  const oracle::ArcExpect fig5 = oracle::expect_arc(6, 0, 0, 6, false);
  EXPECT_EQ(fig5.pulses, 12);
  EXPECT_EQ(fig5.x_pulses, 6);
  EXPECT_EQ(fig5.y_pulses, 6);
  ASSERT_EQ(fig5.runs.size(), 2u);
  EXPECT_EQ(fig5.runs[1].q, 1);
  for (std::int64_t r : {2, 5, 41, 1000}) {
    const oracle::ArcExpect full = oracle::expect_arc(r, 0, r, 0, true);
    EXPECT_EQ(full.k, 4);
    EXPECT_EQ(full.pulses, 8 * r) << r;
    EXPECT_EQ(check(r, 0, r, 0, true), "");
    EXPECT_EQ(check(0, -r, 0, -r, false), "");
  }
}

// Every arc between lattice points with |coordinates| <= 7 (ends to 8), both
// senses: the oracle's acceptance equals the model's, and every accepted
// arc's walk is the oracle's.
TEST(ArcOracle, EverySmallArcBothSenses) {
  int disagree = 0;
  std::string first_disagreement;
  auto same_acceptance = [&](int xs, int ys, int xe, int ye, bool cw, bool ok) {
    if (model_accepts(xs, ys, xe, ye, cw) != ok && disagree++ == 0)
      first_disagreement = std::to_string(xs) + " " + std::to_string(ys) + " " + std::to_string(xe) + " " +
                           std::to_string(ye) + (cw ? " cw" : " ccw") + (ok ? ": the oracle accepts" : ": the model accepts");
  };
  const oracle::Sweep s = oracle::check_small_arcs(7, check, same_acceptance);
  EXPECT_EQ(disagree, 0) << first_disagreement;
  EXPECT_EQ(s.failed, 0) << s.first;
  EXPECT_GT(s.runs, 5000);
}

// Random arcs of radius up to 2^12 at W = 16 and W = 24, the end a rounded
// point of the circle: the oracle's count and walk.
TEST(ArcOracle, RandomLargeArcs) {
  std::mt19937_64 rng(1982);
  std::uniform_real_distribution<double> ang(0.0, 6.283185307179586);
  std::uniform_int_distribution<int> rad(2, 1 << 12);
  int runs = 0;
  for (int i = 0; i < 200; ++i) {
    const double r = rad(rng), t0 = ang(rng), t1 = ang(rng);
    const auto xs = std::int64_t(std::llround(r * std::cos(t0))), ys = std::int64_t(std::llround(r * std::sin(t0)));
    const auto xe = std::int64_t(std::llround(r * std::cos(t1))), ye = std::int64_t(std::llround(r * std::sin(t1)));
    const bool cw = i % 2;
    if (!oracle::expect_arc(xs, ys, xe, ye, cw).accepted) continue;
    ++runs;
    ASSERT_EQ(check<16>(xs, ys, xe, ye, cw), "");
    ASSERT_EQ(check<24>(xs, ys, xe, ye, cw), "");
  }
  EXPECT_GT(runs, 120);
}

}  // namespace
}  // namespace contour
