// Chords streamed through the link into the simulated board: the STEP/DIR
// pins against the golden two-stage model (planner::two_stage_model),
// pulse by pulse and in time; positions read back; faults on the wire; the
// watchdog's controlled stop and resume.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <random>
#include <string>
#include <utility>

#include "board_sim.hpp"
#include "planner/two_stage.hpp"
#include "sim_transport.hpp"
#include "stream_chords.hpp"

namespace contour::board {
namespace {

std::vector<Chord3> random_chords(std::size_t n, int most, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> d(-most, most);
  std::vector<Chord3> c(n);
  for (auto& x : c) x = {d(rng), d(rng), d(rng)};
  return c;
}

struct Outcome {
  StreamResult res;
  std::vector<StepEvent> steps;
  std::uint64_t simultaneous = 0;
};

Outcome run_stream(const std::vector<Chord3>& chords, Faults faults = {}, StreamConfig cfg = {}) {
  BoardSim sim("", faults);
  SimTransport t(sim);
  LinkClient link(t);
  Outcome o;
  o.res = stream_chords(link, t, chords, cfg);
  o.steps = sim.steps();
  o.simultaneous = sim.simultaneous_steps();
  return o;
}

std::vector<planner::TimedPulse> model_pulses(const std::vector<Chord3>& chords) {
  std::vector<planner::StepChord> sc;
  for (const auto& c : chords) sc.push_back({c.dx, c.dy, c.dz});
  return planner::two_stage_model(sc, 1e-3);
}

// The pins' pulses equal the model's, one by one; returns the largest time
// difference (both measured from their first pulse).
double expect_model_pulses(const Outcome& o, const std::vector<Chord3>& chords) {
  const auto m = model_pulses(chords);
  EXPECT_EQ(o.simultaneous, 0u);
  EXPECT_EQ(o.steps.size(), m.size());
  double worst = 0;
  const std::size_t n = std::min(o.steps.size(), m.size());
  for (std::size_t i = 0; i < n; ++i) {
    if (!(o.steps[i].pulse == m[i].pulse)) {
      ADD_FAILURE() << "pulse " << i << ": pins " << to_string(o.steps[i].pulse) << ", model "
                    << to_string(m[i].pulse);
      return worst;
    }
    const double th = static_cast<double>(o.steps[i].clock - o.steps[0].clock) / kClockHz;
    worst = std::max(worst, std::abs(th - (m[i].t - m[0].t)));
  }
  for (int a = 0; a < 3; ++a) EXPECT_EQ(o.res.end[a], o.res.expected[a]) << "axis " << a;
  EXPECT_EQ(o.res.chords, chords.size());
  return worst;
}

// The output stage's timing as AXIS3's registers give it (axis3.def,
// docs/board-regs.md): every STEP pulse of every axis high for exactly
// STEP_LEN clocks (0 acts as 1), and at least STEP_SPACE clocks (0 acts as
// 1) from a STEP falling to the next rising of any axis. Every pulse must
// have ended (its pin fell) when the run is over. The pulses' count, order
// and axes are expect_model_pulses'; this checks that each rising edge is
// one whole pulse: a pin left high through the space, or never dropped,
// fails here.
void expect_step_timing(const std::vector<StepEvent>& s, std::uint32_t len, std::uint32_t space) {
  std::size_t bad = 0;
  for (const std::string& f : step_timing_faults(s, len, space, false, bad)) ADD_FAILURE() << f;
  std::array<std::size_t, 3> per_axis{};
  for (const StepEvent& e : s) ++per_axis[static_cast<std::size_t>(e.pulse.axis)];
  EXPECT_EQ(bad, 0u) << "pulses of " << s.size() << " (X " << per_axis[0] << ", Y " << per_axis[1] << ", Z "
                     << per_axis[2] << ") off the output stage's timing";
}

TEST(BoardChords, RandomChordsGiveTheModelsPulsesOnTime) {
  const auto chords = random_chords(120, 60, 1);
  const Outcome o = run_stream(chords);
  const double worst = expect_model_pulses(o, chords);
  expect_step_timing(o.steps, StreamConfig{}.step_len, StreamConfig{}.step_space);
  EXPECT_EQ(o.res.underruns, 0u);
  // On the model's time within the output stage's step (1 us high + 1 us
  // low) and a few clocks of latency, once the queue is running.
  EXPECT_LT(worst, 3e-6);
}

TEST(BoardChords, WideChordsGoThroughTheStagedRegisters) {
  std::vector<Chord3> chords{{600, -5, 0}, {-700, 2, 1}, {0, 0, 0}, {3, 4, -900}, {1, 1, 1}};
  StreamConfig cfg;
  cfg.step_len = cfg.step_space = 1;  // up to 3000 steps per 1 ms cycle
  const Outcome o = run_stream(chords, {}, cfg);
  expect_model_pulses(o, chords);
  expect_step_timing(o.steps, 1, 1);
}

// Chords of one axis alone (X, Y, Z, each sign), of two, of three, and
// empty ones, at a STEP_LEN and STEP_SPACE of their own: every axis's
// pulses are the model's, one rising edge each, and every pulse is
// STEP_LEN clocks high with STEP_SPACE clocks low before the next step.
TEST(BoardChords, EveryAxisStepsAloneAndTogetherWithTheRegistersPulseTiming) {
  std::vector<Chord3> chords{{0, 9, 0},  {0, 0, -9}, {7, 0, 0},  {0, -4, 0}, {0, 0, 5},  {-6, 0, 0},
                             {0, 0, 0},  {0, 1, 0},  {0, 0, 1},  {3, -2, 0}, {0, 5, -5}, {-4, 0, 6},
                             {3, -2, 4}, {0, 30, 0}, {0, 0, -30}, {-5, 6, -7}};
  const auto more = random_chords(20, 25, 3);
  chords.insert(chords.end(), more.begin(), more.end());
  for (const auto& [len, space] : {std::pair<std::uint32_t, std::uint32_t>{7, 4}, {3, 10}, {0, 0}}) {
    SCOPED_TRACE("STEP_LEN " + std::to_string(len) + ", STEP_SPACE " + std::to_string(space));
    StreamConfig cfg;
    cfg.step_len = len;
    cfg.step_space = space;
    const Outcome o = run_stream(chords, {}, cfg);
    expect_model_pulses(o, chords);
    expect_step_timing(o.steps, len, space);
  }
}

TEST(BoardChords, AChordBeyondTheBoardsWidthIsRefusedBeforeAnyMoves) {
  // W = 12 on the board: 4095 steps per axis and chord at most.
  try {
    run_stream({{1, 1, 1}, {0, 65536, 0}});
    ADD_FAILURE() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("chord 1 (0, 65536, 0)"), std::string::npos) << e.what();
  }
}

TEST(BoardChords, FlippedBitsAndDroppedBytesAreMendedByResends) {
  const auto chords = random_chords(150, 40, 2);
  Faults f;
  f.flip_every = 97;
  f.drop_every = 389;
  const Outcome o = run_stream(chords, f);
  expect_model_pulses(o, chords);
  EXPECT_GT(o.res.link.resends, 0u);
}

// Every reply carries the position of the pins' axes (board.def REPLY
// POS_*): while it runs it is the pins' net at some clock of the last 1 ms
// before the reply reached the host (read on the board, then sent); at
// rest, exactly the pins' net.
TEST(BoardChords, EveryReplyCarriesThePinsPositions) {
  const std::vector<Chord3> chords(300, Chord3{30, -20, 10});
  BoardSim sim;
  SimTransport t(sim);
  LinkClient link(t);
  std::uint64_t seen = 0, checked = 0;
  auto check = [&](const Progress& p) {
    if (p.replies == seen) return;
    seen = p.replies;
    const std::uint64_t now = sim.clocks(), back = 12000;
    for (int a = 0; a < 3; ++a)
      EXPECT_TRUE(pins_net_seen(sim.steps(), a, now > back ? now - back : 0, now, p.pos[a]))
          << "reply " << seen << " axis " << a << ": " << p.pos[a] << ", pins " << pins_net(sim.steps(), now)[a];
    ++checked;
  };
  const StreamResult r = stream_chords(link, t, chords, {}, check);
  EXPECT_GT(checked, 30u);
  EXPECT_EQ(r.end, (std::array<std::int64_t, 3>{9000, -6000, 3000}));
  EXPECT_EQ(pins_net(sim.steps()), r.end);
  EXPECT_EQ(link.last().pos, (std::array<std::int32_t, 3>{9000, -6000, 3000}));
}

// Steps in [t0, t1) seconds of the run.
std::size_t steps_in(const std::vector<StepEvent>& s, double t0, double t1) {
  return static_cast<std::size_t>(std::count_if(s.begin(), s.end(), [&](const StepEvent& e) {
    const double t = static_cast<double>(e.clock) / kClockHz;
    return t >= t0 && t < t1;
  }));
}

TEST(BoardChords, WatchdogStopsAlongThePathAndResumes) {
  // A steady line, then the host-to-board line dead for 0.3 s (> 100 ms).
  const std::vector<Chord3> chords(500, Chord3{30, -20, 10});
  Faults f;
  f.cut_at_s = 0.15;
  f.cut_for_s = 0.3;
  const Outcome o = run_stream(chords, f);
  expect_model_pulses(o, chords);
  EXPECT_GE(o.res.wdog_trips, 1u);
  expect_step_timing(o.steps, StreamConfig{}.step_len, StreamConfig{}.step_space);  // every pulse whole
  // The stop: the longest gap between steps is where the motion stood still.
  const std::size_t g = after_longest_gap(o.steps);
  const double stop = static_cast<double>(o.steps[g - 1].clock) / kClockHz;
  const double go = static_cast<double>(o.steps[g].clock) / kClockHz;
  EXPECT_GT(go - stop, 0.05);
  const double full = 60.0 * 2e-3 / 1e-3;  // steps in 2 ms at full speed
  // Linear ramp to rest over 65536 * 9 clocks = 49 ms: near the end a
  // crawl, half speed about 25 ms before; full speed 60 ms before.
  EXPECT_LT(steps_in(o.steps, stop - 2e-3, stop + 1e-9), 0.15 * full);
  const double half = static_cast<double>(steps_in(o.steps, stop - 26e-3, stop - 24e-3));
  EXPECT_GT(half, 0.35 * full);
  EXPECT_LT(half, 0.65 * full);
  EXPECT_GT(static_cast<double>(steps_in(o.steps, stop - 62e-3, stop - 60e-3)), 0.9 * full);
  // And the restart ramps up the same way.
  EXPECT_LT(steps_in(o.steps, go, go + 2e-3), 0.15 * full);
}

// A stop request (Ctrl-C in `contour stream`) 0.2 s into a steady line:
// feed hold, rest along the ramp, then the queue dropped. The pins give a
// prefix of the model's pulses, every one whole; the position read back is
// the pins' net.
TEST(BoardChords, AStopRequestHoldsThenStopsAtRestWithAPrefixOfThePulses) {
  const std::vector<Chord3> chords(500, Chord3{30, -20, 10});
  BoardSim sim;
  SimTransport t(sim);
  LinkClient link(t);
  std::atomic<bool> stop{false};
  const StreamResult r = stream_chords(link, t, chords, {}, [&](const Progress&) {
    if (sim.seconds() > 0.2) stop = true;
  }, &stop);
  EXPECT_TRUE(r.stopped);
  const auto m = model_pulses(chords);
  const auto& s = sim.steps();
  ASSERT_GT(s.size(), 1000u);
  ASSERT_LT(s.size(), m.size());
  for (std::size_t i = 0; i < s.size(); ++i)
    ASSERT_EQ(s[i].pulse, m[i].pulse) << "pulse " << i;
  EXPECT_EQ(pins_net(s), r.end);
  EXPECT_EQ(sim.simultaneous_steps(), 0u);
  EXPECT_FALSE(sim.enable_pin());
  // The ramp: the last pulses crawl, 60 ms before it was full speed.
  const double end = static_cast<double>(s.back().clock) / kClockHz, full = 60.0 * 2;
  EXPECT_LT(steps_in(s, end - 2e-3, end + 1e-9), 0.15 * full);
  const double half = static_cast<double>(steps_in(s, end - 26e-3, end - 24e-3));
  EXPECT_GT(half, 0.35 * full);
  EXPECT_LT(half, 0.65 * full);
  EXPECT_GT(static_cast<double>(steps_in(s, end - 62e-3, end - 60e-3)), 0.9 * full);
  // At rest: nothing more comes.
  const std::size_t n = s.size();
  sim.run(120000);
  EXPECT_EQ(sim.steps().size(), n);
  expect_step_timing(sim.steps(), StreamConfig{}.step_len, StreamConfig{}.step_space);  // every pulse whole
}

}  // namespace
}  // namespace contour::board

namespace contour::board {
namespace {

// The link's figures for docs/board.md, in simulated time (deterministic):
//   build/tb/board/board_rtl_test --gtest_filter='BoardLink.*'
// Throughput: chords on a cycle shorter than the link can feed (20 us),
// so the link is the bottleneck: chords loaded per simulated second.
TEST(BoardLink, ThroughputInChordsPerSecond) {
  const std::vector<Chord3> chords(2000, Chord3{1, -1, 1});
  StreamConfig cfg;
  cfg.cycle_s = 20e-6;
  cfg.step_len = cfg.step_space = 1;
  BoardSim sim;
  SimTransport t(sim);
  LinkClient link(t);
  const StreamResult r = stream_chords(link, t, chords, cfg);
  ASSERT_EQ(sim.steps().size(), 3 * chords.size());
  const double span = static_cast<double>(sim.steps().back().clock - sim.steps().front().clock) / kClockHz;
  const double rate = static_cast<double>(chords.size()) / span;
  std::printf("link: %.0f chords/s at 1 Mbaud (%zu chords in %.4f s, %llu frames)\n", rate, chords.size(), span,
              static_cast<unsigned long long>(r.link.frames));
  EXPECT_GT(rate, 1000.0);  // the 1 ms cycle needs 1000
}

// Latency: from the first start bit of a frame that queues one chord and
// sets RUN to the first STEP edge (the chord of 461 steps: its first
// command 25 clocks after the boundary).
TEST(BoardLink, LatencyFromAFrameToTheFirstStep) {
  BoardSim sim;
  SimTransport t(sim);
  LinkClient link(t);
  link.sync(BOARD_LINK_ID);
  link.transact({Op{true, BOARD_AXIS3_CH_X, 461}});
  const std::uint64_t c0 = sim.clocks();
  sim.send(make_request(1, {Op{true, BOARD_AXIS3_PUSH, 0}, Op{true, BOARD_AXIS3_CTRL, 1}}));
  while (sim.steps().empty() && sim.clocks() - c0 < 120000) sim.run(1);
  ASSERT_FALSE(sim.steps().empty());
  const double us = static_cast<double>(sim.steps().front().clock - c0) / kClockHz * 1e6;
  std::printf("link: %.2f us from a frame's first bit to the first step (frame of %zu characters)\n", us,
              make_request(1, {Op{true, BOARD_AXIS3_PUSH, 0}, Op{true, BOARD_AXIS3_CTRL, 1}}).size());
  EXPECT_LT(us, 1000.0);  // well inside one cycle
}

}  // namespace
}  // namespace contour::board
