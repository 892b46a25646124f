// Regression of the Verilated interp_core against the golden model:
// pulse by pulse and state by state (x, y, D, quadrant, crossings left,
// done), exhaustive at W = 8, random at W = 24 with the extremes, back to
// back through the queue, reset and abort in the middle of a move.
//
// CONTOUR_FULL=1: every arc end point of every radius at W = 8 (long).
// CONTOUR_FST=FILE: FST trace of the harness (use with --gtest_filter).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>

#include "Vinterp_w24.h"
#include "Vinterp_w8.h"
#include "compare.hpp"
#include "interp/engine.hpp"

namespace contour {
namespace {

using rtl::Block;
using rtl::CoreHarness;
using rtl::make_block;
using tb::lockstep;
using H8 = CoreHarness<Vinterp_w8, 8>;
using H24 = CoreHarness<Vinterp_w24, 24>;

// CONTOUR_FULL=1 (set, not empty, not 0): the long runs.
bool full_run() {
  const char* e = std::getenv("CONTOUR_FULL");
  return e != nullptr && *e != '\0' && *e != '0';
}

// Runs `m` on the harness and on the model in lock step, at most `limit`
// pulses, comparing the initial state, every pulse and the state after it,
// and (for a whole run) the end. Memory stays flat however long the move.
// On a mismatch: the first differing pulse with both sides' values and a
// few pulses of context; the trace is closed there.
template <class H>
std::optional<std::string> check_move(H& h, const Move& m, std::uint64_t limit = ~std::uint64_t{0}) {
  constexpr unsigned W = H::kWidth;
  const Block b = make_block<W>(m);
  if (m.is_arc()) {
    Circular<W> model(m.xs, m.ys, m.xe, m.ye, m.sense);
    return lockstep(h, m, b, model, limit);
  }
  Linear<W> model(m.xe, m.ye);
  return lockstep(h, m, b, model, limit);
}

// Runs a list of moves and reports the first few failures, with a summary
// line first ("100.00% PASS 12 PASSED, 0 FAILED").
template <class H>
void check_all(H& h, const std::vector<Move>& moves, std::uint64_t limit = ~std::uint64_t{0}) {
  std::size_t failed = 0;
  std::string first;
  for (const Move& m : moves) {
    if (auto d = check_move(h, m, limit)) {
      if (failed < 3) first += *d + "\n";
      ++failed;
    }
  }
  if (failed) {
    ADD_FAILURE() << 100.0 * double(moves.size() - failed) / double(moves.size()) << "% PASS "
                  << moves.size() - failed << " PASSED, " << failed << " FAILED\n"
                  << first;
  }
}


// ------------------------------------------------------------ paper examples

TEST(InterpCore, PaperLine6x5) {
  H24 h;
  const Move m = Move::line(6, 5);
  EXPECT_EQ(check_move(h, m), std::nullopt);
  // Fig. 2 of paper A: X Y X Y X Y X Y X Y X.
  const RunResult r = h.run(make_block<24>(m), 100);
  std::string seq;
  for (const auto& s : r.steps) seq += to_string(s.pulse) + " ";
  EXPECT_EQ(seq, "+X +Y +X +Y +X +Y +X +Y +X +Y +X ");
}

TEST(InterpCore, PaperArc6QuarterCcw) {
  H24 h;
  const Move m = Move::arc(6, 0, 0, 6, Sense::CCW);
  EXPECT_EQ(check_move(h, m), std::nullopt);
  // Fig. 5 of paper A: the pulses and D after each.
  const RunResult r = h.run(make_block<24>(m), 100);
  const std::vector<std::string> want_p{"-X", "+Y", "+Y", "+Y", "+Y", "-X", "+Y", "-X", "+Y", "-X", "-X", "-X"};
  const std::vector<std::int64_t> want_d{-11, -10, -7, -2, 5, -4, 5, -2, 9, 4, 1, 0};
  ASSERT_EQ(r.steps.size(), want_p.size());
  for (std::size_t i = 0; i < want_p.size(); ++i) {
    EXPECT_EQ(to_string(r.steps[i].pulse), want_p[i]) << "pulse " << i + 1;
    EXPECT_EQ(r.steps[i].state.d, want_d[i]) << "pulse " << i + 1;
  }
  EXPECT_TRUE(r.final_state.done);
}

TEST(InterpCore, ZeroLineIsDoneWithoutPulses) {
  H8 h;
  const RunResult r = h.run(make_block<8>(Move::line(0, 0)), 10);
  EXPECT_TRUE(r.steps.empty());
  EXPECT_TRUE(r.initial_state.done);
  EXPECT_EQ(check_move(h, Move::line(0, 0)), std::nullopt);
}

// --------------------------------------------------------- exhaustive W = 8

TEST(InterpCoreW8, EveryLineEndPoint) {
  H8 h;
  constexpr std::int64_t M = Linear<8>::kMax;
  std::vector<Move> moves;
  moves.reserve((2 * M + 1) * (2 * M + 1));
  for (std::int64_t xe = -M; xe <= M; ++xe)
    for (std::int64_t ye = -M; ye <= M; ++ye) moves.push_back(Move::line(xe, ye));
  check_all(h, moves);
}

// Full circles from every start point of radius class: (R, 0) and the
// three other axis points, both senses, every R with R^2 >= 2.
TEST(InterpCoreW8, FullCirclesEveryRadius) {
  H8 h;
  constexpr std::int64_t M = Circular<8>::kMax;
  std::vector<Move> moves;
  for (std::int64_t r = 1; r <= M; ++r) {
    const std::int64_t pts[5][2] = {{r, 0}, {0, r}, {-r, 0}, {0, -r}, {r, r / 2 + 1}};
    for (const auto& p : pts) {
      if (p[0] * p[0] + p[1] * p[1] < 2 || std::abs(p[0]) > M || std::abs(p[1]) > M) continue;
      if (p[0] * p[0] + p[1] * p[1] > M * M) continue;
      for (Sense s : {Sense::CCW, Sense::CW}) moves.push_back(Move::arc(p[0], p[1], p[0], p[1], s));
    }
  }
  check_all(h, moves);
}

// Points of the circle x^2 + y^2 = r2 rounded to integers: for every x,
// y = +-round(sqrt(r2 - x^2)), and the same with the axes swapped.
std::vector<std::pair<std::int64_t, std::int64_t>> rounded_points(std::int64_t r2) {
  std::vector<std::pair<std::int64_t, std::int64_t>> v;
  const auto r = static_cast<std::int64_t>(std::floor(std::sqrt(double(r2))));
  for (std::int64_t a = -r; a <= r; ++a) {
    const auto b = static_cast<std::int64_t>(std::llround(std::sqrt(double(r2 - a * a))));
    for (std::int64_t sb : {b, -b}) {
      v.push_back({a, sb});
      v.push_back({sb, a});
    }
  }
  return v;
}

// Arcs of every radius, both senses, from a start on the +X axis and from
// one a third of the way round, to the rounded points of the circle
// (every `stride`-th one; all of them with CONTOUR_FULL=1). Ends that
// Circular<8>::validate, the host's check, refuses are skipped.
TEST(InterpCoreW8, ArcsEveryRadiusBothSenses) {
  H8 h;
  constexpr std::int64_t M = Circular<8>::kMax;
  const std::size_t stride = full_run() ? 1 : 23;
  std::vector<Move> moves;
  std::size_t rejected = 0;
  for (std::int64_t r = 2; r <= M; ++r) {
    for (Sense s : {Sense::CCW, Sense::CW}) {
      const RunResult circle = run_model<8>(Move::arc(r, 0, r, 0, s));
      const auto& third = circle.steps[circle.steps.size() / 3].state;
      const std::int64_t starts[2][2] = {{r, 0}, {third.x, third.y}};
      for (const auto& st : starts) {
        const auto ends = rounded_points(st[0] * st[0] + st[1] * st[1]);
        for (std::size_t i = std::size_t(r * 7) % stride; i < ends.size(); i += stride) {
          const Move m = Move::arc(st[0], st[1], ends[i].first, ends[i].second, s);
          try {
            validate<8>(m);
            moves.push_back(m);
          } catch (const InputError&) {
            ++rejected;
          }
        }
      }
    }
  }
  // Rounded points are acceptable ends but for a few; a broken generator
  // would not be.
  EXPECT_GT(moves.size(), 4 * rejected);
  check_all(h, moves);
}

// ------------------------------------------------------------ random W = 24

// A seeded source of moves' coordinates: uniform in [-lim, lim], the same
// sequence every run; `rng` for the other random choices of a test.
struct Coords {
  explicit Coords(std::uint64_t seed) : rng(seed) {}
  std::int64_t operator()(std::int64_t lim) { return std::int64_t(rng() % (2 * lim + 1)) - lim; }
  std::mt19937_64 rng;
};

TEST(InterpCoreW24, RandomLinesAndExtremes) {
  H24 h;
  constexpr std::int64_t M = Linear<24>::kMax;
  Coords any(20260124);
  std::vector<Move> moves;
  for (int i = 0; i < 400; ++i) moves.push_back(Move::line(any(3000), any(3000)));
  for (int i = 0; i < 40; ++i) moves.push_back(Move::line(any(M), any(200)));
  for (int i = 0; i < 40; ++i) moves.push_back(Move::line(any(200), any(M)));
  check_all(h, moves, 60000);
  // The extremes, cut after 200k pulses (D reaches its bounds at once).
  const std::vector<Move> ext{Move::line(M, M),     Move::line(-M, M),    Move::line(M, 1 - M),
                              Move::line(-M, -M),   Move::line(M, 1),     Move::line(1, -M),
                              Move::line(M, M - 1), Move::line(-(M - 1), M)};
  check_all(h, ext, 200000);
  // Two whole extreme lines.
  check_all(h, {Move::line(-M, 3), Move::line(2, M)});
}

TEST(InterpCoreW24, RandomArcsAndExtremes) {
  H24 h;
  constexpr std::int64_t M = Circular<24>::kMax;
  Coords coord(20260125);
  std::mt19937_64& rng = coord.rng;
  std::vector<Move> moves;
  std::size_t small_arcs = 0, large_arcs = 0;
  // Small circles, whole.
  for (int i = 0; i < 120; ++i) {
    const std::int64_t xs = coord(600), ys = coord(600);
    if (xs * xs + ys * ys < 2) continue;
    const Sense s = rng() & 1 ? Sense::CW : Sense::CCW;
    const auto ends = rounded_points(xs * xs + ys * ys);
    const auto& e = ends[rng() % ends.size()];
    const Move m = Move::arc(xs, ys, e.first, e.second, s);
    try {
      validate<24>(m);
      moves.push_back(m);
      ++small_arcs;
    } catch (const InputError&) {
    }
    if (i % 4 == 0) moves.push_back(Move::arc(xs, ys, xs, ys, s));
  }
  // Large radii up to the maximum, started next to an axis so that the
  // run crosses quadrants; ends taken from the model's walk.
  for (int i = 0; i < 60; ++i) {
    const std::int64_t r = i < 10 ? M - i : std::int64_t(rng() % std::uint64_t(M)) + 2;
    const std::int64_t off = std::int64_t(rng() % 3000);
    std::int64_t xs = r, ys = off;
    if (xs > M) xs = M;
    switch (i % 4) {
      case 1: std::swap(xs, ys); xs = -xs; break;
      case 2: xs = -xs; ys = -ys; break;
      case 3: std::swap(xs, ys); ys = -ys; break;
      default: break;
    }
    const Sense s = rng() & 1 ? Sense::CW : Sense::CCW;
    if (xs * xs + ys * ys > M * M) continue;
    // Walk 3000..9000 pulses and end there.
    Circular<24> c(xs, ys, xs, ys, s);
    const std::uint64_t n = 3000 + rng() % 6000;
    for (std::uint64_t k = 0; k < n; ++k) c.step();
    const Move m = Move::arc(xs, ys, c.state().x, c.state().y, s);
    try {
      validate<24>(m);
      moves.push_back(m);
      ++large_arcs;
    } catch (const InputError&) {
    }
  }
  // Each filtered sweep on its own (an all-rejected sweep must not pass).
  std::printf("small arcs %zu, large arcs %zu\n", small_arcs, large_arcs);
  EXPECT_GE(small_arcs, 100u);  // 120 with this seed
  EXPECT_GE(large_arcs, 25u);  // 30 with this seed (half the starts lie outside R = M)
  EXPECT_GT(moves.size(), 150u);
  check_all(h, moves);
  // Full circles of the largest radii, cut after 100k pulses.
  check_all(h, {Move::arc(M, 0, M, 0, Sense::CCW), Move::arc(0, -M, 0, -M, Sense::CW),
                Move::arc(M - 1, 1, M - 1, 1, Sense::CW)},
            100000);
}

// -------------------------------------------------------- queue and control

// Blocks queued ahead run back to back: with the command held high every
// clock from the first pulse to the last carries a pulse, and the pulses
// are the concatenation of the model's.
// Queued blocks, run with the command held high: the model's pulses and
// states, the last pulse of each block flagged, no idle clock between.
template <class H, int W>
void expect_back_to_back(const std::vector<Move>& moves) {
  H h;
  std::vector<Pulse> want;
  std::vector<State> want_state;
  std::vector<bool> want_last;
  for (const Move& m : moves) {
    const RunResult r = run_model<W>(m);
    for (std::size_t i = 0; i < r.steps.size(); ++i) {
      want.push_back(r.steps[i].pulse);
      State s = r.steps[i].state;
      s.pulses = 0;
      want_state.push_back(s);
      want_last.push_back(i + 1 == r.steps.size());
    }
  }
  for (const Move& m : moves) ASSERT_TRUE(h.push(make_block<W>(m)));
  h.top().i_cmd = 1;
  std::vector<rtl::Observed> got;
  std::uint64_t first = 0, gaps = 0;
  for (std::size_t c = 0; c < want.size() + 40 && got.size() < want.size(); ++c) {
    h.tick();
    if (auto o = h.pulse()) {
      if (got.empty()) first = h.clocks();
      got.push_back(*o);
    } else if (!got.empty()) {
      ++gaps;
    }
  }
  ASSERT_EQ(got.size(), want.size());
  EXPECT_EQ(gaps, 0u) << "idle clocks between queued blocks";
  EXPECT_EQ(got.back().cycle - first + 1, want.size());
  for (std::size_t i = 0; i < want.size(); ++i) {
    ASSERT_EQ(got[i].pulse, want[i]) << "pulse " << i + 1;
    ASSERT_EQ(got[i].last, want_last[i]) << "pulse " << i + 1;
    // The state after a block's last pulse is replaced by the next block
    // in the same clock; every other state is compared.
    if (!want_last[i]) {
      State s = got[i].state;
      ASSERT_EQ(s, want_state[i]) << "pulse " << i + 1;
    }
  }
  h.tick();
  EXPECT_FALSE(h.top().o_busy);
  EXPECT_FALSE(h.top().o_pulse);
}

TEST(InterpCore, BackToBackBlocksHaveNoGap) {
  expect_back_to_back<H8, 8>({Move::line(6, 5), Move::arc(6, 0, 0, 6, Sense::CCW), Move::line(-3, 7),
                              Move::line(1, 0), Move::arc(5, 5, 5, 5, Sense::CW), Move::line(0, -1),
                              Move::arc(2, 1, -2, 1, Sense::CCW), Move::line(255, -255)});
}

// The same at W = 24 (the width of the synthesized core): arcs of a
// radius near 2^24 whose magnitudes use the high bits, one crossing the
// X axis, between short lines.
TEST(InterpCoreW24, BackToBackBlocksHaveNoGap) {
  expect_back_to_back<H24, 24>({walked_arc(16000000, 5, Sense::CCW, 3000), Move::line(0, 1),
                                walked_arc(-16000000, 1000, Sense::CCW, 3000), Move::line(-2999, 3000),
                                Move::arc(3, 4, -4, 3, Sense::CCW), Move::line(-1, 0)});
}

// Command low: nothing moves; command high again: the run continues where
// it stopped. Pulses equal the model's however the command is gated.
TEST(InterpCore, CommandGatingKeepsTheSequence) {
  H8 h;
  std::mt19937 rng(7);
  for (const Move& m : {Move::line(-200, 77), Move::arc(100, 30, 100, 30, Sense::CW)}) {
    const RunResult model = run_model<8>(m);
    ASSERT_TRUE(h.push(make_block<8>(m)));
    h.drain_queue();
    std::vector<StepRecord> got;
    for (int c = 0; c < 40000 && h.top().o_busy; ++c) {
      h.top().i_cmd = (rng() % 3) != 0;
      h.tick();
      if (auto o = h.pulse()) {
        o->state.pulses = got.size() + 1;
        got.push_back({o->pulse, o->state});
      }
    }
    ASSERT_EQ(got.size(), model.steps.size());
    for (std::size_t i = 0; i < got.size(); ++i) {
      ASSERT_EQ(got[i].pulse, model.steps[i].pulse) << describe(m) << " pulse " << i + 1;
      ASSERT_EQ(got[i].state, model.steps[i].state) << describe(m) << " pulse " << i + 1;
    }
    h.top().i_cmd = 0;
    h.tick();
  }
}

// Reset and abort in the middle of a move: no further pulse, an empty
// queue, and the next move runs exactly as the model says.
TEST(InterpCore, ResetAndAbortInTheMiddleOfAMove) {
  H24 h;
  for (int kind = 0; kind < 2; ++kind) {
    ASSERT_TRUE(h.push(make_block<24>(Move::arc(1000, 0, 1000, 0, Sense::CCW))));
    ASSERT_TRUE(h.push(make_block<24>(Move::line(500, 500))));
    h.top().i_cmd = 1;
    int seen = 0;
    for (int c = 0; c < 1234; ++c) {
      h.tick();
      seen += h.top().o_pulse;
    }
    EXPECT_GT(seen, 1000);
    EXPECT_TRUE(h.top().o_busy);
    if (kind == 0) {
      h.top().i_rst = 1;
      h.tick();
      h.top().i_rst = 0;
    } else {
      h.top().i_abort = 1;
      h.tick();
      h.top().i_abort = 0;
    }
    EXPECT_FALSE(h.top().o_busy);
    EXPECT_EQ(h.top().o_level, 0);
    for (int c = 0; c < 100; ++c) {
      h.tick();
      EXPECT_FALSE(h.top().o_pulse) << (kind ? "abort" : "reset") << " clock " << c;
    }
    h.top().i_cmd = 0;
    EXPECT_EQ(check_move(h, Move::arc(7, 2, -7, -2, Sense::CW)), std::nullopt);
  }
}

// A full queue refuses a block (o_full), keeps the ones it has, and the
// refused block produces no pulses.
TEST(InterpCore, FullQueueRefusesAndKeepsTheRest) {
  H8 h;
  int accepted = 0;
  for (int i = 0; i < 30; ++i) accepted += h.push(make_block<8>(Move::line(1 + i % 3, 0)));
  // 16 in the queue memory, one at its output, one in the datapath.
  EXPECT_EQ(accepted, 18);
  EXPECT_TRUE(h.top().o_full);
  std::uint64_t want = 0;
  for (int i = 0; i < accepted; ++i) want += 1 + i % 3;
  h.top().i_cmd = 1;
  std::uint64_t n = 0;
  for (int c = 0; c < 200; ++c) {
    h.tick();
    n += h.top().o_pulse;
  }
  EXPECT_EQ(n, want);
  EXPECT_FALSE(h.top().o_busy);
  EXPECT_EQ(h.top().o_level, 0);
}

}  // namespace
}  // namespace contour
