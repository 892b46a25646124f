// Circular interpolator: paper A's worked example, every quadrant and both
// senses, the end point rule, the accepted domain and its messages.
#include "interp/circular.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

namespace contour {
namespace {

std::string steps(std::int64_t xs, std::int64_t ys, std::int64_t xe, std::int64_t ye, Sense s) {
  Circular<24> c(xs, ys, xe, ye, s);
  std::string out;
  while (auto p = c.step()) out += (out.empty() ? "" : " ") + to_string(*p);
  return out;
}

std::string error_of(std::int64_t xs, std::int64_t ys, std::int64_t xe, std::int64_t ye, Sense s) {
  try {
    Circular<24>::validate(xs, ys, xe, ye, s);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(Circular, PaperFig5SixZeroToZeroSix) {
  EXPECT_EQ(steps(6, 0, 0, 6, Sense::CCW), "-X +Y +Y +Y +Y -X +Y -X +Y -X -X -X");
}

TEST(Circular, PaperFig5DiscriminantAfterEachPulse) {
  // The D column of paper A's Fig. 5.
  const std::vector<std::int64_t> want = {-11, -10, -7, -2, 5, -4, 5, -2, 9, 4, 1, 0};
  Circular<24> c(6, 0, 0, 6, Sense::CCW);
  for (std::int64_t d : want) {
    ASSERT_TRUE(c.step());
    EXPECT_EQ(c.state().d, d);
  }
  EXPECT_TRUE(c.done());
  EXPECT_EQ(c.state().quadrant, 1) << "(0, 6) belongs to Q2 for CCW travel";
}

TEST(Circular, ClockwiseIsTheMirrorOfFig5) {
  // Mirroring Fig. 5 in the line y = x swaps X and Y and reverses the sense.
  EXPECT_EQ(steps(0, 6, 6, 0, Sense::CW), "-Y +X +X +X +X -Y +X -Y +X -Y -Y -Y");
}

TEST(Circular, EveryQuadrantIsFig5Rotated) {
  // Rotating Fig. 5 by 90 degrees maps (x, y) -> (-y, x): X pulses become Y
  // pulses and Y pulses become -X pulses.
  EXPECT_EQ(steps(0, 6, -6, 0, Sense::CCW), "-Y -X -X -X -X -Y -X -Y -X -Y -Y -Y");
  EXPECT_EQ(steps(-6, 0, 0, -6, Sense::CCW), "+X -Y -Y -Y -Y +X -Y +X -Y +X +X +X");
  EXPECT_EQ(steps(0, -6, 6, 0, Sense::CCW), "+Y +X +X +X +X +Y +X +Y +X +Y +Y +Y");
}

TEST(Circular, FullCircleReturnsToTheStartAndCrossesFourQuadrants) {
  for (Sense s : {Sense::CW, Sense::CCW}) {
    Circular<24> c(7, 3, 7, 3, s);
    EXPECT_EQ(c.state().crossings, 4);
    int crossings = 0;
    std::uint8_t q = c.state().quadrant;
    while (c.step())
      if (c.state().quadrant != q) {
        ++crossings;
        q = c.state().quadrant;
      }
    EXPECT_EQ(crossings, 4);
    EXPECT_EQ(c.state().x, 7);
    EXPECT_EQ(c.state().y, 3);
  }
}

TEST(Circular, EndPointOffTheIntegerCircleIsReachedExactly) {
  // R^2 = 100; (7, 7) has x^2 + y^2 = 98: a rounded G-code end point.
  Circular<24> c(10, 0, 7, 7, Sense::CCW);
  while (c.step()) {
  }
  EXPECT_TRUE(c.done());
  EXPECT_EQ(c.state().x, 7);
  EXPECT_EQ(c.state().y, 7);
  EXPECT_EQ(c.state().d, 98 - 100);
}

TEST(Circular, EndBehindTheStartInTheSameQuadrantGoesRound) {
  Circular<24>::Plan ahead = Circular<24>::validate(10, 1, 9, 4, Sense::CCW);
  EXPECT_EQ(ahead.crossings, 0);
  Circular<24>::Plan behind = Circular<24>::validate(9, 4, 10, 1, Sense::CCW);
  EXPECT_EQ(behind.crossings, 4);
}

TEST(Circular, RejectsWithAMessageNamingTheProblem) {
  EXPECT_NE(error_of(0, 0, 0, 0, Sense::CW).find("zero radius"), std::string::npos);
  EXPECT_NE(error_of(1, 0, 0, 1, Sense::CW).find("radius too small: R^2 = XS^2 + YS^2 = 1"), std::string::npos);
  EXPECT_NE(error_of(10, 0, 5, 5, Sense::CCW).find("end point (5, 5) is not on the circle"), std::string::npos);
  EXPECT_NE(error_of(1 << 24, 0, 0, 1, Sense::CCW).find("XS = 16777216 is out of range"), std::string::npos);
  const std::int64_t M = max_magnitude(24);
  EXPECT_NE(error_of(M, 1, M, 1, Sense::CCW).find("radius too large"), std::string::npos);
  EXPECT_EQ(error_of(M, 0, 0, M, Sense::CCW), "");
  // R^2 = 2: (0, 2) is within the band but the walk enters Q2 at (0, 1).
  EXPECT_NE(error_of(1, 1, 0, 2, Sense::CCW).find("cannot be reached exactly"), std::string::npos);
}

TEST(Circular, LargestRadiusFullCircleStaysInsideTheWidths) {
  const std::int64_t M = max_magnitude(24);
  for (Sense s : {Sense::CW, Sense::CCW}) {
    Circular<24> c(M, 0, M, 0, s);
    std::uint64_t n = 0;
    std::int64_t dmin = 0, dmax = 0;
    while (c.step()) {  // OverflowError would fail the test
      ++n;
      dmin = std::min(dmin, c.state().d);
      dmax = std::max(dmax, c.state().d);
    }
    EXPECT_TRUE(c.done());
    EXPECT_EQ(c.state().x, M);
    // A full circle of radius R on a one-axis-per-pulse lattice: 8R pulses.
    EXPECT_EQ(n, 8u * static_cast<std::uint64_t>(M));
    EXPECT_GE(dmin, -(std::int64_t{1} << 25));
    EXPECT_LT(dmax, std::int64_t{1} << 25);
  }
}

TEST(Circular, RandomW24ArcsReachTheirEndsWithDInClosedForm) {
  std::mt19937_64 rng(2024);
  std::uniform_int_distribution<std::int64_t> coord(-max_magnitude(23), max_magnitude(23));
  std::uniform_real_distribution<double> angle(0, 2 * M_PI);
  int runs = 0;
  while (runs < 300) {
    const std::int64_t xs = coord(rng) / 64, ys = coord(rng) / 64;  // radii up to ~2^17: fast full walks
    const std::int64_t r2 = xs * xs + ys * ys;
    if (r2 < 2) continue;
    const double R = std::sqrt(double(r2)), a = angle(rng);
    const std::int64_t xe = std::llround(R * std::cos(a)), ye = std::llround(R * std::sin(a));
    const Sense s = rng() & 1 ? Sense::CW : Sense::CCW;
    Circular<24> c(xs, ys, xe, ye, s);  // a rounded point of the circle is always accepted
    while (c.step()) {
      const State st = c.state();
      ASSERT_EQ(st.d, st.x * st.x + st.y * st.y - r2);
    }
    ASSERT_TRUE(c.done());
    ASSERT_EQ(c.state().x, xe);
    ASSERT_EQ(c.state().y, ye);
    ++runs;
  }
}

}  // namespace
}  // namespace contour

namespace contour {
namespace {

TEST(Circular, ACopyStepsOnItsOwnRegisters) {
  Circular<24> a(6, 0, 0, 6, Sense::CCW);
  a.step();
  Circular<24> b = a;  // copy mid-move
  a.step();
  a.step();
  EXPECT_EQ(b.state().x, 5);
  EXPECT_EQ(b.state().y, 0);
  b.step();
  EXPECT_EQ(b.state().y, 1) << "the copy moved, not the original";
  EXPECT_EQ(a.state().y, 2);
  b = a;
  b.step();
  EXPECT_EQ(a.state().y, 2);
  EXPECT_EQ(b.state().y, 3);
}

}  // namespace
}  // namespace contour
