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

#include "Vdloop.h"
#include "Vdloop1.h"
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

template <class V>
class Dloop : public contour::tb::Harness<V> {
 public:
  using contour::tb::Harness<V>::top;
  using contour::tb::Harness<V>::tick;
  Dloop() {
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

// The arc from (x0, y0), Q1 CCW: SUB = 2 x0 - 1, ADD = 2 y0 + 1.
template <class H>
Outcome arc(H& h, std::mt19937_64& rng, std::int64_t x0, std::int64_t y0, std::uint64_t max_steps) {
  Outcome r;
  r.name = "arc from (" + std::to_string(x0) + ", " + std::to_string(y0) + ")";
  r.error = h.load(true, static_cast<std::uint64_t>(2 * x0 - 1), static_cast<std::uint64_t>(2 * y0 + 1));
  if (!r.error.empty()) {
    r.error = r.name + ": " + r.error;
    return r;
  }
  const std::int64_t r2 = x0 * x0 + y0 * y0;
  std::int64_t x = x0, y = y0;
  while (r.steps < max_steps) {
    const std::int64_t dbefore = x * x + y * y - r2;
    if (x == 1 && dbefore >= 0) break;  // the next step would reach the axis
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
    if (g) --x; else ++y;
    const std::int64_t want = x * x + y * y - r2;
    if (h.d() != want) {
      r.error = where(r, "D", x, y, h.d(), want);
      return r;
    }
  }
  return r;
}

// The line with constants A (outward), B (inward) from the origin.
template <class H>
Outcome line(H& h, std::mt19937_64& rng, std::int64_t a, std::int64_t b, std::uint64_t max_steps) {
  Outcome r;
  r.name = "line A = " + std::to_string(a) + ", B = " + std::to_string(b);
  r.error = h.load(false, static_cast<std::uint64_t>(b), static_cast<std::uint64_t>(a));
  if (!r.error.empty()) {
    r.error = r.name + ": " + r.error;
    return r;
  }
  std::int64_t x = 0, y = 0;
  while (r.steps < max_steps) {
    const std::int64_t dbefore = a * y - b * x;
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
    if (g) ++x; else ++y;
    const std::int64_t want = a * y - b * x;
    if (h.d() != want) {
      r.error = where(r, "D", x, y, h.d(), want);
      return r;
    }
  }
  return r;
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

}  // namespace
