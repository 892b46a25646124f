// Regression of rtl/interp3/interp3_core against the golden model
// Linear3<W> (docs/algorithm.md, "Linear on three axes"): pulse by pulse and state by state.
//
//   W = 4:  every end point of the cube |XE|, |YE|, |ZE| <= 15 (29,791
//           moves), command held high; the invariants of the contract
//           checked on every RTL state on their own; command gaps; loads
//           and resets in the middle of a move.
//   W = 24: random moves (seeded) of every size class, the first pulses of
//           the extreme moves, and complete full-range moves.
//
// Environment: CONTOUR_FULL=1 runs more random and full-range moves;
// CONTOUR_SEED=N changes the random seed (printed with every failure);
// CONTOUR_FST=FILE writes an FST trace of the (last) harness.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include "Vinterp3_w24.h"
#include "Vinterp3_w4.h"
#include "Vinterp3_w4_xrand.h"
#include "compare3.hpp"
#include "interp/linear3.hpp"
#include "interp3_harness.hpp"

namespace contour::rtl3 {
namespace {

using H4 = Interp3Harness<Vinterp3_w4, 4>;
using H24 = Interp3Harness<Vinterp3_w24, 24>;
using H4X = Interp3Harness<Vinterp3_w4_xrand, 4>;
constexpr std::int64_t kMax4 = 15;
constexpr std::int64_t kMax24 = (std::int64_t{1} << 24) - 1;

// CONTOUR_FULL=1 (set, not empty, not 0): the long runs.
bool full_run() {
  const char* e = std::getenv("CONTOUR_FULL");
  return e != nullptr && *e != '\0' && *e != '0';
}

std::uint64_t seed() {
  const char* e = std::getenv("CONTOUR_SEED");
  return e ? std::strtoull(e, nullptr, 10) : 1982;
}

// Regression summary: one line first, then the failures.
struct Tally {
  std::string name;
  std::uint64_t moves = 0, failed = 0, pulses = 0;
  std::vector<std::string> reports;
  void add(const std::string& report, std::uint64_t n) {
    ++moves;
    pulses += n;
    if (!report.empty()) {
      ++failed;
      if (reports.size() < 3) reports.push_back(report);
    }
  }
  void print(double seconds) const {
    std::printf("%s: %.2f%% PASS %llu PASSED, %llu FAILED (%llu pulses, %.1f s)\n", name.c_str(),
                moves ? 100.0 * static_cast<double>(moves - failed) / static_cast<double>(moves) : 0.0,
                static_cast<unsigned long long>(moves - failed), static_cast<unsigned long long>(failed),
                static_cast<unsigned long long>(pulses), seconds);
    for (const auto& r : reports) std::printf("%s", r.c_str());
  }
};

double since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

std::uint64_t total(const Move3& m) {
  auto mag = [](std::int64_t v) { return static_cast<std::uint64_t>(v < 0 ? -v : v); };
  return mag(m.xe) + mag(m.ye) + mag(m.ze);
}

TEST(Interp3W4, EveryEndPointOfTheCubeMatchesTheModel) {
  H4 h;
  Tally t{"interp3 W=4 exhaustive", 0, 0, 0, {}};
  const auto t0 = std::chrono::steady_clock::now();
  for (std::int64_t xe = -kMax4; xe <= kMax4; ++xe)
    for (std::int64_t ye = -kMax4; ye <= kMax4; ++ye)
      for (std::int64_t ze = -kMax4; ze <= kMax4; ++ze) {
        const Move3 m{xe, ye, ze};
        t.add(compare_move<4>(h, m), total(m));
      }
  t.print(since(t0));
  EXPECT_EQ(t.moves, 29791u);
  EXPECT_EQ(t.failed, 0u) << (t.reports.empty() ? "" : t.reports[0]);
}

// Every other model starts its registers at 0 (--x-initial fast). This one
// (--x-initial unique) starts them random (+verilator+rand+reset+2), a
// different draw per seed: after the reset the core must behave the same,
// so a register the reset misses (or a move that depends on state the
// load does not set) shows up here. Every 3rd end point of the cube,
// under 4 seeds, each on a fresh model.
TEST(Interp3W4, RandomInitialValuesDoNotMatter) {
  std::uint64_t moves = 0;
  for (int s = 1; s <= 4; ++s) {
    H4X h("", {"+verilator+rand+reset+2", "+verilator+seed+" + std::to_string(s)});
    Tally t{"interp3 W=4 random reset, seed " + std::to_string(s), 0, 0, 0, {}};
    const auto t0 = std::chrono::steady_clock::now();
    std::int64_t k = 0;
    for (std::int64_t xe = -kMax4; xe <= kMax4; ++xe)
      for (std::int64_t ye = -kMax4; ye <= kMax4; ++ye)
        for (std::int64_t ze = -kMax4; ze <= kMax4; ++ze)
          if (k++ % 3 == s % 3) {
            const Move3 m{xe, ye, ze};
            t.add(compare_move<4>(h, m), total(m));
          }
    t.print(since(t0));
    EXPECT_EQ(t.failed, 0u) << (t.reports.empty() ? "" : t.reports[0]);
    moves += t.moves;
  }
  EXPECT_GE(moves, 4 * (29791u / 3));
}

// The contract's properties, checked on the RTL's own outputs (not through
// the model): the three discriminant identities and their ranges, one
// unit step per command clock on an axis with distance left, exactly
// |XE| + |YE| + |ZE| pulses, the end point reached, and every point within
// sqrt(3)/2 pulse of the segment.
TEST(Interp3W4, RtlStatesSatisfyTheContractInvariants) {
  H4 h;
  std::uint64_t checked = 0;
  for (std::int64_t xe = -kMax4; xe <= kMax4; ++xe)
    for (std::int64_t ye = -kMax4; ye <= kMax4; ++ye)
      for (std::int64_t ze = -kMax4; ze <= kMax4; ++ze) {
        const std::int64_t A = xe < 0 ? -xe : xe, B = ye < 0 ? -ye : ye, C = ze < 0 ? -ze : ze;
        const std::int64_t sx = xe < 0 ? -1 : 1, sy = ye < 0 ? -1 : 1, sz = ze < 0 ? -1 : 1;
        const double L2 = static_cast<double>(A * A + B * B + C * C);
        h.load(xe, ye, ze);
        State3 prev = h.state();
        const std::string move = describe({xe, ye, ze});
        for (std::int64_t n = 0; n <= A + B + C; ++n) {
          const State3 s = h.state();
          const std::int64_t x = s.x * sx, y = s.y * sy, z = s.z * sz;
          ASSERT_TRUE(0 <= x && x <= A && 0 <= y && y <= B && 0 <= z && z <= C) << move << " " << show(s);
          ASSERT_EQ(s.dxy, A * (2 * y + 1) - B * (2 * x + 1)) << move << " " << show(s);
          ASSERT_EQ(s.dxz, A * (2 * z + 1) - C * (2 * x + 1)) << move << " " << show(s);
          ASSERT_EQ(s.dyz, B * (2 * z + 1) - C * (2 * y + 1)) << move << " " << show(s);
          ASSERT_TRUE(-2 * B <= s.dxy && s.dxy <= 2 * A) << move << " " << show(s);
          ASSERT_TRUE(-2 * C <= s.dxz && s.dxz <= 2 * A) << move << " " << show(s);
          ASSERT_TRUE(-2 * C <= s.dyz && s.dyz <= 2 * B) << move << " " << show(s);
          ASSERT_EQ(s.done, n == A + B + C) << move << " " << show(s);
          if (L2 > 0) {  // distance to the segment from the origin to (A, B, C)
            const double t = static_cast<double>(x * A + y * B + z * C) / L2;
            const double dx = static_cast<double>(x) - t * static_cast<double>(A);
            const double dy = static_cast<double>(y) - t * static_cast<double>(B);
            const double dz = static_cast<double>(z) - t * static_cast<double>(C);
            ASSERT_LE(dx * dx + dy * dy + dz * dz, 0.75 + 1e-9) << move << " " << show(s);
          }
          ++checked;
          if (n == A + B + C) break;
          const auto p = h.step(true);
          ASSERT_TRUE(p.has_value()) << move << ": no single pulse at command " << n + 1 << " (" << h.strobes()
                                     << " strobes)";
          const State3 q = h.state();
          const std::int64_t moved = (q.x != prev.x) + (q.y != prev.y) + (q.z != prev.z);
          ASSERT_EQ(moved, 1) << move;
          const std::int64_t dpos = (q.x - prev.x) + (q.y - prev.y) + (q.z - prev.z);
          const std::int64_t want = p->axis == Axis::X ? q.x - prev.x : p->axis == Axis::Y ? q.y - prev.y : q.z - prev.z;
          ASSERT_EQ(dpos, want) << move << ": the pulse " << to_string(*p) << " is not on the axis that moved";
          ASSERT_EQ(want, p->sign) << move << ": the pulse " << to_string(*p) << " has the wrong sign";
          prev = q;
        }
        // Command clocks after the end: nothing.
        for (int k = 0; k < 2; ++k) {
          ASSERT_FALSE(h.step(true).has_value()) << move << ": a pulse after the end";
          ASSERT_EQ(h.state().x, xe);
          ASSERT_EQ(h.state().y, ye);
          ASSERT_EQ(h.state().z, ze);
        }
      }
  std::printf("interp3 W=4 invariants: %llu states checked\n", static_cast<unsigned long long>(checked));
}

// docs/rtl-3axis.md's clock-by-clock example, worked by hand from the
// contract: (2, -1, 0) loads Exy = 1, Exz = 2, Eyz = 1 and pulses X, -Y, X;
// each pulse is on the outputs with the state after it; done comes with the
// last pulse; a command after the end gives nothing.
TEST(Interp3W4, DocumentedTimingOfTheMove2m10) {
  H4 h;
  h.load(2, -1, 0);
  EXPECT_EQ(h.strobes(), 0u);
  EXPECT_EQ(h.state(), (State3{0, 0, 0, 1, 2, 1, 0, false}));
  const std::optional<Pulse> p1 = h.step(true);
  EXPECT_EQ(p1, (Pulse{Axis::X, +1}));
  EXPECT_EQ(h.state(), (State3{1, 0, 0, -1, 2, 1, 1, false}));
  const std::optional<Pulse> p2 = h.step(true);
  EXPECT_EQ(p2, (Pulse{Axis::Y, -1}));
  EXPECT_EQ(h.state(), (State3{1, -1, 0, 3, 2, 1, 2, false}));
  const std::optional<Pulse> p3 = h.step(true);
  EXPECT_EQ(p3, (Pulse{Axis::X, +1}));
  EXPECT_EQ(h.state(), (State3{2, -1, 0, 1, 2, 1, 3, true}));
  EXPECT_FALSE(h.step(true).has_value());
  EXPECT_EQ(h.state(), (State3{2, -1, 0, 1, 2, 1, 3, true}));
  EXPECT_EQ(h.clocks(), 1u + 1u + 4u + 4u);  // reset, load, four preparing clocks, four command clocks
}

// The preparation after a load, clock by clock (docs/rtl-3axis.md,
// "Timing"): o_ready low for exactly four clocks, o_done already the new
// move's, and the command held high in those clocks moves nothing; the
// first pulse comes in the clock after the fifth edge from the load.
TEST(Interp3W4, CommandsWhilePreparingAreIgnored) {
  H4 h;
  h.load(-3, 0, 1);  // a move to abandon: its state must not leak
  ASSERT_TRUE(h.step(true).has_value());
  auto& t = h.top();
  t.i_xe = 2;
  t.i_ye = 1;
  t.i_ze = 0;
  t.i_xneg = 0;
  t.i_yneg = 1;
  t.i_zneg = 0;
  t.i_load = 1;
  t.i_cmd = 1;  // the load wins
  h.tick();
  t.i_load = 0;
  for (unsigned k = 0; k < 4; ++k) {
    EXPECT_FALSE(h.ready()) << "clock " << k;
    EXPECT_FALSE(h.done()) << "clock " << k;
    EXPECT_EQ(h.strobes(), 0u) << "clock " << k;
    EXPECT_EQ(t.o_x, 0u);
    EXPECT_EQ(t.o_y, 0u);
    t.i_cmd = 1;
    h.tick();
  }
  EXPECT_TRUE(h.ready());
  EXPECT_EQ(h.strobes(), 0u);
  const State3 s = h.state();  // its pulse count is the harness's, not the core's
  EXPECT_EQ((State3{s.x, s.y, s.z, s.dxy, s.dxz, s.dyz, 0, s.done}), (State3{0, 0, 0, 1, 2, 1, 0, false}));
  EXPECT_EQ(h.step(true), (Pulse{Axis::X, +1}));
  EXPECT_EQ(h.step(true), (Pulse{Axis::Y, -1}));
  EXPECT_EQ(h.step(true), (Pulse{Axis::X, +1}));
  EXPECT_TRUE(h.done());
  // The zero move: done from the clock after its load, ready four later.
  t.i_xe = t.i_ye = t.i_ze = 0;
  t.i_load = 1;
  h.tick();
  t.i_load = 0;
  EXPECT_TRUE(h.done());
  EXPECT_FALSE(h.ready());
}

// The command input low in random clocks (1/3 of them, or long holds):
// no pulse and no state change in those clocks.
TEST(Interp3W4, CommandGapsHoldTheState) {
  H4 h;
  std::mt19937_64 rng(seed());
  Tally t{"interp3 W=4 command gaps", 0, 0, 0, {}};
  const auto t0 = std::chrono::steady_clock::now();
  for (int i = 0; i < 3000; ++i) {
    std::uniform_int_distribution<std::int64_t> c(-kMax4, kMax4);
    const Move3 m{c(rng), c(rng), c(rng)};
    const std::uint64_t pattern = rng();
    const bool holds = i % 2;
    Compare3Options o;
    o.cmd = [pattern, holds](std::uint64_t k) {
      return holds ? ((k / 5) % 3 != 1) : ((pattern >> (k % 64)) & 3) != 0;
    };
    t.add(compare_move<4>(h, m, o), total(m));
  }
  t.print(since(t0));
  EXPECT_EQ(t.failed, 0u) << "seed " << seed() << "\n" << (t.reports.empty() ? "" : t.reports[0]);
}

TEST(Interp3W4, LoadInTheMiddleOfAMoveStartsTheNewOne) {
  H4 h;
  std::mt19937_64 rng(seed() + 1);
  std::uniform_int_distribution<std::int64_t> c(-kMax4, kMax4);
  for (int i = 0; i < 500; ++i) {
    const Move3 first{c(rng), c(rng), c(rng)}, second{c(rng), c(rng), c(rng)};
    Compare3Options o;
    o.max_pulses = 1 + rng() % 20;  // abandoned after this many pulses (or at its end)
    ASSERT_EQ(compare_move<4>(h, first, o), "");
    const std::string r = compare_move<4>(h, second);
    ASSERT_EQ(r, "") << "after " << describe(first) << " abandoned at pulse " << o.max_pulses << "\n" << r;
  }
}

TEST(Interp3W4, ResetInTheMiddleOfAMoveLeavesTheZeroMove) {
  H4 h;
  h.load(15, -7, 3);
  for (int k = 0; k < 9; ++k) ASSERT_TRUE(h.step(true).has_value());
  h.reset();
  const State3 zero{0, 0, 0, 0, 0, 0, 0, true};
  EXPECT_EQ(h.state(), zero);
  EXPECT_FALSE(h.step(true).has_value());
  EXPECT_EQ(compare_move<4>(h, Move3{-15, 7, -3}), "");
}

TEST(Interp3W4, RejectsAMoveOutsideTheDomain) {
  H4 h;
  EXPECT_THROW(h.load(16, 0, 0), InputError);
  EXPECT_THROW(h.load(0, 0, -16), InputError);
  try {
    h.load(0, 16, 0);
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "YE = 16 is out of range: |YE| must be <= 2^4 - 1 = 15");
  }
}

// The checker itself: a difference must be reported at the first clock
// where the two sides differ, with both sides' values and the context.
TEST(Interp3W4, ReportNamesTheFirstDifferenceAndBothSides) {
  H4 h;
  // (3, 1, 0) loads Exy = 2, (1, 3, 0) Exy = -2: different from the load.
  const std::string r = compare_move<4>(h, Move3{3, 1, 0}, Move3{1, 3, 0});
  ASSERT_NE(r, "");
  EXPECT_NE(r.find("move (3, 1, 0) at W = 4 (model: (1, 3, 0)): first difference at command clock 0"),
            std::string::npos)
      << r;
  EXPECT_NE(r.find("model -- x=0 y=0 z=0 Exy=-2 Exz=1 Eyz=3 n=0 done=0"), std::string::npos) << r;
  EXPECT_NE(r.find("rtl -- x=0 y=0 z=0 Exy=2 Exz=3 Eyz=1 n=0 done=0"), std::string::npos) << r;
}

TEST(Interp3W4, ReportShowsThePulsesAroundTheDifference) {
  H4 h;
  // (5, 3, 1) and (6, 4, 2) load the same state (origin, Exy = 2, Exz = 4,
  // Eyz = 2) and both step X first; then Exy -= 2B differs (-4 and -6).
  const std::string r = compare_move<4>(h, Move3{5, 3, 1}, Move3{6, 4, 2});
  ASSERT_NE(r, "");
  EXPECT_NE(r.find("first difference at command clock 1, model pulse 1"), std::string::npos) << r;
  EXPECT_NE(r.find(">     1  1  model +X x=1 y=0 z=0 Exy=-6 Exz=0 Eyz=2 n=1 done=0"), std::string::npos) << r;
  EXPECT_NE(r.find("!  rtl +X x=1 y=0 z=0 Exy=-4 Exz=2 Eyz=2 n=1 done=0"), std::string::npos) << r;
  // Context: the load (clock 0) before, two clocks after.
  EXPECT_NE(r.find("      0  0  model --"), std::string::npos) << r;
  EXPECT_NE(r.find("      3  1  model"), std::string::npos) << r;
  EXPECT_EQ(r.find("      4  1  model"), std::string::npos) << r;
  std::printf("example report:\n%s", r.c_str());
}

// W = 24: a magnitude from a random size class: 0, 1, 2^k - 1, 2^k, or
// uniform below 2^k, for k up to `kmax`.
std::int64_t random_magnitude(std::mt19937_64& rng, unsigned kmax) {
  const unsigned k = static_cast<unsigned>(rng() % (kmax + 1));
  switch (rng() % 6) {
    case 0: return 0;
    case 1: return 1;
    case 2: return (std::int64_t{1} << k) - 1;
    case 3: return std::int64_t{1} << k;
    default: return static_cast<std::int64_t>(rng() % (std::uint64_t{1} << k));
  }
}

TEST(Interp3W24, RandomMovesMatchTheModel) {
  H24 h;
  std::mt19937_64 rng(seed() + 24);
  Tally t{"interp3 W=24 random", 0, 0, 0, {}};
  const int moves = full_run() ? 5000 : 600;
  const auto t0 = std::chrono::steady_clock::now();
  for (int i = 0; i < moves; ++i) {
    auto pick = [&] {
      const std::int64_t v = random_magnitude(rng, 16);
      return (rng() & 1) ? -v : v;
    };
    const Move3 m{pick(), pick(), pick()};
    t.add(compare_move<24>(h, m), total(m));
  }
  t.print(since(t0));
  EXPECT_EQ(t.failed, 0u) << "seed " << seed() << "\n" << (t.reports.empty() ? "" : t.reports[0]);
}

// The extreme loads: every combination of {0, 1, 2^23, 2^24 - 2, 2^24 - 1}
// per axis, both signs: the first 3000 pulses of each (the discriminants
// start at their widest: |A - B| up to 2^24 - 1, and take steps of
// 2 (2^24 - 1)), then the last pulses of the ones short enough.
TEST(Interp3W24, ExtremeMovesMatchTheModelOnTheirFirstPulses) {
  H24 h;
  const std::int64_t mags[] = {0, 1, std::int64_t{1} << 23, kMax24 - 1, kMax24};
  Tally t{"interp3 W=24 extremes (first 3000 pulses)", 0, 0, 0, {}};
  const auto t0 = std::chrono::steady_clock::now();
  std::mt19937_64 rng(seed() + 3);
  for (auto a : mags)
    for (auto b : mags)
      for (auto c : mags) {
        const Move3 m{(rng() & 1) ? -a : a, (rng() & 1) ? -b : b, (rng() & 1) ? -c : c};
        Compare3Options o;
        o.max_pulses = 3000;
        t.add(compare_move<24>(h, m, o), std::min<std::uint64_t>(3000, total(m)));
      }
  t.print(since(t0));
  EXPECT_EQ(t.moves, 125u);
  EXPECT_EQ(t.failed, 0u) << (t.reports.empty() ? "" : t.reports[0]);
}

// Complete full-range moves: every pulse of a move whose ends are 2^24 - 1,
// through the widest discriminant values to the end point.
TEST(Interp3W24, FullRangeMovesMatchTheModelToTheEnd) {
  H24 h;
  std::vector<Move3> moves = {{kMax24, -kMax24, kMax24}, {-kMax24, 1, std::int64_t{1} << 23}};
  if (full_run()) {
    moves.push_back({kMax24, 0, 0});
    moves.push_back({0, -kMax24, kMax24 - 1});
    moves.push_back({1, kMax24 - 1, -kMax24});
    moves.push_back({-(std::int64_t{1} << 23), kMax24, 3});
  }
  Tally t{"interp3 W=24 full range", 0, 0, 0, {}};
  const auto t0 = std::chrono::steady_clock::now();
  for (const auto& m : moves) t.add(compare_move<24>(h, m), total(m));
  t.print(since(t0));
  EXPECT_EQ(t.failed, 0u) << (t.reports.empty() ? "" : t.reports[0]);
}

TEST(Interp3W24, RejectsAMoveOutsideTheDomain) {
  H24 h;
  try {
    h.load(0, 0, kMax24 + 1);
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "ZE = 16777216 is out of range: |ZE| must be <= 2^24 - 1 = 16777215");
  }
}

}  // namespace
}  // namespace contour::rtl3
