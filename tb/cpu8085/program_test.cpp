// The interpolation program (sw8085/interp) on the Verilated 8085 CPU
// (rtl/cpu8085) with the C++ board, and on the Verilated board
// rtl/board8085 (the engine "cpu"), against the golden model.
#include <gtest/gtest.h>

#include <cstdlib>

#include "board_machine.hpp"
#include "cpu_machine.hpp"
#include "interp/engine.hpp"
#include "sw8085/interp/expect_model.hpp"
#include "sw8085/interp/host.hpp"

namespace contour::sw8085 {
namespace {

// CONTOUR_FULL=1 (set, not empty, not 0): the long runs.
bool full_run() {
  const char* e = std::getenv("CONTOUR_FULL");
  return e != nullptr && *e != '\0' && *e != '0';
}

std::unique_ptr<i8085::Machine> rtl(i8085::Bus& bus, i8085::Mode mode) {
  return cpu8085::make_cpu_machine(bus, mode);
}

TEST(Rtl, PaperExamplesAndSmallMoves) {
  Host h(Program::builtin(), rtl);
  expect_model_run(h, Move::line(6, 5));
  expect_model_run(h, Move::arc(6, 0, 0, 6, Sense::CCW));
  const int n = full_run() ? 8 : 3;
  for (int xe = -n; xe <= n; ++xe)
    for (int ye = -n; ye <= n; ++ye) {
      expect_model_run(h, Move::line(xe, ye));
      if (HasFatalFailure()) return;
    }
  int arcs = 0;
  for (Sense s : {Sense::CCW, Sense::CW})
    for (const Move& m : {Move::arc(5, 0, 5, 0, s), Move::arc(-3, 4, 4, -3, s), Move::arc(7, 1, -1, -7, s),
                          Move::arc(2, -9, 9, 2, s)}) {
      if (!accepted(m)) continue;
      expect_model_run(h, m);
      if (HasFatalFailure()) return;
      ++arcs;
    }
  EXPECT_EQ(arcs, 8);  // every end is on its start's circle: all are accepted
}

TEST(Rtl, ByteBoundariesOfTheCounters) {
  Host h(Program::builtin(), rtl);
  expect_model_run(h, Move::line(257, -2));
  expect_model_run(h, Move::line(-1, 512));
}

TEST(Rtl, OverrunsAreCountedOnTheVerilogCpu) {
  Host h(Program::builtin(), rtl);
  const auto t = h.drive({Move::line(40, -17), Move::arc(9, 2, -2, 9, Sense::CCW)}, 100.0);
  ASSERT_TRUE(t.all_done);
  EXPECT_GT(t.overruns, 0u);
  EXPECT_EQ(t.commands, t.pulses + t.overruns + t.idle_commands);
}

// The engine "cpu": the board in Verilog.
TEST(Board, PaperExamplesSmallMovesQueueAndOverruns) {
  const i8085::MachineFactory board = board8085::make_board_machine;
  {
    // One board at a time: two Verilated boards alive together deadlock in
    // their destructors (Verilator 5.006, VerilatedContextImp::scopeErase).
    Host h(Program::builtin(), board);
    expect_model_run(h, Move::line(6, 5));
    expect_model_run(h, Move::arc(6, 0, 0, 6, Sense::CCW));
    for (int xe = -3; xe <= 3; ++xe)
      for (int ye = -3; ye <= 3; ++ye) {
        expect_model_run(h, Move::line(xe, ye));
        if (HasFatalFailure()) return;
      }
    for (Sense s : {Sense::CCW, Sense::CW}) {
      expect_model_run(h, Move::arc(5, 0, 5, 0, s));
      expect_model_run(h, Move::arc(-3, 4, 4, -3, s));
      if (HasFatalFailure()) return;
  }
    expect_model_run(h, Move::line(257, -2));
  }
  Host fast(Program::builtin(), board);
  const auto t = fast.drive({Move::line(40, -17), Move::arc(9, 2, -2, 9, Sense::CCW)}, 100.0);
  ASSERT_TRUE(t.all_done);
  EXPECT_GT(t.overruns, 0u);
  EXPECT_EQ(t.commands, t.pulses + t.overruns + t.idle_commands);
}

}  // namespace
}  // namespace contour::sw8085
