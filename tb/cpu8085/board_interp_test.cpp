// The interpolation program (sw8085/interp/interp.a80) on the Verilog board:
// sw8085's Host, written for the ISS on a C++ model of the board, drives the
// Verilated board (board8085::make_board_machine) and the ISS side by side;
// every move must give the same pulses and states and every command pulse
// the same T-states and instruction count. The paper's Fig. 2 line pins the
// pulses to the paper as well.
#include <gtest/gtest.h>

#include <cstdio>
#include <random>

#include "board_machine.hpp"
#include "sw8085/interp/host.hpp"

namespace {

using contour::Move;
using contour::Sense;
using contour::sw8085::CommandResult;
using contour::sw8085::Host;

void same_run(const Move& m) {
  SCOPED_TRACE(contour::describe(m));
  Host iss;
  Host board(contour::sw8085::Program::builtin(), board8085::make_board_machine);
  std::vector<CommandResult> ci, cb;
  const contour::RunResult ri = iss.run(m, &ci);
  const contour::RunResult rb = board.run(m, &cb);
  ASSERT_EQ(ri.steps.size(), rb.steps.size());
  for (std::size_t i = 0; i < ri.steps.size(); ++i) {
    ASSERT_EQ(ri.steps[i].pulse, rb.steps[i].pulse) << "pulse " << i;
    ASSERT_EQ(ri.steps[i].state, rb.steps[i].state) << "state after pulse " << i;
  }
  ASSERT_EQ(ci.size(), cb.size());
  for (std::size_t i = 0; i < ci.size(); ++i) {
    ASSERT_EQ(ci[i].tstates, cb[i].tstates) << "T-states of command " << i;
    ASSERT_EQ(ci[i].instructions, cb[i].instructions) << "instructions of command " << i;
    ASSERT_EQ(ci[i].move_ended, cb[i].move_ended) << "command " << i;
  }
  EXPECT_EQ(iss.machine().tstates(), board.machine().tstates());
}

TEST(BoardInterp, PaperFigure2LineOnTheBoard) {
  Host board(contour::sw8085::Program::builtin(), board8085::make_board_machine);
  const contour::RunResult r = board.run(Move::line(6, 5));
  std::string s;
  for (const auto& st : r.steps) s += contour::to_string(st.pulse) + " ";
  EXPECT_EQ(s, "+X +Y +X +Y +X +Y +X +Y +X +Y +X ");
  same_run(Move::line(6, 5));
}

TEST(BoardInterp, PaperFigure5ArcAndMoreMovesSameAsTheIss) {
  same_run(Move::arc(6, 0, 0, 6, Sense::CCW));
  same_run(Move::arc(0, 13, 13, 0, Sense::CW));
  same_run(Move::line(-37, 12));
  same_run(Move::line(0, -9));
  std::mt19937_64 rng(8085);
  for (int i = 0; i < 6; ++i) {
    const auto c = [&rng] { return static_cast<std::int64_t>(rng() % 121) - 60; };
    same_run(Move::line(c(), c()));
  }
}

// Command pulses on a timer, faster than some interrupt routines: moves
// queued back to back, pulses lost to the RST 7.5 latch counted by the
// program through IN 11h. Same counts and pulses on the board as on the ISS.
TEST(BoardInterp, TimedCommandsSameAsTheIss) {
  const std::vector<Move> moves = {Move::line(20, 7), Move::arc(10, 0, 0, 10, Sense::CCW), Move::line(-5, -15)};
  for (double period : {1000.0, 250.0}) {
    SCOPED_TRACE(period);
    Host iss;
    Host board(contour::sw8085::Program::builtin(), board8085::make_board_machine);
    std::vector<contour::Pulse> pi, pb;
    const Host::Timed ti = iss.drive(moves, period, &pi);
    const Host::Timed tb = board.drive(moves, period, &pb);
    EXPECT_TRUE(ti.all_done);
    EXPECT_EQ(ti.commands, tb.commands);
    EXPECT_EQ(ti.pulses, tb.pulses);
    EXPECT_EQ(ti.overruns, tb.overruns);
    EXPECT_EQ(ti.idle_commands, tb.idle_commands);
    EXPECT_EQ(ti.all_done, tb.all_done);
    EXPECT_EQ(pi, pb);
    EXPECT_EQ(iss.machine().tstates(), board.machine().tstates());
    std::printf("  period %.0f T: %llu commands, %llu pulses, %llu lost (overruns), %llu idle\n", period,
                static_cast<unsigned long long>(tb.commands), static_cast<unsigned long long>(tb.pulses),
                static_cast<unsigned long long>(tb.overruns), static_cast<unsigned long long>(tb.idle_commands));
  }
}

}  // namespace
