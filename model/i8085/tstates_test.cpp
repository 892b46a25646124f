// T-states of all 256 opcodes in both modes, against tables typed from the
// Intel documents (docs/i8085.md, "T-states"): the 8085AH data sheet's
// instruction summary and the 8080A data sheet / 8080 Assembly Language
// Programming Manual. "a/b" is not taken / taken for conditional jumps,
// calls and returns. `u` marks the 8085's undocumented opcodes, which this
// simulator runs as a 4-state NOP (docs/i8085.md, "Undocumented opcodes").
#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "i8085/test_util.hpp"

namespace i8085 {
namespace {

// Rows are the high nibble of the opcode, columns the low nibble.
const char* const k8085[16] = {
    /*0*/ "4 10 7 6 4 4 7 4 u 10 7 6 4 4 7 4",
    /*1*/ "u 10 7 6 4 4 7 4 u 10 7 6 4 4 7 4",
    /*2*/ "4 10 16 6 4 4 7 4 u 10 16 6 4 4 7 4",
    /*3*/ "4 10 13 6 10 10 10 4 u 10 13 6 4 4 7 4",
    /*4*/ "4 4 4 4 4 4 7 4 4 4 4 4 4 4 7 4",
    /*5*/ "4 4 4 4 4 4 7 4 4 4 4 4 4 4 7 4",
    /*6*/ "4 4 4 4 4 4 7 4 4 4 4 4 4 4 7 4",
    /*7*/ "7 7 7 7 7 7 5 7 4 4 4 4 4 4 7 4",
    /*8*/ "4 4 4 4 4 4 7 4 4 4 4 4 4 4 7 4",
    /*9*/ "4 4 4 4 4 4 7 4 4 4 4 4 4 4 7 4",
    /*A*/ "4 4 4 4 4 4 7 4 4 4 4 4 4 4 7 4",
    /*B*/ "4 4 4 4 4 4 7 4 4 4 4 4 4 4 7 4",
    /*C*/ "6/12 10 7/10 10 9/18 12 7 12 6/12 10 7/10 u 9/18 18 7 12",
    /*D*/ "6/12 10 7/10 10 9/18 12 7 12 6/12 u 7/10 10 9/18 u 7 12",
    /*E*/ "6/12 10 7/10 16 9/18 12 7 12 6/12 6 7/10 4 9/18 u 7 12",
    /*F*/ "6/12 10 7/10 4 9/18 12 7 12 6/12 6 7/10 4 9/18 u 7 12",
};

// 8080: CB is JMP, D9 RET, DD ED FD CALL, 08 10 18 20 28 30 38 NOP.
const char* const k8080[16] = {
    /*0*/ "4 10 7 5 5 5 7 4 4 10 7 5 5 5 7 4",
    /*1*/ "4 10 7 5 5 5 7 4 4 10 7 5 5 5 7 4",
    /*2*/ "4 10 16 5 5 5 7 4 4 10 16 5 5 5 7 4",
    /*3*/ "4 10 13 5 10 10 10 4 4 10 13 5 5 5 7 4",
    /*4*/ "5 5 5 5 5 5 7 5 5 5 5 5 5 5 7 5",
    /*5*/ "5 5 5 5 5 5 7 5 5 5 5 5 5 5 7 5",
    /*6*/ "5 5 5 5 5 5 7 5 5 5 5 5 5 5 7 5",
    /*7*/ "7 7 7 7 7 7 7 7 5 5 5 5 5 5 7 5",
    /*8*/ "4 4 4 4 4 4 7 4 4 4 4 4 4 4 7 4",
    /*9*/ "4 4 4 4 4 4 7 4 4 4 4 4 4 4 7 4",
    /*A*/ "4 4 4 4 4 4 7 4 4 4 4 4 4 4 7 4",
    /*B*/ "4 4 4 4 4 4 7 4 4 4 4 4 4 4 7 4",
    /*C*/ "5/11 10 10/10 10 11/17 11 7 11 5/11 10 10/10 10 11/17 17 7 11",
    /*D*/ "5/11 10 10/10 10 11/17 11 7 11 5/11 10 10/10 10 11/17 17 7 11",
    /*E*/ "5/11 10 10/10 18 11/17 11 7 11 5/11 5 10/10 4 11/17 17 7 11",
    /*F*/ "5/11 10 10/10 4 11/17 11 7 11 5/11 5 10/10 4 11/17 17 7 11",
};

struct Entry {
  int not_taken = 0;  // or the only value
  int taken = 0;      // 0 if unconditional
  bool undocumented = false;
};

Entry entry(const char* const table[16], int op) {
  std::istringstream row(table[op >> 4]);
  std::string cell;
  for (int i = 0; i <= (op & 15); ++i) row >> cell;
  Entry e;
  if (cell == "u") {
    e.not_taken = 4;
    e.undocumented = true;
  } else if (auto slash = cell.find('/'); slash != std::string::npos) {
    e.not_taken = std::stoi(cell.substr(0, slash));
    e.taken = std::stoi(cell.substr(slash + 1));
  } else {
    e.not_taken = std::stoi(cell);
  }
  return e;
}

bool is_conditional(int op) {
  const int z = op & 7;
  return (op >> 6) == 3 && (z == 0 || z == 2 || z == 4);
}

// F value that makes condition cc (NZ Z NC C PO PE P M) true or false.
std::uint8_t flags_for(int cc, bool want) {
  static const std::uint8_t bit[4] = {flag::Z, flag::CY, flag::P, flag::S};
  const bool set_means_true = (cc & 1) != 0;
  return (want == set_means_true) ? bit[cc >> 1] : 0;
}

int run_one(Mode mode, int op, std::uint8_t f, bool* undocumented) {
  test::Rig rig(mode);
  rig.load({static_cast<std::uint8_t>(op), 0x00, 0x20});
  rig.cpu.regs.sp = 0xF000;
  rig.cpu.regs.h = 0x20;
  rig.cpu.regs.f = static_cast<std::uint8_t>(f | fixed_flags(mode));
  const int t = rig.cpu.step();
  EXPECT_EQ(static_cast<std::uint64_t>(t), rig.cpu.tstates());
  EXPECT_EQ(rig.cpu.last().tstates, t);
  *undocumented = rig.cpu.last().undocumented;
  return t;
}

void check_table(Mode mode, const char* const table[16]) {
  for (int op = 0; op < 256; ++op) {
    SCOPED_TRACE(::testing::Message() << "opcode 0x" << std::hex << op);
    const Entry e = entry(table, op);
    bool undoc = false;
    if (is_conditional(op)) {
      const int cc = (op >> 3) & 7;
      EXPECT_EQ(run_one(mode, op, flags_for(cc, false), &undoc), e.not_taken) << "not taken";
      EXPECT_EQ(run_one(mode, op, flags_for(cc, true), &undoc), e.taken) << "taken";
    } else {
      EXPECT_EQ(run_one(mode, op, 0, &undoc), e.not_taken);
      EXPECT_EQ(undoc, e.undocumented);
    }
  }
}

TEST(TStates, Every8085OpcodeMatchesTheDataSheet) { check_table(Mode::i8085, k8085); }
TEST(TStates, Every8080OpcodeMatchesTheDataSheet) { check_table(Mode::i8080, k8080); }

TEST(TStates, CounterAccumulatesAcrossSteps) {
  test::Rig rig(Mode::i8085);
  // MVI A,1 (7); ADD A (4); CALL 0200 (18); at 0200: RET (10); HLT (5)
  rig.load({0x3E, 0x01, 0x87, 0xCD, 0x00, 0x02, 0x76});
  rig.bus.mem[0x0200] = 0xC9;
  rig.cpu.regs.sp = 0xF000;
  while (!rig.cpu.halted()) rig.cpu.step();
  EXPECT_EQ(rig.cpu.tstates(), 7u + 4u + 18u + 10u + 5u);
  EXPECT_EQ(rig.cpu.regs.a, 2);
}

TEST(TStates, HaltedStepIsOneIdleUnit) {
  for (Mode mode : {Mode::i8085, Mode::i8080}) {
    test::Rig rig(mode);
    rig.load({0x76});
    EXPECT_EQ(rig.cpu.step(), mode == Mode::i8085 ? 5 : 7);
    ASSERT_TRUE(rig.cpu.halted());
    const std::uint64_t t = rig.cpu.tstates();
    for (int i = 0; i < 10; ++i) {
      EXPECT_EQ(rig.cpu.step(), kHaltIdleTStates);
      EXPECT_EQ(rig.cpu.last().kind, StepKind::idle);
      EXPECT_EQ(rig.cpu.regs.pc, 0x0101);
    }
    EXPECT_EQ(rig.cpu.tstates(), t + 10u * kHaltIdleTStates);
  }
}

}  // namespace
}  // namespace i8085
