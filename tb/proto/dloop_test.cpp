// rtl/proto/dloop (the step loop prototypes, docs/rtl-proto.md: dloop two
// steps ahead, dloop1 one) against the closed forms of docs/algorithm.md, not its own recurrence:
//
//   arc (Q1 CCW, inward axis X, start (x0, y0), R^2 = x0^2 + y0^2):
//     the choice of a step is D >= 0 with D = x^2 + y^2 - R^2 before it;
//     inward x -= 1, outward y += 1; after it D == x^2 + y^2 - R^2.
//     Runs until just before x would reach 0 (x == 1 and D >= 0).
//   line (SUB = B, ADD = A): inward x += 1, outward y += 1,
//     D == A y - B x after every step.
//
// Each step's o_pulse, o_g and o_d are checked; commands come with random
// gaps (a clock without a command must change nothing). The arc of
// R = 2^23 from the X axis runs whole (16.8 M steps, ~2 s).
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>
#include <algorithm>

#include "Vdloop.h"
#include "Vdloop1.h"
#include "Vdloop1l.h"
#include "Vdloop1x.h"
#include "harness.hpp"

namespace {

constexpr unsigned kW = 24;
constexpr unsigned kN = kW + 2;  // width of D

// CONTOUR_FULL=1 (set, not empty, not 0): the long runs.
bool full_run() {
  const char* e = std::getenv("CONTOUR_FULL");
  return e != nullptr && *e != '\0' && *e != '0';
}

std::uint64_t seed() {
  const char* e = std::getenv("CONTOUR_SEED");
  return e ? std::strtoull(e, nullptr, 10) : 1982;
}

// What every prototype's harness has: no load and no command after the
// reset, and D read back sign-extended.
template <class V>
class ProtoHarness : public contour::tb::Harness<V> {
 public:
  using contour::tb::Harness<V>::top;
  using contour::tb::Harness<V>::tick;
  ProtoHarness() {
    top().i_load = 0;
    top().i_cmd = 0;
    this->hold_reset(1);
  }

  // o_d, sign-extended.
  std::int64_t d() const {
    std::int64_t v = static_cast<std::int64_t>(top().o_d);
    if (v & (std::int64_t{1} << (kN - 1))) v -= std::int64_t{1} << kN;
    return v;
  }
};

template <class V>
class Dloop : public ProtoHarness<V> {
 public:
  using ProtoHarness<V>::top;
  using ProtoHarness<V>::tick;
  using ProtoHarness<V>::d;

  // Load; returns "" or what went wrong (not ready, D != 0).
  std::string load(bool arc, std::uint64_t sub, std::uint64_t add) {
    top().i_arc = arc;
    top().i_sub = static_cast<std::uint32_t>(sub);
    top().i_add = static_cast<std::uint32_t>(add);
    top().i_load = 1;
    top().i_cmd = 1;  // ignored until ready
    tick();
    top().i_load = 0;
    for (unsigned k = 0; !top().o_ready; ++k) {
      if (k == 4) return "not ready 4 clocks after the load";
      if (top().o_pulse) return "a pulse while preparing";
      tick();
    }
    if (top().o_pulse) return "a pulse while preparing";
    if (d() != 0) return "D = " + std::to_string(d()) + " after the load";
    return "";
  }

  // One step (after `gap` clocks without a command); returns the choice,
  // or -1 if the clocks did not behave (pulse without a command, D moved,
  // no pulse after the command).
  int step(unsigned gap) {
    const std::int64_t before = d();
    top().i_cmd = 0;
    for (unsigned i = 0; i < gap; ++i) {
      tick();
      if (top().o_pulse || d() != before) return -1;
    }
    top().i_cmd = 1;
    tick();
    top().i_cmd = 0;
    if (!top().o_pulse) return -1;
    return top().o_g ? 1 : 0;
  }
};

struct Outcome {
  std::string name;
  std::uint64_t steps = 0;
  std::string error;  // the first mismatch
};

std::string where(const Outcome& r, const char* what, std::int64_t x, std::int64_t y, std::int64_t got,
                  std::int64_t want) {
  std::ostringstream s;
  s << r.name << ": step " << r.steps << " at (" << x << ", " << y << "): " << what << " " << got
    << ", expected " << want;
  return s.str();
}

// Steps from (x, y) after a load: before each step, stop when `stop(x, y,
// D)` holds; the choice must be D >= 0 (the closed form `d(x, y)`), an
// inward step (choice 1) applies `in` to (x, y), an outward one `out`, and
// the prototype's D after the step must be d(x, y) again.
template <class H, class D, class Stop, class In, class Out>
Outcome walk(H& h, std::mt19937_64& rng, Outcome r, std::int64_t x, std::int64_t y, std::uint64_t max_steps, D d,
             Stop stop, In in, Out out) {
  while (r.steps < max_steps) {
    const std::int64_t dbefore = d(x, y);
    if (stop(x, dbefore)) break;
    const int g = h.step(rng() % 4 == 0 ? static_cast<unsigned>(rng() % 3) : 0u);
    ++r.steps;
    if (g < 0) {
      r.error = where(r, "pulse/hold misbehaved, D", x, y, h.d(), dbefore);
      return r;
    }
    if (g != (dbefore >= 0 ? 1 : 0)) {
      r.error = where(r, "choice", x, y, g, dbefore >= 0);
      return r;
    }
    if (g) in(x, y); else out(x, y);
    const std::int64_t want = d(x, y);
    if (h.d() != want) {
      r.error = where(r, "D", x, y, h.d(), want);
      return r;
    }
  }
  return r;
}

// Loads a block; an Outcome named `name`, with the load's error if any.
template <class H>
Outcome loaded(H& h, std::string name, bool arc, std::int64_t sub, std::int64_t add) {
  Outcome r;
  r.name = std::move(name);
  const std::string e = h.load(arc, static_cast<std::uint64_t>(sub), static_cast<std::uint64_t>(add));
  if (!e.empty()) r.error = r.name + ": " + e;
  return r;
}

// The arc from (x0, y0), Q1 CCW: SUB = 2 x0 - 1, ADD = 2 y0 + 1; D =
// x^2 + y^2 - R^2, inward is -X, outward +Y; up to just before x reaches 0.
template <class H>
Outcome arc(H& h, std::mt19937_64& rng, std::int64_t x0, std::int64_t y0, std::uint64_t max_steps) {
  Outcome r = loaded(h, "arc from (" + std::to_string(x0) + ", " + std::to_string(y0) + ")", true, 2 * x0 - 1,
                     2 * y0 + 1);
  if (!r.error.empty()) return r;
  const std::int64_t r2 = x0 * x0 + y0 * y0;
  return walk(
      h, rng, r, x0, y0, max_steps, [r2](std::int64_t x, std::int64_t y) { return x * x + y * y - r2; },
      // the next step would reach the axis
      [](std::int64_t x, std::int64_t dbefore) { return x == 1 && dbefore >= 0; },
      [](std::int64_t& x, std::int64_t&) { --x; }, [](std::int64_t&, std::int64_t& y) { ++y; });
}

// The line with constants A (outward), B (inward) from the origin: D =
// A y - B x, inward is +X, outward +Y.
template <class H>
Outcome line(H& h, std::mt19937_64& rng, std::int64_t a, std::int64_t b, std::uint64_t max_steps) {
  Outcome r = loaded(h, "line A = " + std::to_string(a) + ", B = " + std::to_string(b), false, b, a);
  if (!r.error.empty()) return r;
  return walk(
      h, rng, r, 0, 0, max_steps, [a, b](std::int64_t x, std::int64_t y) { return a * y - b * x; },
      [](std::int64_t, std::int64_t) { return false; }, [](std::int64_t& x, std::int64_t&) { ++x; },
      [](std::int64_t&, std::int64_t& y) { ++y; });
}

template <class V>
void check_all(const char* name) {
  Dloop<V> h;
  std::mt19937_64 rng(seed());
  std::uint64_t runs = 0, steps = 0, failed = 0;
  std::string first;
  auto tally = [&](const Outcome& r) {
    ++runs;
    steps += r.steps;
    if (!r.error.empty() && ++failed == 1) first = r.error;
  };
  constexpr std::int64_t kMaxMag = (std::int64_t{1} << kW) - 1;  // |x|, |y| of the contract
  constexpr std::uint64_t kAll = ~std::uint64_t{0};

  // Arcs from the X axis, whole quadrant: small R, both sides of the split
  // of the sums (2^13), big R.
  for (std::int64_t r : {std::int64_t{1}, std::int64_t{2}, std::int64_t{3}, std::int64_t{4}, std::int64_t{5},
                         std::int64_t{6}, std::int64_t{7}, std::int64_t{10}, std::int64_t{25}, std::int64_t{100},
                         std::int64_t{1000}, std::int64_t{4095}, std::int64_t{4096}, std::int64_t{4097},
                         std::int64_t{8191}, std::int64_t{8192}, std::int64_t{65537}, std::int64_t{1000003},
                         std::int64_t{1} << 23})
    tally(arc(h, rng, r, 0, kAll));
  // Arcs from the X axis, the first 300 000 steps.
  for (std::int64_t r : {(std::int64_t{1} << 23) - 1, std::int64_t{6000001}}) tally(arc(h, rng, r, 0, 300000));
  // The ends of big quadrants: x small, y up to 2^24 - 1 (operands of 25
  // bits, D near the ends of its W + 2 bits), to the axis.
  for (std::int64_t x0 : {1, 2, 3, 50, 5792, 20000})
    tally(arc(h, rng, x0, kMaxMag - 30, kAll));
  tally(arc(h, rng, 5792, 8386815, kAll));  // on the integer circle R = 8386817
  // Random starts (any point: R^2 = x0^2 + y0^2), to the axis or 100 000 steps.
  for (int i = 0; i < (full_run() ? 400 : 40); ++i) {
    const unsigned bits = 1 + static_cast<unsigned>(rng() % 23);
    const std::int64_t x0 = 1 + static_cast<std::int64_t>(rng() % (std::uint64_t{1} << bits));
    const std::int64_t y0 = static_cast<std::int64_t>(rng() % (std::uint64_t{1} << bits));
    tally(arc(h, rng, x0, y0, 100000));
  }
  // Lines: whole small ones, the first 200 000 steps of big ones.
  for (auto [a, b] : {std::pair<std::int64_t, std::int64_t>{1, 1}, {3, 5}, {5, 3}, {7, 2}, {1, 9},
                      {4096, 8191}, {8193, 12}, {123457, 98765}})
    tally(line(h, rng, a, b, static_cast<std::uint64_t>(a + b)));
  for (auto [a, b] : {std::pair<std::int64_t, std::int64_t>{kMaxMag, kMaxMag}, {kMaxMag, 1}, {1, kMaxMag},
                      {12345678, 9876543}, {kMaxMag - 1, kMaxMag}})
    tally(line(h, rng, a, b, 200000));
  for (int i = 0; i < (full_run() ? 200 : 20); ++i) {
    const std::int64_t a = 1 + static_cast<std::int64_t>(rng() % kMaxMag);
    const std::int64_t b = 1 + static_cast<std::int64_t>(rng() % kMaxMag);
    tally(line(h, rng, a, b, 50000));
  }

  std::printf("%s W=24: %llu runs, %llu steps, %llu failed (seed %llu)\n",
              name, static_cast<unsigned long long>(runs), static_cast<unsigned long long>(steps),
              static_cast<unsigned long long>(failed), static_cast<unsigned long long>(seed()));
  EXPECT_EQ(failed, 0u) << first;
  EXPECT_GT(steps, 20000000u);
}

TEST(Dloop, TwoStepsAheadMatchesTheClosedForms) { check_all<Vdloop>("dloop"); }
TEST(Dloop, OneStepAheadMatchesTheClosedForms) { check_all<Vdloop1>("dloop1"); }

// dloop1l, dloop1x: the block as a block preparation would give it; loads
// in one clock, which may be the clock of a step.
template <class V>
class OneClockLoad : public ProtoHarness<V> {
 public:
  using ProtoHarness<V>::top;
  using ProtoHarness<V>::tick;
  using ProtoHarness<V>::d;
  // The block's fields on the inputs (D's, -SUB, kept until the first step).
  void block(bool arc, std::int64_t sub, std::int64_t add) {
    const std::int64_t a = arc ? 1 : 0;
    auto f = [](std::int64_t v) { return static_cast<std::uint32_t>(v & ((std::int64_t{1} << kN) - 1)); };
    top().i_arc = arc;
    top().i_s2 = f(sub - 2 * a);
    top().i_a0 = f(add);
    top().i_f1 = f(2 * sub - 2 * a);
    top().i_f2 = f(add - sub);
    top().i_f3 = f(-sub);
    if constexpr (requires(V& v) { v.i_r; }) top().i_r = f(add - 2);
  }
  // The last step crossed onto the next quadrant (dloop1x), else false.
  bool crossed() const {
    if constexpr (requires(const V& v) { v.o_cross; }) return top().o_cross;
    else return false;
  }
  // One clock: load and/or command; returns the pulse's choice or -1.
  int clock(bool load, bool cmd) {
    top().i_load = load;
    top().i_cmd = cmd;
    tick();
    top().i_load = 0;
    top().i_cmd = 0;
    return top().o_pulse ? (top().o_g ? 1 : 0) : -1;
  }
};
using Dloop1l = OneClockLoad<Vdloop1l>;
using Dloop1x = OneClockLoad<Vdloop1x>;

// A move on dloop1l against the closed form; the move is loaded in the
// clock of the previous move's last step when `chained` (that step's choice
// is checked by the caller: `last` returns it).
struct Move1l {
  bool arc;
  std::int64_t x0, y0;  // arc: start; line: A = y0, B = x0
  std::uint64_t steps;  // at most
};

// With `crossings` an arc runs on round the circle: an inward step from
// |in| = 1 crosses onto the next quadrant, (in, out) = (out, 0) (table Q of
// docs/algorithm.md: the old outward axis becomes the inward one); D is
// in^2 + out^2 - R^2 all the same. Without, it stops before |in| reaches 0.
std::uint64_t g_crossings = 0;  // crossings the oracle saw (and checked)

template <class H>
std::string run_moves(H& h, std::mt19937_64& rng, const std::vector<Move1l>& moves, bool chained,
                      std::uint64_t& total, bool crossings = false) {
  int pending = -2;  // the choice the last step of the move before must show (-2: none)
  for (std::size_t m = 0; m < moves.size(); ++m) {
    const Move1l& mv = moves[m];
    const std::int64_t sub = mv.arc ? 2 * mv.x0 - 1 : mv.x0;
    const std::int64_t add = mv.arc ? 2 * mv.y0 + 1 : mv.y0;
    const std::int64_t r2 = mv.x0 * mv.x0 + mv.y0 * mv.y0;
    std::int64_t x = mv.x0, y = mv.arc ? mv.y0 : 0;
    if (!mv.arc) x = 0;
    auto dval = [&]() { return mv.arc ? x * x + y * y - r2 : mv.y0 * y - mv.x0 * x; };
    auto name = [&]() {
      return std::string(mv.arc ? "arc from (" : "line (A, B) = (") + std::to_string(mv.arc ? mv.x0 : mv.y0) + ", " +
             std::to_string(mv.arc ? mv.y0 : mv.x0) + ")" + (chained ? " chained" : "");
    };
    h.block(mv.arc, sub, add);
    const bool with_step = pending != -2;
    const int got = h.clock(true, with_step);
    if (with_step && got != pending) return name() + ": the last step of the move before: choice " + std::to_string(got);
    if (!with_step && got != -1) return name() + ": a pulse in the load clock without a command";
    if (h.d() != 0) return name() + ": D = " + std::to_string(h.d()) + " after the load";
    pending = -2;
    for (std::uint64_t n = 0; n < mv.steps; ++n) {
      const std::int64_t before = dval();
      if (mv.arc && !crossings && x == 1 && before >= 0) break;
      const int want = before >= 0 ? 1 : 0;
      // The state after this step, to know whether it is the move's last.
      const bool cross = crossings && mv.arc && want && x == 1;
      std::int64_t x1 = want ? (mv.arc ? x - 1 : x + 1) : x, y1 = want ? y : y + 1;
      if (cross) { x1 = y; y1 = 0; }
      const std::int64_t d1 = mv.arc ? x1 * x1 + y1 * y1 - r2 : mv.y0 * y1 - mv.x0 * x1;
      const bool last = chained && m + 1 < moves.size() &&
                        (n + 1 == mv.steps || (mv.arc && !crossings && x1 == 1 && d1 >= 0));
      if (last) {  // this step is taken in the clock that loads the next move
        pending = want;
        ++total;
        break;
      }
      if (!chained) {
        for (unsigned gap = rng() % 4 == 0 ? static_cast<unsigned>(rng() % 3) : 0u; gap > 0; --gap)
          if (h.clock(false, false) != -1 || h.d() != before) return name() + ": a clock without a command moved";
      }
      const int g = h.clock(false, true);
      ++total;
      if (g != want)
        return name() + ": step " + std::to_string(n) + " choice " + std::to_string(g) + ", expected " + std::to_string(want);
      if (h.crossed() != cross)
        return name() + ": step " + std::to_string(n) + " crossing " + std::to_string(h.crossed());
      g_crossings += cross ? 1 : 0;
      x = x1;
      y = y1;
      if (h.d() != dval())
        return name() + ": step " + std::to_string(n) + " D " + std::to_string(h.d()) + ", expected " + std::to_string(dval());
    }
  }
  return "";
}

TEST(Dloop, OneClockLoadMatchesTheClosedForms) {
  Dloop1l h;
  std::mt19937_64 rng(seed() + 1);
  constexpr std::int64_t kMaxMag = (std::int64_t{1} << kW) - 1;
  std::vector<Move1l> moves;
  for (std::int64_t r : {2, 3, 4, 5, 7, 10, 100, 4095, 4096, 8193, 65537})
    moves.push_back({true, r, 0, ~std::uint64_t{0}});
  moves.push_back({true, std::int64_t{1} << 23, 0, 400000});
  moves.push_back({true, 50, kMaxMag - 30, ~std::uint64_t{0}});
  for (auto [a, b] : {std::pair<std::int64_t, std::int64_t>{1, 1}, {3, 5}, {5, 3}, {4096, 8191}, {kMaxMag, kMaxMag},
                      {kMaxMag, 1}, {1, kMaxMag}})
    moves.push_back({false, b, a, static_cast<std::uint64_t>(std::min<std::int64_t>(a + b, 200000))});
  for (int i = 0; i < 200; ++i) {  // short moves of every size: the load path back to back
    const unsigned bits = 2 + static_cast<unsigned>(rng() % 22);
    const std::int64_t p = 2 + static_cast<std::int64_t>(rng() % (std::uint64_t{1} << bits));
    const std::int64_t q = static_cast<std::int64_t>(rng() % (std::uint64_t{1} << bits));
    if (rng() % 2) moves.push_back({true, p, q, 1 + rng() % 40});
    else moves.push_back({false, p, q + 1, 1 + rng() % 40});
  }
  std::uint64_t total = 0;
  const std::string e1 = run_moves(h, rng, moves, false, total);
  EXPECT_EQ(e1, "");
  const std::string e2 = run_moves(h, rng, moves, true, total);
  EXPECT_EQ(e2, "");
  std::printf("dloop1l W=24: %zu moves twice (apart, chained), %llu steps\n", moves.size(),
              static_cast<unsigned long long>(total));
  EXPECT_GT(total, 2000000u);
}

TEST(Dloop, CrossingsMatchTheClosedForms) {
  Dloop1x h;
  std::mt19937_64 rng(seed() + 2);
  constexpr std::int64_t kMaxMag = (std::int64_t{1} << kW) - 1;
  std::vector<Move1l> moves;
  // Whole turns and more (8 R steps is about one turn): small circles
  // (new |in| of 1 and 2 right after a crossing), R on both sides of the
  // split of the sums, points off the integer circle.
  for (std::int64_t r : {2, 3, 4, 5, 7, 10, 100, 4095, 4097, 8193, 65537})
    moves.push_back({true, r, 0, static_cast<std::uint64_t>(20 * r + 50)});
  for (auto [x0, y0] : {std::pair<std::int64_t, std::int64_t>{2, 1}, {2, 2}, {3, 1}, {3, 3}, {2, 5}, {5, 2}, {9, 4}})
    moves.push_back({true, x0, y0, 300});
  // Crossings with big operands: near the axis of big circles.
  for (std::int64_t x0 : {2, 3, 5, 40, 5000})
    moves.push_back({true, x0, kMaxMag - 30, 400000});
  moves.push_back({true, 2, std::int64_t{1} << 23, 300000});
  for (int i = 0; i < 200; ++i) {
    const unsigned bits = 1 + static_cast<unsigned>(rng() % 23);
    const std::int64_t x0 = 2 + static_cast<std::int64_t>(rng() % 30);
    const std::int64_t y0 = static_cast<std::int64_t>(rng() % (std::uint64_t{1} << bits));
    moves.push_back({true, x0, y0, 1 + rng() % 3000});
    if (i % 4 == 0) moves.push_back({false, 1 + static_cast<std::int64_t>(rng() % kMaxMag), 1 + static_cast<std::int64_t>(rng() % kMaxMag), 1 + rng() % 300});
  }
  std::uint64_t total = 0;
  g_crossings = 0;
  const std::string e1 = run_moves(h, rng, moves, false, total, true);
  EXPECT_EQ(e1, "");
  const std::string e2 = run_moves(h, rng, moves, true, total, true);
  EXPECT_EQ(e2, "");
  std::printf("dloop1x W=24: %zu moves twice (apart, chained), %llu steps, %llu crossings\n", moves.size(),
              static_cast<unsigned long long>(total), static_cast<unsigned long long>(g_crossings));
  EXPECT_GT(total, 2000000u);
  EXPECT_GT(g_crossings, 1000u);
}

}  // namespace
