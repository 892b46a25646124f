// Queued moves, random 24-bit moves and overruns, on the ISS.
#include <gtest/gtest.h>

#include <cstdlib>
#include <random>

#include "interp/circular.hpp"
#include "interp/engine.hpp"
#include "interp/linear.hpp"
#include "sw8085/interp/expect_model.hpp"
#include "sw8085/interp/host.hpp"

namespace contour::sw8085 {
namespace {

// CONTOUR_FULL=1 (set, not empty, not 0): the long runs.
bool full_run() {
  const char* e = std::getenv("CONTOUR_FULL");
  return e != nullptr && *e != '\0' && *e != '0';
}

constexpr std::int64_t kMax = (std::int64_t{1} << 24) - 1;

// The first `n` pulses of a line too long to run to its end on an ISS in a
// test (up to 2^25 pulses): pulse and state after each, against Linear<24>.
void expect_line_prefix(std::int64_t xe, std::int64_t ye, int n) {
  Host h;
  Linear<24> model(xe, ye);
  const SlotMove sm = h.queue(Move::line(xe, ye));
  ASSERT_EQ(h.state(sm, 0), model.state());
  for (int i = 1; i <= n && !model.done(); ++i) {
    const auto want = model.step();
    const CommandResult c = h.command();
    ASSERT_TRUE(c.pulse.has_value()) << "line " << xe << " " << ye << " pulse " << i;
    ASSERT_EQ(*c.pulse, *want) << "line " << xe << " " << ye << " pulse " << i;
    ASSERT_EQ(h.state(sm, static_cast<std::uint64_t>(i)), model.state())
        << "line " << xe << " " << ye << " after pulse " << i << ": got " << to_string(h.state(sm, i)) << ", want "
        << to_string(model.state());
  }
}

TEST(Random24, LinePrefixesIncludingExtremes) {
  for (auto [xe, ye] : {std::pair<std::int64_t, std::int64_t>{kMax, kMax}, {kMax, 0}, {0, -kMax}, {-kMax, 1},
                        {1, kMax}, {-kMax, -kMax + 1}, {kMax, 65536}, {-65536, kMax}}) {
    expect_line_prefix(xe, ye, 1500);
    if (HasFatalFailure()) return;
  }
  std::mt19937_64 rng(6);
  std::uniform_int_distribution<std::int64_t> c(-kMax, kMax);
  const int n = full_run() ? 200 : 20;
  for (int i = 0; i < n; ++i) {
    expect_line_prefix(c(rng), c(rng), 700);
    if (HasFatalFailure()) return;
  }
}

// Whole lines whose counters cross 16-bit and byte boundaries: blocks of
// 65536 P steps change on the first pulse (65537), in the middle (70000),
// twice (-131073: the second one starts the last block), and on a one-axis
// line (-131075, 0: P is every other pulse, 65538 P steps).
TEST(Random24, WholeLinesAcrossByteBoundaries) {
  Host h;
  for (auto [xe, ye] : {std::pair<std::int64_t, std::int64_t>{65537, 3}, {-2, 65536}, {256, 255}, {-257, -512},
                        {70000, -69999}, {65535, 1}, {-131073, 5}, {-131075, 0}}) {
    const Move m = Move::line(xe, ye);
    const RunResult want = run_model<24>(m), got = h.run(m, nullptr, want.steps.size() + 1);
    ASSERT_EQ(got.steps.size(), want.steps.size()) << describe(m);
    for (std::size_t i = 0; i < want.steps.size(); ++i) {
      ASSERT_EQ(got.steps[i].pulse, want.steps[i].pulse) << describe(m) << " pulse " << i + 1;
      ASSERT_EQ(got.steps[i].state, want.steps[i].state) << describe(m) << " after pulse " << i + 1;
    }
  }
}

// A 24-bit arc from a random start over `n` pulses: the end is where the
// model is after n pulses of the full circle (so it is reachable), then the
// arc runs to that end on both.
Move short_arc(std::int64_t xs, std::int64_t ys, Sense s, int n) {
  Circular<24> walk(xs, ys, xs, ys, s);
  for (int i = 0; i < n; ++i) walk.step();
  // An accepted end is within |XE| + |YE| of the circle: walk on to one.
  auto near = [](const State& st) { return std::abs(st.d) <= std::abs(st.x) + std::abs(st.y); };
  while (!near(walk.state())) walk.step();
  const State e = walk.state();
  return Move::arc(xs, ys, e.x, e.y, s);
}

void expect_arc(const Move& m) {
  Host h;
  expect_model_run(h, m);
}

TEST(Random24, ShortArcsOnLargeCirclesIncludingAxisCrossings) {
  // Near the axes and at the largest radius: crossings with 24-bit values.
  const std::int64_t big = kMax;
  for (Sense s : {Sense::CCW, Sense::CW}) {
    for (auto [xs, ys] : {std::pair<std::int64_t, std::int64_t>{big, 0}, {0, big}, {-big, 3}, {5, -big},
                          {11863282, 11863283}, {-16777000, 2700}, {300, 16777000}}) {
      if (xs * xs + ys * ys > big * big) continue;
      expect_arc(short_arc(xs, ys, s, 1200));
      if (HasFatalFailure()) return;
    }
  }
  std::mt19937_64 rng(85);
  std::uniform_int_distribution<std::int64_t> c(-kMax, kMax);
  const int n = full_run() ? 200 : 20;
  for (int i = 0; i < n; ++i) {
    const std::int64_t xs = c(rng), ys = c(rng);
    if (xs * xs + ys * ys > kMax * kMax || xs * xs + ys * ys < 2) continue;
    expect_arc(short_arc(xs, ys, i % 2 ? Sense::CW : Sense::CCW, 600));
    if (HasFatalFailure()) return;
  }
}

// Two moves queued before the first command pulse run back to back: every
// command pulse gives a pulse, the second move starts on the command after
// the first one's last pulse. The arc runs as segments: the host writes
// each into the slot the one before it frees (pump) and the main loop arms
// it (settle) between command pulses.
TEST(Queue, TwoMovesBackToBack) {
  Host h;
  const Move a = Move::line(7, -3), b = Move::arc(-5, 0, 0, -5, Sense::CW);
  std::vector<SlotMove> writes = {h.queue(a), h.queue(b)};
  EXPECT_THROW(h.queue(Move::line(1, 1)), std::logic_error);  // the arc's segments wait
  std::size_t cur = 0;
  for (const Move& m : {a, b}) {
    const RunResult want = run_model<24>(m);
    for (std::size_t i = 0; i < want.steps.size(); ++i) {
      const CommandResult c = h.command();
      ASSERT_TRUE(c.pulse.has_value()) << describe(m) << " pulse " << i + 1;
      ASSERT_EQ(*c.pulse, want.steps[i].pulse) << describe(m) << " pulse " << i + 1;
      ASSERT_EQ(h.state(writes[cur], i + 1), want.steps[i].state) << describe(m) << " after pulse " << i + 1;
      if (h.done(writes[cur])) ++cur;
      for (const auto& w : h.pump()) writes.push_back(w);
      h.settle();
    }
  }
  EXPECT_EQ(cur, writes.size());
  EXPECT_GT(writes.size(), 3u);  // the arc took more than one segment
  EXPECT_TRUE(h.can_queue());
  // Nothing queued: a command pulse is counted as idle, no pulse.
  const CommandResult c = h.command();
  EXPECT_FALSE(c.pulse.has_value());
  EXPECT_EQ(h.idle_commands(), 1);
  EXPECT_EQ(h.overruns(), 0u);
}

TEST(Queue, ThirdMoveWaitsForAFreeSlot) {
  Host h;
  h.queue(Move::line(3, 3));
  h.queue(Move::line(2, 2));
  EXPECT_THROW(h.queue(Move::line(1, 1)), std::logic_error);
}

TEST(Queue, BadMoveIsRejectedBeforeTheMailbox) {
  Host h;
  EXPECT_THROW(h.queue(Move::line(kMax + 1, 0)), InputError);
  EXPECT_THROW(h.queue(Move::arc(3, 4, 6, 6, Sense::CW)), InputError);
}

// Three edges while one interrupt routine runs: the first is served, the
// second waits in the RST 7.5 latch and is served next, the third is lost
// and counted.
TEST(Overrun, ThreeEdgesInOneRoutineLoseExactlyOne) {
  Host h;
  const Move m = Move::line(10, 4);
  const SlotMove sm = h.queue(m);
  auto& cpu = h.machine();
  auto edge = [&] {
    cpu.set_rst75(true);
    ++h.bus().edges;
    cpu.step();
    cpu.set_rst75(false);
    cpu.step();
  };
  edge();  // acknowledged at once
  edge();  // latched
  edge();  // latch already set: lost
  h.settle();
  EXPECT_EQ(h.overruns(), 1u);
  const RunResult want = run_model<24>(m);
  EXPECT_EQ(h.state(sm, 2), want.steps[1].state);
}

// Command pulses far too fast: every one is either served (a pulse, or idle
// after the end) or counted as lost, and the moves still give the model's
// pulses in order.
TEST(Overrun, TooFastCommandsAreCountedNeverSilentlyLost) {
  Host h;
  const std::vector<Move> moves = {Move::line(300, -211), Move::arc(40, 9, -9, 40, Sense::CCW), Move::line(-5, 0)};
  std::vector<Pulse> pulses;
  const Host::Timed t = h.drive(moves, 120.0, &pulses);
  ASSERT_TRUE(t.all_done);
  EXPECT_GT(t.overruns, 0u);
  EXPECT_EQ(t.commands, t.pulses + t.overruns + t.idle_commands);
  std::vector<Pulse> want;
  for (const auto& m : moves)
    for (const auto& s : run_model<24>(m).steps) want.push_back(s.pulse);
  EXPECT_EQ(pulses, want);
}

// Drives the moves with a command every period_t T-states: every move
// done, no command lost (overrun) or idle, one pulse per command, and the
// pulses are the model's.
void expect_kept_up_like_the_model(const std::vector<Move>& moves, double period_t) {
  Host h;
  std::vector<Pulse> pulses;
  const Host::Timed t = h.drive(moves, period_t, &pulses);
  ASSERT_TRUE(t.all_done);
  EXPECT_EQ(t.overruns, 0u);
  EXPECT_EQ(t.idle_commands, 0u);
  EXPECT_EQ(t.commands, t.pulses);
  std::vector<Pulse> want;
  for (const auto& m : moves)
    for (const auto& s : run_model<24>(m).steps) want.push_back(s.pulse);
  EXPECT_EQ(pulses, want);
}

// A line of more than 65536 P steps runs as segments (three here, the
// second one switched in while the command train runs), then the next
// move: at a rate the program keeps up with, no command is lost or idle
// between the segments, and the pulses are the model's.
TEST(Queue, LongLineRunsAsSegmentsBackToBack) {
  const std::vector<Move> moves = {Move::line(-131075, 77), Move::line(3, 5), Move::line(0, -131074)};
  expect_kept_up_like_the_model(moves, 260.0);
}

// Arcs run as segments (a new one at every byte wrap, crossing, axis
// arrival and every 256 pulses; some a single pulse long), each written by
// the host as a slot frees while the command train runs and started at the
// end of the one before it (armed by the main loop; or, when it had no
// time, by the next command through h_idle): at a rate the program keeps
// up with (a command every 320 T), no command is lost or idle and the
// pulses are the model's. (Seen passing with the main loop's arming
// broken: h_idle and the RST 7.5 latch carry it at this rate.)
TEST(Queue, ArcSegmentsBackToBackUnderACommandTrain) {
  const std::vector<Move> moves = {short_arc(kMax, 0, Sense::CCW, 1500), Move::arc(300, 0, 300, 0, Sense::CW),
                                   Move::arc(-256, 1, 1, 256, Sense::CW), short_arc(5, -16777200, Sense::CW, 900),
                                   Move::line(3, 5)};
  expect_kept_up_like_the_model(moves, 320.0);
}

TEST(Overrun, SlowEnoughCommandsLoseNone) {
  Host h;
  const std::vector<Move> moves = {Move::line(300, -211), Move::arc(40, 9, -9, 40, Sense::CCW)};
  const Host::Timed t = h.drive(moves, 1200.0);
  ASSERT_TRUE(t.all_done);
  EXPECT_EQ(t.overruns, 0u);
  EXPECT_EQ(t.commands, t.pulses + t.idle_commands);
}

}  // namespace
}  // namespace contour::sw8085
