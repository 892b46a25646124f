// Regression of interp_top, the Wishbone peripheral: register reads and
// writes, moves written over the bus, the step/dir pins checked by a
// timing monitor (any step or dir edge that breaks the programmed timing
// fails the test), the overrun flag and counter under a command rate the
// output cannot follow, the feed generator, the command pin, abort.
//
// Offsets come from the generated gen/interp_regs.h (rtl/interp/regmap.def).
// CONTOUR_FST=FILE: FST trace (use with --gtest_filter).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "Vinterp_top.h"
#include "core_harness.hpp"
#include "harness.hpp"
#include "interp/engine.hpp"
#include "interp_regs.h"

namespace contour {
namespace {

struct Timing {
  std::uint32_t len = 1, space = 1, setup = 1, hold = 1;
};

// Watches one axis' STEP and DIR every clock; records the steps (their
// direction at the rising edge) and every timing violation.
class AxisMonitor {
 public:
  AxisMonitor(Axis a, const Timing* t) : axis_(a), t_(t) {}

  void sample(std::uint64_t c, bool step, bool dir, std::vector<std::string>& errors) {
    auto eff = [](std::uint32_t v) { return v == 0 ? 1u : v; };
    const char* name = axis_ == Axis::X ? "X" : "Y";
    if (dir != dir_) {
      if (step) errors.push_back(std::string(name) + ": DIR changed while STEP high at clock " + std::to_string(c));
      if (have_fall_ && c - fall_ < eff(t_->hold))
        errors.push_back(std::string(name) + ": DIR hold " + std::to_string(c - fall_) + " < " +
                         std::to_string(eff(t_->hold)) + " at clock " + std::to_string(c));
      dir_ = dir;
      dir_change_ = c;
      have_dir_change_ = true;
    }
    if (step && !step_) {
      if (have_fall_ && c - fall_ < eff(t_->space))
        errors.push_back(std::string(name) + ": STEP low " + std::to_string(c - fall_) + " < " +
                         std::to_string(eff(t_->space)) + " at clock " + std::to_string(c));
      if (have_dir_change_ && c - dir_change_ < eff(t_->setup))
        errors.push_back(std::string(name) + ": DIR setup " + std::to_string(c - dir_change_) + " < " +
                         std::to_string(eff(t_->setup)) + " at clock " + std::to_string(c));
      rise_ = c;
      steps.push_back(Pulse{axis_, static_cast<std::int8_t>(dir ? -1 : +1)});
      step_cycles.push_back(c);
    }
    if (!step && step_) {
      if (c - rise_ != eff(t_->len))
        errors.push_back(std::string(name) + ": STEP high " + std::to_string(c - rise_) + " != " +
                         std::to_string(eff(t_->len)) + " at clock " + std::to_string(c));
      fall_ = c;
      have_fall_ = true;
    }
    step_ = step;
  }

  std::vector<Pulse> steps;
  std::vector<std::uint64_t> step_cycles;

 private:
  Axis axis_;
  const Timing* t_;
  bool step_ = false, dir_ = false;
  std::uint64_t rise_ = 0, fall_ = 0, dir_change_ = 0;
  bool have_fall_ = false, have_dir_change_ = false;
};

class TopHarness : public tb::Harness<Vinterp_top> {
 public:
  TopHarness() : mx_(Axis::X, &timing), my_(Axis::Y, &timing) {
    top_->i_cmd_ce = 1;  // no time scale here (the board's, tb/board)
    hold_reset(2);
    tick();
  }

  // Wishbone B4 classic single accesses; fail after 8 clocks without ACK.
  std::uint32_t access(std::uint32_t adr, bool we, std::uint32_t dat) {
    top_->i_wb_cyc = 1;
    top_->i_wb_stb = 1;
    top_->i_wb_we = we;
    top_->i_wb_adr = adr;
    top_->i_wb_dat = dat;
    for (int i = 0; i < 8; ++i) {
      tick();
      if (top_->o_wb_ack) {
        last_ack_clocks = i + 1;
        const std::uint32_t v = top_->o_wb_dat;
        top_->i_wb_cyc = 0;
        top_->i_wb_stb = 0;
        top_->i_wb_we = 0;
        tick();
        return v;
      }
    }
    ADD_FAILURE() << "no Wishbone ACK for address " << adr;
    return 0;
  }
  // Accesses one after another with CYC and STB held high throughout, by
  // a registered master (as link_ctrl): it sees ACK after a clock edge and
  // changes its outputs at the next one, so the slave sees the finished
  // access's signals once more, with ACK high, and must not start it
  // again; the next access follows with no idle clock. (access() above
  // drops STB as soon as it sees ACK.) Returns the data of every access
  // (0 for writes); fails on a missing ACK or an ACK in two clocks in a row.
  struct Access {
    std::uint32_t adr;
    bool we;
    std::uint32_t dat;
  };
  std::vector<std::uint32_t> burst(const std::vector<Access>& list) {
    std::vector<std::uint32_t> out;
    top_->i_wb_cyc = 1;
    top_->i_wb_stb = 1;
    for (const Access& a : list) {
      top_->i_wb_we = a.we;
      top_->i_wb_adr = a.adr;
      top_->i_wb_dat = a.dat;
      bool acked = false;
      for (int i = 0; i < 8 && !acked; ++i) {
        tick();
        if (top_->o_wb_ack) {
          acked = true;
          out.push_back(a.we ? 0u : std::uint32_t(top_->o_wb_dat));
        }
      }
      if (!acked) ADD_FAILURE() << "no Wishbone ACK for address " << a.adr << " in a burst";
      tick();  // the master's outputs change at this edge: the slave sees them unchanged
      EXPECT_FALSE(top_->o_wb_ack) << "ACK in two clocks in a row, address " << a.adr;
    }
    top_->i_wb_cyc = 0;
    top_->i_wb_stb = 0;
    top_->i_wb_we = 0;
    for (int i = 0; i < 4; ++i) {
      tick();
      EXPECT_FALSE(top_->o_wb_ack) << "ACK after the burst";
    }
    return out;
  }

  int last_ack_clocks = 0;  // clocks from STB to ACK of the last access()
  void write(std::uint32_t adr, std::uint32_t v) { access(adr, true, v); }
  std::uint32_t read(std::uint32_t adr) { return access(adr, false, 0); }

  void set_timing(const Timing& t) {
    timing = t;
    write(INTERP_REG_STEP_LEN, t.len);
    write(INTERP_REG_STEP_SPACE, t.space);
    write(INTERP_REG_DIR_SETUP, t.setup);
    write(INTERP_REG_DIR_HOLD, t.hold);
  }

  // Stages and pushes a move as the host would (validation at W = 24).
  void push(const Move& m) {
    const rtl::Block b = rtl::make_block<24>(m);
    const std::uint32_t mode = (b.arc << INTERP_BLK_MODE_ARC_LSB) | (b.cw << INTERP_BLK_MODE_CW_LSB) |
                               (b.sxn << INTERP_BLK_MODE_SXN_LSB) | (b.syn << INTERP_BLK_MODE_SYN_LSB) |
                               (std::uint32_t(b.q) << INTERP_BLK_MODE_Q_LSB) |
                               (std::uint32_t(b.k) << INTERP_BLK_MODE_K_LSB);
    write(INTERP_REG_BLK_MODE, mode);
    write(INTERP_REG_BLK_CI, std::uint32_t(b.ci));
    write(INTERP_REG_BLK_CO, std::uint32_t(b.co));
    write(INTERP_REG_BLK_TI, std::uint32_t(b.ti));
    write(INTERP_REG_BLK_TO, std::uint32_t(b.to));
    write(INTERP_REG_PUSH, 1);
  }
  // The same, but as a host may by the register map: a line's CI, CO
  // (ignored) left as the previous block wrote them and its quadrant and
  // crossings bits all ones, an arc's sign bits both set (ignored too).
  void push_leaving_unused(const Move& m) {
    const rtl::Block b = rtl::make_block<24>(m);
    const std::uint32_t mode =
        b.arc ? INTERP_BLK_MODE_ARC_MASK | (b.cw << INTERP_BLK_MODE_CW_LSB) | INTERP_BLK_MODE_SXN_MASK |
                    INTERP_BLK_MODE_SYN_MASK | (std::uint32_t(b.q) << INTERP_BLK_MODE_Q_LSB) |
                    (std::uint32_t(b.k) << INTERP_BLK_MODE_K_LSB)
              : (b.sxn << INTERP_BLK_MODE_SXN_LSB) | (b.syn << INTERP_BLK_MODE_SYN_LSB) | INTERP_BLK_MODE_Q_MASK |
                    INTERP_BLK_MODE_K_MASK;
    write(INTERP_REG_BLK_MODE, mode);
    if (b.arc) {
      write(INTERP_REG_BLK_CI, std::uint32_t(b.ci));
      write(INTERP_REG_BLK_CO, std::uint32_t(b.co));
    }
    write(INTERP_REG_BLK_TI, std::uint32_t(b.ti));
    write(INTERP_REG_BLK_TO, std::uint32_t(b.to));
    write(INTERP_REG_PUSH, 1);
  }

  // Runs clocks until the queue is empty, the core idle and both STEP
  // outputs low for a while (or `max` clocks).
  void run_until_idle(std::uint64_t max) {
    std::uint64_t quiet = 0;
    for (std::uint64_t i = 0; i < max && quiet < 64; ++i) {
      tick();
      const bool idle = !top_->o_busy && !top_->o_step_x && !top_->o_step_y;
      quiet = idle ? quiet + 1 : 0;
    }
  }

  // The pin-level pulses of both axes in the order of their rising edges.
  std::vector<Pulse> pin_pulses() const {
    std::vector<std::pair<std::uint64_t, Pulse>> all;
    for (std::size_t i = 0; i < mx_.steps.size(); ++i) all.push_back({mx_.step_cycles[i], mx_.steps[i]});
    for (std::size_t i = 0; i < my_.steps.size(); ++i) all.push_back({my_.step_cycles[i], my_.steps[i]});
    std::stable_sort(all.begin(), all.end(), [](auto& a, auto& b) { return a.first < b.first; });
    std::vector<Pulse> v;
    for (auto& p : all) v.push_back(p.second);
    return v;
  }

  std::string error_text() const {
    std::ostringstream o;
    for (std::size_t i = 0; i < errors.size() && i < 5; ++i) o << errors[i] << "\n";
    return o.str();
  }

  Timing timing;
  std::vector<std::string> errors;
  std::uint64_t core_pulses = 0, busy_cycles = 0;
  unsigned ce_period = 0;  // i_cmd_ce: 0 always high; N high one clock in N

 private:
  // Every clock: the pins through the timing monitors, the core's counts.
  void after_clock() override {
    mx_.sample(clocks(), top_->o_step_x, top_->o_dir_x, errors);
    my_.sample(clocks(), top_->o_step_y, top_->o_dir_y, errors);
    if (top_->o_pulse) ++core_pulses;
    if (top_->o_busy) ++busy_cycles;
    if (ce_period != 0) top_->i_cmd_ce = clocks() % ce_period == 0;
  }

  Vinterp_top* const top_ = &top();
  AxisMonitor mx_, my_;
};

std::vector<Pulse> model_pulses(const std::vector<Move>& moves) {
  std::vector<Pulse> v;
  for (const Move& m : moves)
    for (const auto& s : run_model<24>(m).steps) v.push_back(s.pulse);
  return v;
}

// The end position of a list of moves (lines relative, arcs about their
// centre: the position changes by end - start).
std::pair<std::int64_t, std::int64_t> displacement(const std::vector<Move>& moves) {
  std::int64_t x = 0, y = 0;
  for (const Move& m : moves) {
    x += m.xe - m.xs;
    y += m.ye - m.ys;
  }
  return {x, y};
}

std::uint32_t status(TopHarness& h) { return h.read(INTERP_REG_STATUS); }

// Runs `moves` through the bus with a command source and the given timing;
// checks the pins carry exactly the model's pulses, the timing monitor is
// clean and the position counters end at the end point.
// Returns the busy clocks and core pulses counted from the command start.
std::pair<std::uint64_t, std::uint64_t> run_and_check(TopHarness& h, const std::vector<Move>& moves,
                                                      std::uint32_t src, std::uint32_t feed,
                                                      std::uint64_t max_clocks, bool leave_unused = false) {
  h.write(INTERP_REG_FEED, feed);
  for (const Move& m : moves) leave_unused ? h.push_leaving_unused(m) : h.push(m);
  h.write(INTERP_REG_CTRL, src << INTERP_CTRL_SRC_LSB);
  const std::uint64_t busy0 = h.busy_cycles, pulses0 = h.core_pulses;
  h.run_until_idle(max_clocks);
  const std::pair<std::uint64_t, std::uint64_t> counts{h.busy_cycles - busy0, h.core_pulses - pulses0};
  h.write(INTERP_REG_CTRL, 0);
  const auto want = model_pulses(moves);
  const auto got = h.pin_pulses();
  EXPECT_EQ(got.size(), want.size()) << "steps on the pins";
  for (std::size_t i = 0; i < want.size() && i < got.size(); ++i) {
    EXPECT_EQ(got[i], want[i]) << "step " << i + 1;
    if (!(got[i] == want[i])) break;
  }
  EXPECT_TRUE(h.errors.empty()) << h.error_text();
  const auto [dx, dy] = displacement(moves);
  EXPECT_EQ(std::int32_t(h.read(INTERP_REG_POS_X)), dx);
  EXPECT_EQ(std::int32_t(h.read(INTERP_REG_POS_Y)), dy);
  EXPECT_EQ(h.read(INTERP_REG_MOVES), moves.size());
  if (!h.errors.empty()) h.close_trace();
  return counts;
}

TEST(InterpTop, RegistersReadAndWrite) {
  TopHarness h;
  // "INTP" in ASCII, independent of the generated constant.
  EXPECT_EQ(h.read(INTERP_REG_ID), 0x494E5450u);
  EXPECT_EQ(INTERP_ID_RESET, 0x494E5450u);
  const std::uint32_t params = h.read(INTERP_REG_PARAMS);
  EXPECT_EQ((params & INTERP_PARAMS_W_MASK) >> INTERP_PARAMS_W_LSB, 24u);
  EXPECT_EQ((params & INTERP_PARAMS_QDEPTH_MASK) >> INTERP_PARAMS_QDEPTH_LSB, 18u);
  // Reset values: queue empty, nothing running.
  EXPECT_EQ(status(h), std::uint32_t(INTERP_STATUS_EMPTY_MASK));
  EXPECT_EQ(h.read(INTERP_REG_POS_X), 0u);
  // CTRL.SRC reads back what was written (ABORT and CLEAR are strobes).
  for (std::uint32_t v : {0xFFFFFFFFu, 0x12345678u, 0u, 0xA5A5A5A5u}) {
    h.write(INTERP_REG_CTRL, v & INTERP_CTRL_SRC_MASK);
    EXPECT_EQ(h.read(INTERP_REG_CTRL), v & INTERP_CTRL_SRC_MASK);
  }
  h.write(INTERP_REG_CTRL, 0);
  // The configuration and the staged block are write only: they read 0
  // whatever was written (what a write does is checked by the moves, the
  // timing monitor and the feed rates of the tests below).
  for (std::uint32_t adr : {INTERP_REG_FEED, INTERP_REG_STEP_LEN, INTERP_REG_STEP_SPACE, INTERP_REG_DIR_SETUP,
                            INTERP_REG_DIR_HOLD, INTERP_REG_BLK_MODE, INTERP_REG_BLK_CI, INTERP_REG_BLK_CO,
                            INTERP_REG_BLK_TI, INTERP_REG_BLK_TO, INTERP_REG_PUSH}) {
    EXPECT_EQ(h.read(adr), 0u) << "register 0x" << std::hex << adr << " after reset";
    if (adr != INTERP_REG_PUSH) h.write(adr, 0xFFFFFFFFu);
    EXPECT_EQ(h.read(adr), 0u) << "register 0x" << std::hex << adr;
  }
  // Read-only registers ignore writes.
  h.write(INTERP_REG_ID, 0);
  h.write(INTERP_REG_POS_X, 55);
  EXPECT_EQ(h.read(INTERP_REG_ID), 0x494E5450u);
  EXPECT_EQ(h.read(INTERP_REG_POS_X), 0u);
  h.write(INTERP_REG_CTRL, 0);
}

// The bus timing (wb_regs, docs/regmap.md): ACK two clocks after STB for
// reads and writes alike, the read data with it.
TEST(InterpTop, AckTwoClocksAfterTheStrobe) {
  TopHarness h;
  EXPECT_EQ(h.read(INTERP_REG_ID), 0x494E5450u);
  EXPECT_EQ(h.last_ack_clocks, 2) << "read";
  h.write(INTERP_REG_CTRL, 1);
  EXPECT_EQ(h.last_ack_clocks, 2) << "write";
  EXPECT_EQ(h.read(INTERP_REG_CTRL), 1u);
  EXPECT_EQ(h.last_ack_clocks, 2) << "read";
}

// Accesses back to back with the strobe held (a registered master: no idle
// clock between them, its signals seen once more with ACK): each is done
// exactly once (one push a PUSH write, not two), every read
// returns its own word, and a write is seen by the read right after it.
TEST(InterpTop, BackToBackAccessesHoldingTheStrobe) {
  TopHarness h;
  const rtl::Block b = rtl::make_block<24>(Move::line(3, 2));
  const std::uint32_t mode = (b.arc << INTERP_BLK_MODE_ARC_LSB) | (b.cw << INTERP_BLK_MODE_CW_LSB) |
                             (b.sxn << INTERP_BLK_MODE_SXN_LSB) | (b.syn << INTERP_BLK_MODE_SYN_LSB);
  using A = TopHarness::Access;
  std::vector<A> list = {
      {INTERP_REG_CTRL, true, 3u << INTERP_CTRL_SRC_LSB},
      {INTERP_REG_CTRL, false, 0},
      {INTERP_REG_ID, false, 0},
      {INTERP_REG_PARAMS, false, 0},
      {INTERP_REG_CTRL, true, 0},
      {INTERP_REG_CTRL, false, 0},
      {INTERP_REG_BLK_MODE, true, mode},
      {INTERP_REG_BLK_CI, true, std::uint32_t(b.ci)},
      {INTERP_REG_BLK_CO, true, std::uint32_t(b.co)},
      {INTERP_REG_BLK_TI, true, std::uint32_t(b.ti)},
      {INTERP_REG_BLK_TO, true, std::uint32_t(b.to)},
      {INTERP_REG_PUSH, true, 1},
      {INTERP_REG_PUSH, true, 1},
      {INTERP_REG_MOVES, false, 0},
  };
  const auto r = h.burst(list);
  ASSERT_EQ(r.size(), list.size());
  EXPECT_EQ(r[1], 3u << INTERP_CTRL_SRC_LSB) << "CTRL read right after its write";
  EXPECT_EQ(r[2], 0x494E5450u);
  EXPECT_EQ((r[3] & INTERP_PARAMS_W_MASK) >> INTERP_PARAMS_W_LSB, 24u);
  EXPECT_EQ(r[5], 0u) << "CTRL read right after its second write";
  EXPECT_EQ(r[13], 0u) << "MOVES: nothing has run";
  // The queue holds both blocks (LEVEL counts the queue, not a block the
  // datapath has taken: 1 or 2 here); a PUSH done twice would show as a
  // third move below.
  EXPECT_FALSE(status(h) & INTERP_STATUS_REJECT_MASK);
  // The two blocks run: 2 x 3 steps, the position at (6, 4).
  h.set_timing({1, 1, 1, 1});
  h.write(INTERP_REG_FEED, 0x40000000u);
  h.write(INTERP_REG_CTRL, 2 << INTERP_CTRL_SRC_LSB);
  h.run_until_idle(100000);
  EXPECT_EQ(h.read(INTERP_REG_POS_X), 6u);
  EXPECT_EQ(h.read(INTERP_REG_POS_Y), 4u);
  EXPECT_EQ(h.read(INTERP_REG_MOVES), 2u);
  EXPECT_TRUE(h.errors.empty()) << h.error_text();
}

TEST(InterpTop, QueueFullRefusesAPushAndFlagsIt) {
  TopHarness h;
  for (int i = 0; i < 18; ++i) h.push(Move::line(1, 1));
  std::uint32_t s = status(h);
  EXPECT_TRUE(s & INTERP_STATUS_FULL_MASK);
  EXPECT_FALSE(s & INTERP_STATUS_REJECT_MASK);
  h.push(Move::line(100, 0));  // refused
  s = status(h);
  EXPECT_TRUE(s & INTERP_STATUS_REJECT_MASK);
  // The 18 accepted blocks run, the refused one does not.
  h.set_timing({1, 1, 1, 1});
  h.write(INTERP_REG_CTRL, 2 << INTERP_CTRL_SRC_LSB);
  h.write(INTERP_REG_FEED, 0x40000000u);  // every 4th clock
  h.run_until_idle(100000);
  EXPECT_EQ(h.read(INTERP_REG_POS_X), 18u);
  EXPECT_EQ(h.read(INTERP_REG_POS_Y), 18u);
  EXPECT_EQ(h.read(INTERP_REG_MOVES), 18u);
  EXPECT_TRUE(status(h) & INTERP_STATUS_REJECT_MASK) << "sticky";
  h.write(INTERP_REG_CTRL, INTERP_CTRL_CLEAR_MASK);
  EXPECT_FALSE(status(h) & INTERP_STATUS_REJECT_MASK);
  EXPECT_TRUE(status(h) & INTERP_STATUS_EMPTY_MASK);
  EXPECT_TRUE(h.errors.empty()) << h.error_text();
}

// Feed generator at a rate the output follows: every pulse on the pins, in
// order, with the programmed timing, and no overrun.
TEST(InterpTop, FeedGeneratorMovesWithinTiming) {
  TopHarness h;
  h.set_timing({3, 2, 2, 3});
  // One command per 16 clocks; a step needs at most 3 + 2 + 3 + 2 = 10.
  run_and_check(h,
                {Move::line(40, -25), Move::arc(30, 0, 0, 30, Sense::CCW), Move::arc(0, 30, 30, 0, Sense::CW),
                 Move::line(-40, 25), Move::arc(5, 5, 5, 5, Sense::CW)},
                2, 0x10000000u, 200000);
  const std::uint32_t s = status(h);
  EXPECT_FALSE(s & INTERP_STATUS_OVERRUN_MASK);
  EXPECT_EQ(h.read(INTERP_REG_OVR_COUNT), 0u);
}

// The fields a kind does not use are ignored (regmap.def), whatever the
// host leaves in them: lines after arcs with CI, CO not written (nonzero
// from the arc) and Q, K all ones; arcs with SXN, SYN set (wb_regs zeroes
// them; interp_core requires them zero).
TEST(InterpTop, UnusedFieldsOfABlockAreIgnored) {
  TopHarness h;
  run_and_check(h,
                {Move::arc(30, 0, 0, 30, Sense::CCW), Move::line(40, -25), Move::arc(-20, 9, 9, -20, Sense::CW),
                 Move::line(-7, 9), Move::arc(0, -17, 17, 0, Sense::CCW), Move::line(0, 12), Move::line(5, 0)},
                2, 0x10000000u, 400000, true);
}

// The command source's clock enable (the board's time scale, its feed
// hold: docs/board.md): the feed generator and the every-clock source
// advance only on it. High one clock in 3, a move at a feed takes 3 times
// as long; one clock in 8 with a command every clock, 8 clocks a pulse;
// the pulses are the model's.
TEST(InterpTop, CommandClockEnableScalesTheCommandRate) {
  const std::vector<Move> moves{Move::line(40, -25), Move::arc(30, 0, 0, 30, Sense::CCW)};
  TopHarness full, slow, every;
  for (TopHarness* h : {&full, &slow, &every}) h->set_timing({1, 1, 1, 1});
  const auto [busy1, pulses1] = run_and_check(full, moves, 2, 0x10000000u, 200000);
  slow.ce_period = 3;
  const auto [busy3, pulses3] = run_and_check(slow, moves, 2, 0x10000000u, 600000);
  EXPECT_EQ(pulses1, pulses3);
  EXPECT_NEAR(static_cast<double>(busy3) / static_cast<double>(busy1), 3.0, 0.05);
  every.ce_period = 8;
  const auto [busy8, pulses8] = run_and_check(every, moves, 3, 0, 200000);
  EXPECT_NEAR(static_cast<double>(busy8) / static_cast<double>(pulses8), 8.0, 0.1);
  EXPECT_EQ(every.read(INTERP_REG_OVR_COUNT), 0u);
}

// Every clock a command pulse, far faster than the output timing allows:
// the overrun flag and counter say so, and still no pulse is lost and no
// timing is broken.
TEST(InterpTop, OverrunFlagAndCounterUnderTooFastCommands) {
  TopHarness h;
  h.set_timing({4, 3, 2, 2});
  const std::vector<Move> moves{Move::line(17, 9), Move::arc(8, 0, -8, 0, Sense::CW)};
  const auto [busy, pulses] = run_and_check(h, moves, 3, 0, 100000);
  const std::uint32_t s = status(h);
  EXPECT_TRUE(s & INTERP_STATUS_OVERRUN_MASK);
  // Every busy clock brought a command; the ones that made no pulse were
  // refused and counted (give or take the clocks around the start).
  const std::uint64_t refused = busy - pulses;
  const std::uint32_t ovr = h.read(INTERP_REG_OVR_COUNT);
  EXPECT_GT(ovr, 0u);
  EXPECT_LE(ovr, refused + 2);
  EXPECT_GE(ovr + 2, refused);
  h.write(INTERP_REG_CTRL, INTERP_CTRL_CLEAR_MASK);
  EXPECT_FALSE(status(h) & INTERP_STATUS_OVERRUN_MASK);
  EXPECT_EQ(h.read(INTERP_REG_OVR_COUNT), 0u);
}

// OVR_COUNT counts up to 2^16 - 1 and stays there: commands every clock
// against the slowest steps (4095 clocks high, 4095 low: the 12-bit timing
// registers' largest), well past the count's end.
TEST(InterpTop, OverrunCountSaturates) {
  TopHarness h;
  h.set_timing({4095, 4095, 1, 1});
  h.push(Move::line(50, 0));
  h.write(INTERP_REG_CTRL, 3 << INTERP_CTRL_SRC_LSB);
  for (int i = 0; i < 40000; ++i) h.tick();
  const std::uint32_t part = h.read(INTERP_REG_OVR_COUNT);
  EXPECT_GT(part, 30000u);
  EXPECT_LT(part, 65535u);
  for (int i = 0; i < 60000; ++i) h.tick();
  EXPECT_EQ(h.read(INTERP_REG_OVR_COUNT), 65535u);
  for (int i = 0; i < 100; ++i) h.tick();
  EXPECT_EQ(h.read(INTERP_REG_OVR_COUNT), 65535u);
  h.write(INTERP_REG_CTRL, 0);
  h.write(INTERP_REG_CTRL, INTERP_CTRL_CLEAR_MASK);
  EXPECT_EQ(h.read(INTERP_REG_OVR_COUNT), 0u);
  EXPECT_TRUE(h.errors.empty()) << h.error_text();
}

// Long DIR setup and hold against short steps, commands every clock, many
// direction reversals (small full circles): DIR timing is what binds.
TEST(InterpTop, DirSetupAndHoldBindUnderFastCommands) {
  for (const Timing t : {Timing{2, 1, 7, 9}, Timing{1, 1, 12, 1}, Timing{1, 1, 1, 12}, Timing{5, 9, 0, 0}}) {
    TopHarness h;
    h.set_timing(t);
    run_and_check(h, {Move::arc(3, 0, 3, 0, Sense::CCW), Move::arc(2, 1, 2, 1, Sense::CW), Move::line(-3, 2)}, 3, 0,
                  100000);
    EXPECT_TRUE(status(h) & INTERP_STATUS_OVERRUN_MASK);
  }
}

// Changing the feed while running changes the command rate at once.
TEST(InterpTop, FeedIsWritableWhileRunning) {
  TopHarness h;
  h.set_timing({1, 1, 1, 1});
  h.push(Move::line(100000, 0));
  h.write(INTERP_REG_FEED, 0x08000000u);  // 1/32 of the clock
  h.write(INTERP_REG_CTRL, 2 << INTERP_CTRL_SRC_LSB);
  std::uint64_t p0 = h.core_pulses;
  for (int i = 0; i < 3200; ++i) h.tick();
  const std::uint64_t slow = h.core_pulses - p0;
  h.write(INTERP_REG_FEED, 0x20000000u);  // 1/8
  p0 = h.core_pulses;
  for (int i = 0; i < 3200; ++i) h.tick();
  const std::uint64_t fast = h.core_pulses - p0;
  EXPECT_NEAR(double(slow), 100.0, 2.0);
  EXPECT_NEAR(double(fast), 400.0, 2.0);
  EXPECT_FALSE(status(h) & INTERP_STATUS_OVERRUN_MASK);
  h.write(INTERP_REG_CTRL, INTERP_CTRL_ABORT_MASK);
  EXPECT_EQ(status(h) & (INTERP_STATUS_BUSY_MASK | INTERP_STATUS_EMPTY_MASK), INTERP_STATUS_EMPTY_MASK);
  EXPECT_TRUE(h.errors.empty()) << h.error_text();
}

// The feed generator's command count over n clocks is n * FEED / 2^32 (the
// phase accumulator's carries; its low half's carry reaches the output a
// step late: +-1; the CTRL writes around the run: a few clocks), for
// increments whose low 16 bits matter. Every command
// is a core pulse or an overrun (the move is running throughout).
TEST(InterpTop, FeedGeneratorCountsEveryCarry) {
  const std::pair<std::uint32_t, std::uint64_t> cases[] = {
      {0x0001FFFFu, 1u << 20}, {0x00012345u, 1u << 20}, {0x7FFFFFFFu, 100000}, {0xFFFFFFFFu, 60000}};
  for (const auto& [feed, n] : cases) {
    TopHarness h;
    h.set_timing({1, 1, 1, 1});
    h.push(Move::line(1000000, 0));
    h.write(INTERP_REG_CTRL, 1 << INTERP_CTRL_SRC_LSB);  // the pin: no command yet
    for (int i = 0; i < 20 && !h.top().o_busy; ++i) h.tick();
    ASSERT_TRUE(h.top().o_busy);
    h.write(INTERP_REG_FEED, feed);
    const std::uint64_t p0 = h.core_pulses;
    h.write(INTERP_REG_CTRL, 2 << INTERP_CTRL_SRC_LSB);
    for (std::uint64_t i = 0; i < n; ++i) h.tick();
    h.write(INTERP_REG_CTRL, 0);
    const double commands = double(h.core_pulses - p0) + double(h.read(INTERP_REG_OVR_COUNT));
    const double want = double(n) * double(feed) / 4294967296.0;
    EXPECT_NEAR(commands, want, 3.0) << "FEED 0x" << std::hex << feed;  // + the clocks of the CTRL writes
    EXPECT_TRUE(h.errors.empty()) << h.error_text();
  }
}

// The command pin: one pulse per rising edge, however long it stays high.
TEST(InterpTop, CommandPinOnePulsePerRisingEdge) {
  TopHarness h;
  h.set_timing({2, 2, 1, 1});
  h.push(Move::line(7, -3));
  h.write(INTERP_REG_CTRL, 1 << INTERP_CTRL_SRC_LSB);
  for (int e = 0; e < 6; ++e) {
    h.top().i_cmd_pin = 1;
    for (int i = 0; i < 5 + 3 * e; ++i) h.tick();
    h.top().i_cmd_pin = 0;
    for (int i = 0; i < 12; ++i) h.tick();
  }
  EXPECT_EQ(h.core_pulses, 6u);
  EXPECT_EQ(h.pin_pulses().size(), 6u);
  const auto want = model_pulses({Move::line(7, -3)});
  for (std::size_t i = 0; i < 6; ++i) EXPECT_EQ(h.pin_pulses()[i], want[i]);
  EXPECT_TRUE(h.errors.empty()) << h.error_text();
}

// Every command pulse that comes while a move runs either makes exactly one
// core pulse or is refused and counted, never both and never neither: two
// pin edges k clocks apart, for every k across a step's output time, so
// the second one meets the output stage in each of its states (the clock
// a channel frees, the clock after a command was passed, ...).
TEST(InterpTop, EveryCommandIsAPulseOrAnOverrun) {
  for (int k = 1; k <= 24; ++k) {
    TopHarness h;
    h.set_timing({4, 3, 2, 2});
    h.push(Move::line(40, 0));
    h.write(INTERP_REG_CTRL, 1 << INTERP_CTRL_SRC_LSB);
    for (int i = 0; i < 20 && !h.top().o_busy; ++i) h.tick();
    ASSERT_TRUE(h.top().o_busy);
    const std::uint64_t p0 = h.core_pulses;
    for (int e = 0; e < 2; ++e) {
      h.top().i_cmd_pin = 1;
      for (int i = 0; i < (e == 0 ? k : 3); ++i) h.tick();
      h.top().i_cmd_pin = 0;
      for (int i = 0; i < (e == 0 ? 1 : 30); ++i) h.tick();
    }
    const std::uint64_t pulses = h.core_pulses - p0;
    const std::uint32_t ovr = h.read(INTERP_REG_OVR_COUNT);
    EXPECT_GE(pulses, 1u) << "k = " << k;
    EXPECT_EQ(pulses + ovr, 2u) << "k = " << k << ": " << pulses << " pulses, " << ovr << " refused";
    EXPECT_EQ(bool(status(h) & INTERP_STATUS_OVERRUN_MASK), ovr != 0) << "k = " << k;
    EXPECT_TRUE(h.errors.empty()) << h.error_text();
  }
}

// Reset in the middle of a move through the bus: abort, then a new move
// runs exactly as the model says.
TEST(InterpTop, AbortInTheMiddleThenANewMove) {
  TopHarness h;
  h.set_timing({1, 1, 1, 1});
  h.push(Move::arc(500, 0, 500, 0, Sense::CCW));
  h.push(Move::line(9, 9));
  h.write(INTERP_REG_FEED, 0x40000000u);
  h.write(INTERP_REG_CTRL, 2 << INTERP_CTRL_SRC_LSB);
  for (int i = 0; i < 2000; ++i) h.tick();
  EXPECT_TRUE(status(h) & INTERP_STATUS_BUSY_MASK);
  h.write(INTERP_REG_CTRL, (2 << INTERP_CTRL_SRC_LSB) | INTERP_CTRL_ABORT_MASK);
  const std::uint64_t p0 = h.core_pulses;
  for (int i = 0; i < 200; ++i) h.tick();
  EXPECT_EQ(h.core_pulses, p0);
  EXPECT_EQ(status(h) & (INTERP_STATUS_BUSY_MASK | INTERP_STATUS_EMPTY_MASK), INTERP_STATUS_EMPTY_MASK);
  h.write(INTERP_REG_CTRL, 0);
  // The aborted arc's pulses so far: the position registers agree with the
  // pins, and the queued line(9, 9) was dropped.
  const std::size_t n0 = h.pin_pulses().size();
  ASSERT_GT(n0, 0u);
  std::int64_t x0 = 0, y0 = 0;
  for (const Pulse& p : h.pin_pulses()) (p.axis == Axis::X ? x0 : y0) += p.sign;
  EXPECT_EQ(std::int32_t(h.read(INTERP_REG_POS_X)), x0);
  EXPECT_EQ(std::int32_t(h.read(INTERP_REG_POS_Y)), y0);
  // A new move after the abort runs whole, from where the abort left off.
  const Move next = Move::line(7, -4);
  h.push(next);
  h.write(INTERP_REG_CTRL, 2 << INTERP_CTRL_SRC_LSB);
  h.run_until_idle(200000);
  h.write(INTERP_REG_CTRL, 0);
  const auto all = h.pin_pulses();
  const std::vector<Pulse> got(all.begin() + std::ptrdiff_t(std::min(n0, all.size())), all.end());
  EXPECT_EQ(got, model_pulses({next}));
  EXPECT_EQ(std::int32_t(h.read(INTERP_REG_POS_X)), x0 + 7);
  EXPECT_EQ(std::int32_t(h.read(INTERP_REG_POS_Y)), y0 - 4);
  EXPECT_EQ(status(h) & (INTERP_STATUS_BUSY_MASK | INTERP_STATUS_EMPTY_MASK), INTERP_STATUS_EMPTY_MASK);
  EXPECT_TRUE(h.errors.empty()) << h.error_text();
}

}  // namespace
}  // namespace contour
