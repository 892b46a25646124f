// Paper A mode (--hw-arcs) through the link into the simulated board: a
// G-code program of lines and arcs as interp_top blocks, its feed written
// every cycle. The STEP/DIR pins against the paper A model (model/interp)
// block by block; each block's end against the G-code's end point; the
// path speed the pins give against the planner's; the feed hold
// (watchdog) on interp_top: a ramp to rest along the path and back.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <random>
#include <sstream>
#include <string>

#include "board_sim.hpp"
#include "gcode/gcode.hpp"
#include "interp/circular.hpp"
#include "interp/linear.hpp"
#include "sim_transport.hpp"
#include "stream_blocks.hpp"

namespace contour::board {
namespace {

constexpr double kSpm = 1000;  // steps per mm

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

planner::Plan plan_text(const std::string& text) { return planner::plan(gcode::parse(text), planner::Config{}); }

struct Outcome {
  StreamResult res;
  std::vector<StepEvent> steps;
  std::uint64_t simultaneous = 0;
};

Outcome run_blocks(const BlockProgram& p, Faults faults = {}) {
  BoardSim sim("", faults);
  SimTransport t(sim);
  LinkClient link(t);
  Outcome o;
  o.res = stream_blocks(link, t, p, StreamConfig{});
  o.steps = sim.steps();
  o.simultaneous = sim.simultaneous_steps();
  return o;
}

// The paper A model's pulses of one block (the golden model, W = 24: the
// same pulses as at the board's W = 16 for every block it accepts).
std::vector<Pulse> model_pulses(const HwBlock& b) {
  std::vector<Pulse> v;
  if (b.arc) {
    Circular<24> c(b.xs, b.ys, b.xe, b.ye, b.cw ? Sense::CW : Sense::CCW);
    while (auto p = c.step()) v.push_back(*p);
  } else {
    Linear<24> l(b.xe, b.ye);
    while (auto p = l.step()) v.push_back(*p);
  }
  return v;
}

// interp_top's output stage as INTERP's registers give it (regmap.def,
// docs/board-regs.md): every STEP pulse of X and Y high for exactly
// STEP_LEN clocks, at least STEP_SPACE clocks low before the next step of
// its axis, and ended (its pin fell) when the run is over.
void expect_step_timing(const std::vector<StepEvent>& s) {
  std::size_t bad = 0;
  for (const std::string& f : step_timing_faults(s, StreamConfig{}.step_len, StreamConfig{}.step_space, true, bad))
    ADD_FAILURE() << f;
  EXPECT_EQ(bad, 0u) << "pulses of " << s.size() << " off the output stage's timing";
}

// The pins give each block's model pulses in turn, each a whole pulse of
// the registers' timing; returns the pins'
// position (relative to the first) after each block.
std::vector<std::pair<std::int64_t, std::int64_t>> expect_model_pulses(const Outcome& o, const BlockProgram& p) {
  std::vector<std::pair<std::int64_t, std::int64_t>> ends;
  EXPECT_EQ(o.simultaneous, 0u);
  expect_step_timing(o.steps);
  std::size_t i = 0;
  std::int64_t x = 0, y = 0;
  for (std::size_t k = 0; k < p.blocks.size(); ++k) {
    for (const Pulse& m : model_pulses(p.blocks[k])) {
      if (i >= o.steps.size()) {
        ADD_FAILURE() << "the pins stop at pulse " << i << ", in block " << k << " (" << p.blocks[k].args() << ")";
        return ends;
      }
      if (!(o.steps[i].pulse == m)) {
        ADD_FAILURE() << "pulse " << i << " (block " << k << ", " << p.blocks[k].args() << "): pins "
                      << to_string(o.steps[i].pulse) << ", model " << to_string(m);
        return ends;
      }
      (m.axis == Axis::X ? x : y) += m.sign;
      ++i;
    }
    ends.emplace_back(x, y);
  }
  EXPECT_EQ(o.steps.size(), i) << "pulses after the last block";
  EXPECT_EQ(o.res.end[0] - o.res.start[0], x);
  EXPECT_EQ(o.res.end[1] - o.res.start[1], y);
  EXPECT_EQ(o.res.end, o.res.expected);
  EXPECT_EQ(o.res.chords, p.blocks.size());
  return ends;
}

const std::string kProgram = std::string(CONTOUR_SOURCE_DIR) + "/tb/board/hw_arcs.ngc";

TEST(BoardBlocks, ConversionCoversEveryQuadrantBothSensesAndFullCircles) {
  const BlockProgram p = to_blocks(plan_text(read_text(kProgram)), kSpm);
  int arcs[2] = {0, 0}, full = 0, quadrants = 0;
  for (const HwBlock& b : p.blocks) {
    if (!b.arc) continue;
    ++arcs[b.cw];
    full += b.xs == b.xe && b.ys == b.ye;
    quadrants |= 1 << b.q;
  }
  EXPECT_GE(arcs[0], 3);
  EXPECT_GE(arcs[1], 3);
  EXPECT_EQ(full, 2);
  EXPECT_EQ(quadrants, 0xF);
}

// Random G17 arcs (radius 0.01 to 40 mm, any start and end angle, both
// senses, 4 decimals as a CAM writes them): how often the conversion ends
// an arc exactly on the G-code's end point rounded to the grid (the rule's
// first choice) rather than beside it (docs/board.md). Every block is one
// paper A accepts at W = 16 and starts where the one before ended.
TEST(BoardBlocks, ArcsEndOnTheRoundedEndPoint) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> ang(0, 6.283185307179586), lr(std::log(0.01), std::log(40.0));
  std::size_t exact = 0, beside = 0, as_line = 0, n = 2000;
  double worst = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double r = std::exp(lr(rng)), a0 = ang(rng), a1 = ang(rng);
    char text[256];
    const double xs = r * std::cos(a0), ys = r * std::sin(a0);
    std::snprintf(text, sizeof text, "G21 G90 G17\nG01 X%.4f Y%.4f F3000\nG0%d X%.4f Y%.4f I%.4f J%.4f\n", xs, ys,
                  i % 2 ? 2 : 3, r * std::cos(a1), r * std::sin(a1), -xs, -ys);
    const auto g = gcode::parse(text);
    const BlockProgram p = to_blocks(planner::plan(g, planner::Config{}), kSpm);
    ASSERT_FALSE(p.blocks.empty()) << text;
    const HwBlock& b = p.blocks.back();
    if (p.blocks.size() == 2) {
      EXPECT_EQ(b.x0, p.blocks[0].end_x()) << text;
    }
    if (!b.arc) {
      ++as_line;
      continue;
    }
    EXPECT_NO_THROW(Circular<16>::validate(b.xs, b.ys, b.xe, b.ye, b.cw ? Sense::CW : Sense::CCW)) << text;
    const double dx = static_cast<double>(b.end_x() - std::llround(g.back().end.x * kSpm));
    const double dy = static_cast<double>(b.end_y() - std::llround(g.back().end.y * kSpm));
    const double d = std::hypot(dx, dy);
    worst = std::max(worst, d);
    (d == 0 ? exact : beside) += 1;
  }
  std::printf("arcs: %zu of %zu end on the rounded end point, %zu beside it (at most %.2f steps), %zu sent as lines\n",
              exact, n, beside, worst, as_line);
  EXPECT_GT(exact, n * 95 / 100);
  EXPECT_LE(worst, 3.0);
}

// The oracle of the ends is the G-code reader's end points, rounded to the
// grid: a line ends there exactly; an arc too, when paper A accepts it
// about a lattice centre within 2 steps of the programmed one (all of
// this program's arcs), which is the conversion's rule (docs/board.md).
TEST(BoardBlocks, ProgramGivesTheModelsPulsesAndEndsOnTheGcodesPoints) {
  const std::string text = read_text(kProgram);
  const BlockProgram p = to_blocks(plan_text(text), kSpm);
  const Outcome o = run_blocks(p);
  const auto ends = expect_model_pulses(o, p);
  ASSERT_EQ(ends.size(), p.blocks.size());
  const auto g = gcode::parse(text);
  for (std::size_t k = 0; k < p.blocks.size(); ++k) {
    const auto it = std::find_if(g.begin(), g.end(), [&](const gcode::Block& b) { return b.line == p.blocks[k].line; });
    ASSERT_NE(it, g.end());
    EXPECT_EQ(ends[k].first, std::llround(it->end.x * kSpm)) << "block " << k << " line " << p.blocks[k].line;
    EXPECT_EQ(ends[k].second, std::llround(it->end.y * kSpm)) << "block " << k << " line " << p.blocks[k].line;
  }
  EXPECT_EQ(o.res.wdog_trips, 0u);
}

// The path speed the pins give, in windows of 2 ms, against the planner's
// speed at the nearest of its samples (the planner's geometry, not the
// conversion's): the feed's residual error. Printed for docs/board.md.
TEST(BoardBlocks, PathSpeedFollowsThePlannersProfile) {
  const planner::Plan plan = plan_text(read_text(kProgram));
  const BlockProgram p = to_blocks(plan, kSpm);
  const Outcome o = run_blocks(p);
  expect_model_pulses(o, p);
  const auto samples = planner::interpolate(plan);
  double vmax = 0;
  for (const auto& s : samples) vmax = std::max(vmax, s.v);
  const std::uint64_t win = static_cast<std::uint64_t>(2e-3 * kClockHz);
  std::size_t i = 0, cursor = 0, n = 0;
  double x = 0, y = 0, worst = 0, sum2 = 0;
  for (std::uint64_t c0 = o.steps.front().clock; c0 + win <= o.steps.back().clock; c0 += win) {
    const double xa = x, ya = y;
    for (; i < o.steps.size() && o.steps[i].clock < c0 + win; ++i)
      (o.steps[i].pulse.axis == Axis::X ? x : y) += o.steps[i].pulse.sign / kSpm;
    const double v_hw = std::hypot(x - xa, y - ya) / 2e-3;
    // The planner's sample nearest the window's middle, searched forward.
    const double mx = (x + xa) / 2, my = (y + ya) / 2;
    std::size_t best = cursor;
    for (std::size_t j = cursor; j < samples.size() && j < cursor + 40; ++j)
      if (std::hypot(samples[j].p.x - mx, samples[j].p.y - my) <
          std::hypot(samples[best].p.x - mx, samples[best].p.y - my))
        best = j;
    cursor = best;
    const double v_plan = samples[best].v;
    if (std::getenv("FEED_DUMP"))  // every window: time, sample, v pins, v plan (mm/s)
      std::printf("%.4f %zu %.2f %.2f\n", static_cast<double>(c0) / kClockHz, best, v_hw, v_plan);
    if (v_plan < 0.3 * vmax || v_hw < 0.3 * vmax) continue;  // near rest: the position says little of time
    const double e = (v_hw - v_plan) / v_plan;
    worst = std::max(worst, std::abs(e));
    sum2 += e * e;
    ++n;
  }
  const double rms = std::sqrt(sum2 / static_cast<double>(n));
  std::printf("feed: path speed of the pins vs the plan over %zu windows of 2 ms: max %.2f %%, rms %.2f %%\n", n,
              100 * worst, 100 * rms);
  EXPECT_GT(n, 100u);
  EXPECT_LT(worst, 0.10);
  EXPECT_LT(rms, 0.03);
}

// The feed rule on a 45 degree line in cruise: a pulse is 1/spm along one
// axis, so the pulse rate is v * spm * (|cos| + |sin|) = v * spm * sqrt(2).
TEST(BoardBlocks, FeedCountsThePathLengthOfAPulse) {
  const planner::Plan plan = plan_text("G21 G90 G17\nG01 X30. Y30. F3000\n");
  const BlockProgram p = to_blocks(plan, kSpm);
  const double mid = plan.total_time / 2;
  EXPECT_NEAR(p.feed.rate_at(mid), 50.0 * kSpm * std::sqrt(2.0), 1.0);
  const planner::Plan along = plan_text("G21 G90 G17\nG01 X30. F3000\n");
  EXPECT_NEAR(to_blocks(along, kSpm).feed.rate_at(along.total_time / 2), 50.0 * kSpm, 1.0);
}

TEST(BoardBlocks, WhatTheBoardCannotDoIsRefusedNamingTheLine) {
  auto refused = [](const std::string& text, const std::string& what) {
    try {
      to_blocks(plan_text(text), kSpm);
      ADD_FAILURE() << "no error for " << text;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
    }
  };
  refused("G21 G90 G17\nG01 X1. F1000\nG01 X2. Z0.5\n", "line 3: a Z move");
  refused("G21 G90 G18\nG01 X1. F1000\nG02 X2. Z0. I0.5 K0.\n", "line 3: an arc out of the XY plane");
  refused("G21 G90 G17\nG01 X70. F1000\n", "line 2: a line's X = 70000 steps is beyond the board's 2^16 - 1");
  refused("G21 G90 G17\nG01 X1. F1000\nG03 X1. Y0. I-70. J0.\n", "line 3: an arc's start X about its centre");
}

// 400 collinear lines of `mm` at 80 mm/s through the link, `braking` the
// feed's cap (off: to measure the link alone); the pins must be the
// model's. Returns the longest gap between pulses in the middle half (us)
// and the mean speed there (mm/s).
std::pair<double, double> run_short_lines(double mm, bool braking) {
  std::string text = "G21 G90 G17 G64\nF4800\n";
  for (int i = 1; i <= 400; ++i) text += "G01 X" + std::to_string(mm * i) + "\n";
  BlockProgram p = to_blocks(plan_text(text), kSpm);
  EXPECT_EQ(p.blocks.size(), 400u);
  if (!braking) p.decel = 0;
  const Outcome o = run_blocks(p);
  expect_model_pulses(o, p);
  const std::size_t a = o.steps.size() / 4, b = 3 * o.steps.size() / 4;
  std::uint64_t gap = 0;
  for (std::size_t i = a + 1; i < b; ++i) gap = std::max(gap, o.steps[i].clock - o.steps[i - 1].clock);
  const double span = static_cast<double>(o.steps[b].clock - o.steps[a].clock) / kClockHz;
  const double us = static_cast<double>(gap) / kClockHz * 1e6, v = static_cast<double>(b - a) / kSpm / span;
  std::printf("lines of %.3f mm, cap %s: longest gap between pulses %.2f us (12.5 planned), speed %.1f mm/s (80)\n",
              mm, braking ? "on" : "off", us, v);
  return {us, v};
}

// The link alone (the cap off): blocks shorter than a cycle (0.05 mm at
// 80 mm/s: 0.625 ms, 1600 a second) keep the queue fed, the pulses even
// through the cruise (one block a cycle starved: a gap of 562.5 us).
TEST(BoardBlocks, ShortBlocksKeepTheQueueFed) { EXPECT_LT(run_short_lines(0.05, false).first, 20.0); }

// Blocks too short for the link (0.015 mm: 5333 a second): without the
// cap the queue runs dry and the motion stops dead (gaps of hundreds of
// us); with it the feed stays where the board can brake within the blocks
// it has: slower, never a stop.
TEST(BoardBlocks, BlocksTooShortForTheLinkSlowTheMotionInsteadOfStoppingIt) {
  EXPECT_GT(run_short_lines(0.015, false).first, 300.0);
  const auto [gap, v] = run_short_lines(0.015, true);
  EXPECT_LT(gap, 150.0);
  EXPECT_LT(v, 40.0);
}

// The distance (mm) the pins moved in [t0, t1) seconds of the run.
double path_in(const std::vector<StepEvent>& s, double t0, double t1) {
  double x = 0, y = 0;
  for (const StepEvent& e : s) {
    const double t = static_cast<double>(e.clock) / kClockHz;
    if (t >= t0 && t < t1) (e.pulse.axis == Axis::X ? x : y) += e.pulse.sign / kSpm;
  }
  return std::hypot(x, y);
}

// The board's time scale slows interp_top's feed generator too: the
// host's line cut for 0.3 s (> the 50 ms watchdog) in the middle of a
// full circle at cruise (44 mm/s: the chord tolerance's cap), the motion ramps to rest along the arc
// (over 49 ms) and back, every pulse the model's.
TEST(BoardBlocks, WatchdogStopsAlongThePathAndResumes) {
  const planner::Plan plan = plan_text("G21 G90 G17\nG03 X0. Y0. I6. J0. F3000\n");
  const BlockProgram p = to_blocks(plan, kSpm);
  Faults f;
  f.cut_at_s = 0.3;
  f.cut_for_s = 0.3;
  const Outcome o = run_blocks(p, f);
  expect_model_pulses(o, p);
  EXPECT_GE(o.res.wdog_trips, 1u);
  const std::size_t g = after_longest_gap(o.steps);
  const double stop = static_cast<double>(o.steps[g - 1].clock) / kClockHz;
  const double go = static_cast<double>(o.steps[g].clock) / kClockHz;
  EXPECT_GT(go - stop, 0.05);
  const double full = plan.segs.back().v_cruise * 4e-3;  // mm in 4 ms at the planned cruise
  std::printf("hold: path in 4 ms: %.4f mm 62 ms before rest, %.4f mm 25 ms before, %.4f mm at the end, "
              "%.4f mm after the restart (full speed: %.4f mm)\n",
              path_in(o.steps, stop - 64e-3, stop - 60e-3), path_in(o.steps, stop - 27e-3, stop - 23e-3),
              path_in(o.steps, stop - 4e-3, stop + 1e-9), path_in(o.steps, go, go + 4e-3), full);
  EXPECT_GT(path_in(o.steps, stop - 64e-3, stop - 60e-3), 0.9 * full);
  const double half = path_in(o.steps, stop - 27e-3, stop - 23e-3);
  EXPECT_GT(half, 0.35 * full);
  EXPECT_LT(half, 0.65 * full);
  EXPECT_LT(path_in(o.steps, stop - 4e-3, stop + 1e-9), 0.15 * full);
  EXPECT_LT(path_in(o.steps, go, go + 4e-3), 0.15 * full);
}

// The host's hold (Ctrl-C in `contour stream`): HOLD, rest along the
// path, then the queue dropped. The pins give a prefix of the model's
// pulses (none lost, none half given), the position read back is their
// net, nothing moves after.
TEST(BoardBlocks, HostHoldStopsAlongThePathThenAborts) {
  const planner::Plan plan = plan_text("G21 G90 G17\nG03 X0. Y0. I6. J0. F3000\n");
  const BlockProgram p = to_blocks(plan, kSpm);
  BoardSim sim;
  SimTransport t(sim);
  LinkClient link(t);
  std::atomic<bool> stop{false};
  const StreamResult r = stream_blocks(
      link, t, p, StreamConfig{}, [&](const Progress&) { stop = stop || sim.seconds() > 0.3; }, &stop);
  EXPECT_TRUE(r.stopped);
  const std::vector<StepEvent> s = sim.steps();
  const std::vector<Pulse> m = model_pulses(p.blocks.at(0));
  ASSERT_GT(s.size(), 0u);
  ASSERT_LT(s.size(), m.size());
  std::int64_t x = 0, y = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    ASSERT_EQ(s[i].pulse, m[i]) << "pulse " << i;
    (m[i].axis == Axis::X ? x : y) += m[i].sign;
  }
  EXPECT_EQ(r.end[0] - r.start[0], x);
  EXPECT_EQ(r.end[1] - r.start[1], y);
  const double rest = static_cast<double>(s.back().clock) / kClockHz;
  const double full = plan.segs.back().v_cruise * 4e-3;
  EXPECT_GT(path_in(s, rest - 64e-3, rest - 60e-3), 0.9 * full);
  EXPECT_LT(path_in(s, rest - 4e-3, rest + 1e-9), 0.15 * full);
  sim.run(120000);  // 10 ms more
  EXPECT_EQ(sim.steps().size(), s.size());
  expect_step_timing(sim.steps());  // every pulse whole
}

}  // namespace
}  // namespace contour::board
