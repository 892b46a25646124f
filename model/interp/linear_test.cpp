// Linear interpolator: paper A's worked example, the closed form of D, the
// end point rule, the accepted domain.
#include "interp/linear.hpp"

#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

namespace contour {
namespace {

std::string steps(std::int64_t xe, std::int64_t ye) {
  Linear<24> l(xe, ye);
  std::string s;
  while (auto p = l.step()) s += (s.empty() ? "" : " ") + to_string(*p);
  return s;
}

TEST(Linear, PaperFig2SixFive) {
  // Paper A, Fig. 2: Xe = 6, Ye = 5 gives X Y X Y X Y X Y X Y X.
  EXPECT_EQ(steps(6, 5), "+X +Y +X +Y +X +Y +X +Y +X +Y +X");
}

TEST(Linear, PaperFig2DiscriminantFollowsEquations2To5) {
  // D after each pulse, from eq. 3 and 5 by hand: D -= 5 on X, D += 6 on Y.
  const std::vector<std::int64_t> want = {-5, 1, -4, 2, -3, 3, -2, 4, -1, 5, 0};
  Linear<24> l(6, 5);
  for (std::int64_t d : want) {
    ASSERT_TRUE(l.step());
    EXPECT_EQ(l.state().d, d);
  }
  EXPECT_TRUE(l.done());
  EXPECT_FALSE(l.step()) << "a finished move emits nothing";
}

TEST(Linear, QuadrantsMirrorTheFirst) {
  EXPECT_EQ(steps(-6, 5), "-X +Y -X +Y -X +Y -X +Y -X +Y -X");
  EXPECT_EQ(steps(6, -5), "+X -Y +X -Y +X -Y +X -Y +X -Y +X");
  EXPECT_EQ(steps(-6, -5), "-X -Y -X -Y -X -Y -X -Y -X -Y -X");
}

TEST(Linear, AxisWithNoDistanceLeftHandsThePulseOver) {
  // Xe = 0: D stays 0, which chooses X, but X has no distance: Y moves.
  EXPECT_EQ(steps(0, 3), "+Y +Y +Y");
  EXPECT_EQ(steps(0, -2), "-Y -Y");
  EXPECT_EQ(steps(4, 0), "+X +X +X +X");
  EXPECT_EQ(steps(0, 0), "") << "a zero move is done at once";
}

TEST(Linear, ExtremesStayInsideTheirWidths) {
  constexpr std::int64_t M = max_magnitude(24);
  for (auto [xe, ye] : std::vector<std::pair<std::int64_t, std::int64_t>>{{M, M}, {M, 1}, {1, M}, {-M, M}, {M, -M - 0}}) {
    Linear<24> l(xe, ye);
    std::uint64_t n = 0;
    while (l.step()) ++n;  // OverflowError would fail the test
    EXPECT_EQ(n, static_cast<std::uint64_t>(std::llabs(xe) + std::llabs(ye)));
    EXPECT_EQ(l.state().x, xe);
    EXPECT_EQ(l.state().y, ye);
  }
}

TEST(Linear, RejectsEndPointsOutsideTheWidth) {
  constexpr std::int64_t M = max_magnitude(24);
  EXPECT_THROW(Linear<24>(M + 1, 0), InputError);
  EXPECT_THROW(Linear<24>(0, -M - 1), InputError);
  try {
    Linear<24>(1, 1 << 24);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("YE = 16777216 is out of range"), std::string::npos) << e.what();
  }
}

TEST(Linear, RandomW24MatchesClosedForm) {
  std::mt19937_64 rng(24);
  std::uniform_int_distribution<std::int64_t> coord(-max_magnitude(24), max_magnitude(24));
  for (int i = 0; i < 2000; ++i) {
    // Short moves in any direction, end points anywhere in the 24-bit range:
    // a long move's first pulses exercise the full width of D.
    const std::int64_t xe = coord(rng), ye = coord(rng);
    Linear<24> l(xe, ye);
    const std::int64_t a = std::llabs(xe), b = std::llabs(ye);
    for (int k = 0; k < 300 && !l.done(); ++k) {
      ASSERT_TRUE(l.step());
      const State s = l.state();
      ASSERT_EQ(s.d, a * std::llabs(s.y) - b * std::llabs(s.x)) << xe << "," << ye << " after " << k;
      ASSERT_GE(s.d, -b);
      ASSERT_LE(s.d, a - 1 < 0 ? 0 : a - 1);
    }
  }
}

}  // namespace
}  // namespace contour
