// Linear3<W>: paper A's linear method on three axes (docs/algorithm.md, "Linear on three axes").
#include "interp/linear3.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <random>


namespace contour {
namespace {

// Euclidean distance in pulses of (x, y, z) from the segment 0 -> (xe, ye, ze).
double segment_distance(std::int64_t x, std::int64_t y, std::int64_t z, std::int64_t xe, std::int64_t ye,
                        std::int64_t ze) {
  const double ex = static_cast<double>(xe), ey = static_cast<double>(ye), ez = static_cast<double>(ze);
  const double px = static_cast<double>(x), py = static_cast<double>(y), pz = static_cast<double>(z);
  const double ee = ex * ex + ey * ey + ez * ez;
  double t = ee == 0 ? 0 : (px * ex + py * ey + pz * ez) / ee;
  t = t < 0 ? 0 : (t > 1 ? 1 : t);
  return std::hypot(px - t * ex, py - t * ey, pz - t * ez);
}

struct Stats {
  double max_dev = 0;
};

// Runs one move and checks every invariant of the contract independently of
// the implementation's own bookkeeping.
template <unsigned W>
void check_move(std::int64_t xe, std::int64_t ye, std::int64_t ze, Stats& st, bool check_every_step = true) {
  Linear3<W> l(xe, ye, ze);
  const std::int64_t A = std::llabs(xe), B = std::llabs(ye), C = std::llabs(ze);
  std::int64_t x = 0, y = 0, z = 0;  // magnitudes travelled, from the pulses alone
  std::uint64_t n = 0;
  while (auto p = l.step()) {
    ++n;
    // Independent check of the rule: the moved axis has distance left and
    // its next step is due first, (2p+1)/L smallest among the axes with
    // distance left (ties: X before Y before Z), compared exactly.
    const std::int64_t prog[3] = {x, y, z}, len[3] = {A, B, C};
    int want = -1;
    for (int a = 0; a < 3; ++a) {
      if (prog[a] >= len[a]) continue;
      if (want < 0 || (2 * prog[a] + 1) * len[want] < (2 * prog[want] + 1) * len[a]) want = a;
    }
    ASSERT_EQ(static_cast<int>(p->axis), want) << "move " << xe << " " << ye << " " << ze << " pulse " << n;
    const std::int64_t e[3] = {xe, ye, ze};
    ASSERT_EQ(p->sign, e[want] < 0 ? -1 : +1);
    (want == 0 ? x : (want == 1 ? y : z)) += 1;
    if (!check_every_step && !l.done()) continue;
    const State3 s = l.state();
    ASSERT_EQ(s.x, xe < 0 ? -x : x);
    ASSERT_EQ(s.y, ye < 0 ? -y : y);
    ASSERT_EQ(s.z, ze < 0 ? -z : z);
    ASSERT_EQ(s.dxy, A * (2 * y + 1) - B * (2 * x + 1));
    ASSERT_EQ(s.dxz, A * (2 * z + 1) - C * (2 * x + 1));
    ASSERT_EQ(s.dyz, B * (2 * z + 1) - C * (2 * y + 1));
    // Stated bounds of the discriminants.
    ASSERT_GE(s.dxy, -2 * B);
    ASSERT_LE(s.dxy, 2 * A);
    ASSERT_GE(s.dxz, -2 * C);
    ASSERT_LE(s.dxz, 2 * A);
    ASSERT_GE(s.dyz, -2 * C);
    ASSERT_LE(s.dyz, 2 * B);
    const double dev = segment_distance(s.x, s.y, s.z, xe, ye, ze);
    st.max_dev = std::max(st.max_dev, dev);
    ASSERT_LE(dev, std::sqrt(3.0) / 2 + 1e-9) << "move " << xe << " " << ye << " " << ze << " at " << s.x << " " << s.y << " " << s.z;
  }
  EXPECT_EQ(n, static_cast<std::uint64_t>(A + B + C));
  EXPECT_TRUE(l.done());
  const State3 s = l.state();
  EXPECT_EQ(s.x, xe);
  EXPECT_EQ(s.y, ye);
  EXPECT_EQ(s.z, ze);
  EXPECT_EQ(s.pulses, n);
  EXPECT_FALSE(l.step().has_value());
}

TEST(Linear3, ExhaustiveSmallCubeAtW4) {
  Stats st;
  for (std::int64_t xe = -15; xe <= 15; ++xe)
    for (std::int64_t ye = -15; ye <= 15; ++ye)
      for (std::int64_t ze = -15; ze <= 15; ++ze) {
        check_move<4>(xe, ye, ze, st);
        if (::testing::Test::HasFatalFailure()) return;
      }
  RecordProperty("max_deviation_pulses", std::to_string(st.max_dev));
  EXPECT_GT(st.max_dev, 0.5);  // the bound is not vacuous
}

TEST(Linear3, PaperARuleOnThreeAxesWouldStrayMoreThanOnePulse) {
  // Why linear3 compares mid-points: paper A's progress rule (move the axis
  // with the smallest x/A, y/B, z/C) on the move (2117, 87, 434) steps X, Y,
  // Z first and reaches (1, 1, 1), 1.23 pulses from the segment.
  EXPECT_GT(segment_distance(1, 1, 1, 2117, 87, 434), 1.2);
  // linear3 moves X, X, then Z (due at 1/868 of the move, before X's third
  // step at 5/4234), and Y only at 1/174.
  Linear3<24> l(2117, 87, 434);
  EXPECT_EQ(l.step()->axis, Axis::X);
  EXPECT_EQ(l.step()->axis, Axis::X);
  EXPECT_EQ(l.step()->axis, Axis::Z);
  EXPECT_LE(segment_distance(2, 0, 1, 2117, 87, 434), std::sqrt(3.0) / 2);
}

TEST(Linear3, TwoAxesStayWithinHalfADiagonal) {
  // With one axis at rest every point is within sqrt(2)/2 of the segment
  // (paper A's own rule: within 1).
  for (std::int64_t xe = -20; xe <= 20; ++xe)
    for (std::int64_t ze = -20; ze <= 20; ++ze) {
      Linear3<8> l(xe, 0, ze);
      while (l.step()) {
        const State3 s = l.state();
        ASSERT_EQ(s.y, 0);
        ASSERT_LE(segment_distance(s.x, 0, s.z, xe, 0, ze), std::sqrt(2.0) / 2 + 1e-9);
      }
    }
}

TEST(Linear3, PaperAFigure2ExampleWithZ) {
  // Paper A, Fig. 2: Xe 6, Ye 5 gives X Y X Y X Y X Y X Y X.
  Linear3<24> l(6, 5, 0);
  std::string seq;
  while (auto p = l.step()) seq += to_string(*p) + " ";
  EXPECT_EQ(seq, "+X +Y +X +Y +X +Y +X +Y +X +Y +X ");
  // Equal lengths on three axes: X Y Z repeated.
  Linear3<24> m(-2, 2, -2);
  seq.clear();
  while (auto p = m.step()) seq += to_string(*p) + " ";
  EXPECT_EQ(seq, "-X +Y -Z -X +Y -Z ");
}

TEST(Linear3, RandomAtW24) {
  std::mt19937_64 rng(20240601);
  Stats st;
  const std::int64_t kMax = Linear3<24>::kMax;
  // Short moves, checked every step.
  std::uniform_int_distribution<std::int64_t> small(-3000, 3000);
  for (int i = 0; i < 300; ++i) check_move<24>(small(rng), small(rng), small(rng), st);
  // Full-range magnitudes (tens of millions of pulses): invariants checked at
  // the end; the rule is still checked on every pulse.
  std::uniform_int_distribution<std::int64_t> big(-kMax, kMax);
  std::uniform_int_distribution<int> bits(0, 24);
  for (int i = 0; i < 4; ++i) {
    auto mag = [&] { return big(rng) >> bits(rng); };
    check_move<24>(mag(), mag(), mag(), st, /*check_every_step=*/false);
  }
  check_move<24>(kMax, -kMax, kMax, st, false);
}

TEST(Linear3, RejectsOutOfRangeEndPoints) {
  EXPECT_THROW(Linear3<24>(std::int64_t{1} << 24, 0, 0), InputError);
  EXPECT_THROW(Linear3<24>(0, -(std::int64_t{1} << 24), 0), InputError);
  EXPECT_THROW(Linear3<4>(0, 0, 16), InputError);
  EXPECT_NO_THROW(Linear3<4>(15, -15, 15));
  try {
    Linear3<24>(0, 0, 1 << 24);
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("ZE = 16777216"), std::string::npos) << e.what();
  }
}

TEST(Linear3, ZeroMoveIsDoneAtOnce) {
  Linear3<24> l(0, 0, 0);
  EXPECT_TRUE(l.done());
  EXPECT_FALSE(l.step().has_value());
}

}  // namespace
}  // namespace contour
