// The 8085 interrupt system (docs/i8085.md, "Interrupts"): the RST 7.5
// latch, level-sensitive RST 6.5/5.5, INTR with an instruction on the bus,
// masks through SIM, the EI delay, priorities, TRAP, HLT wake-up and the
// acknowledge's T-states.
#include <gtest/gtest.h>

#include <deque>
#include <stdexcept>

#include "i8085/test_util.hpp"

namespace i8085 {
namespace {

// A RAM bus whose INTA cycles return queued bytes (RST 7 when empty).
class IntaBus : public RamBus {
 public:
  std::uint8_t inta() override {
    ++inta_cycles;
    if (queue.empty()) return 0xFF;
    const std::uint8_t v = queue.front();
    queue.pop_front();
    return v;
  }
  std::deque<std::uint8_t> queue;
  int inta_cycles = 0;
};

struct Sys {
  explicit Sys(Mode m = Mode::i8085) : cpu(bus, m) {
    cpu.regs.sp = 0xF000;
    cpu.regs.pc = 0x0100;
  }
  void code(std::uint16_t at, std::initializer_list<std::uint8_t> bytes) {
    for (auto b : bytes) bus.mem[at++] = b;
  }
  std::uint16_t stacked() const {
    return static_cast<std::uint16_t>(bus.mem[cpu.regs.sp] | bus.mem[(cpu.regs.sp + 1) & 0xFFFF] << 8);
  }
  IntaBus bus;
  Cpu cpu;
};

// 0100: SIM with A (masks), EI, then NOPs.
void unmask_and_enable(Sys& s, std::uint8_t sim_a) {
  s.cpu.regs.a = sim_a;
  s.code(0x0100, {0x30, 0xFB, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00});
  s.cpu.step();  // SIM
  s.cpu.step();  // EI
}

TEST(Interrupts, ResetMasksEverythingAndDisables) {
  Sys s;
  EXPECT_EQ(s.cpu.masks(), 0x07);
  EXPECT_FALSE(s.cpu.ie());
  EXPECT_EQ(s.cpu.rim_value(), 0x07);
}

TEST(Interrupts, Rst75LatchesOnRisingEdgeEvenWhileMasked) {
  Sys s;
  s.code(0x0100, {0x00, 0x00});
  s.cpu.set_rst75(true);
  s.cpu.set_rst75(false);  // a pulse: the latch keeps it
  EXPECT_TRUE(s.cpu.rst75_latched());
  EXPECT_EQ(s.cpu.rim_value() & 0x40, 0x40);
  s.cpu.step();
  EXPECT_EQ(s.cpu.last().kind, StepKind::instruction);  // masked and IE = 0
  EXPECT_TRUE(s.cpu.rst75_latched());
}

TEST(Interrupts, Rst75AcknowledgeClearsLatchAndCostsTheConstant) {
  Sys s;
  unmask_and_enable(s, 0x08);  // MSE, all unmasked
  s.cpu.set_rst75(true);
  s.cpu.step();  // NOP after EI: the EI delay
  EXPECT_EQ(s.cpu.last().kind, StepKind::instruction);
  const std::uint64_t t0 = s.cpu.tstates();
  const std::uint16_t pc = s.cpu.regs.pc;
  EXPECT_EQ(s.cpu.step(), kVectoredAckTStates);
  EXPECT_EQ(kVectoredAckTStates, 12);
  EXPECT_EQ(s.cpu.tstates(), t0 + 12);
  EXPECT_EQ(s.cpu.last().kind, StepKind::interrupt);
  EXPECT_EQ(s.cpu.last().irq, Interrupt::rst75);
  EXPECT_EQ(s.cpu.regs.pc, 0x003C);
  EXPECT_EQ(s.stacked(), pc);
  EXPECT_EQ(s.cpu.regs.sp, 0xEFFE);
  EXPECT_FALSE(s.cpu.rst75_latched());
  EXPECT_FALSE(s.cpu.ie());
  // The input still high is no new edge: nothing pending after EI.
  s.code(0x003C, {0xFB, 0x00, 0x00});
  s.cpu.step();
  s.cpu.step();
  s.cpu.step();
  EXPECT_EQ(s.cpu.last().kind, StepKind::instruction);
}

TEST(Interrupts, SimBit4ClearsTheRst75Latch) {
  Sys s;
  s.cpu.set_rst75(true);
  s.cpu.regs.a = 0x10;  // R7.5 without MSE: masks unchanged
  s.code(0x0100, {0x30});
  s.cpu.step();
  EXPECT_FALSE(s.cpu.rst75_latched());
  EXPECT_EQ(s.cpu.masks(), 0x07);
}

TEST(Interrupts, ResetClearsTheRst75Latch) {
  Sys s;
  s.cpu.set_rst75(true);
  s.cpu.reset();
  EXPECT_FALSE(s.cpu.rst75_latched());
}

TEST(Interrupts, MaskedRst75IsTakenOnceUnmasked) {
  Sys s;
  unmask_and_enable(s, 0x0C);  // MSE, M7.5 set
  s.cpu.set_rst75(true);
  s.cpu.step();
  s.cpu.step();
  EXPECT_EQ(s.cpu.last().kind, StepKind::instruction);
  // SIM A=08 unmasks; the latch is still set.
  s.cpu.regs.a = 0x08;
  s.code(s.cpu.regs.pc, {0x30});
  s.cpu.step();
  s.cpu.step();
  EXPECT_EQ(s.cpu.last().irq, Interrupt::rst75);
}

TEST(Interrupts, Rst65AndRst55AreLevelSensitive) {
  Sys s;
  unmask_and_enable(s, 0x08);
  s.cpu.step();  // EI delay over
  s.cpu.set_rst65(true);
  s.cpu.set_rst65(false);  // dropped before the boundary: nothing latched
  s.cpu.step();
  EXPECT_EQ(s.cpu.last().kind, StepKind::instruction);
  s.cpu.set_rst55(true);
  EXPECT_EQ(s.cpu.rim_value() & 0x30, 0x10);
  s.cpu.step();
  EXPECT_EQ(s.cpu.last().irq, Interrupt::rst55);
  EXPECT_EQ(s.cpu.regs.pc, 0x002C);
  EXPECT_EQ(s.cpu.last().tstates, 12);
}

TEST(Interrupts, MaskedRst65IsPendingButNotTaken) {
  Sys s;
  unmask_and_enable(s, 0x0A);  // M6.5 set
  s.cpu.step();
  s.cpu.set_rst65(true);
  s.cpu.step();
  EXPECT_EQ(s.cpu.last().kind, StepKind::instruction);
  EXPECT_EQ(s.cpu.rim_value(), 0x0A | 0x20);  // masks 010, IE, I6.5
}

TEST(Interrupts, IntrExecutesTheRstOnTheBus) {
  for (Mode mode : {Mode::i8085, Mode::i8080}) {
    Sys s(mode);
    s.code(0x0100, {0xFB, 0x00, 0x00, 0x00});
    s.cpu.step();  // EI
    s.cpu.set_intr(true);
    s.bus.queue = {0xEF};  // RST 5
    s.cpu.step();          // the instruction after EI
    EXPECT_EQ(s.cpu.last().kind, StepKind::instruction);
    EXPECT_EQ(s.bus.inta_cycles, 0);
    const int t = s.cpu.step();
    EXPECT_EQ(s.cpu.last().irq, Interrupt::intr);
    EXPECT_EQ(t, mode == Mode::i8085 ? 12 : 11);  // the RST instruction's T-states
    EXPECT_EQ(s.cpu.regs.pc, 0x0028);
    EXPECT_EQ(s.stacked(), 0x0102);
    EXPECT_EQ(s.bus.inta_cycles, 1);
    EXPECT_FALSE(s.cpu.ie());
    EXPECT_EQ(trace_line(s.cpu.last(), s.cpu.regs).substr(0, 44),
              "T=         8 PC=0102 OP=EF INTA RST 5     A=");
  }
}

TEST(Interrupts, IntrWithCallOnTheBusReadsThreeBytes) {
  Sys s;
  s.code(0x0100, {0xFB, 0x00, 0x00});
  s.cpu.step();
  s.cpu.step();
  s.cpu.set_intr(true);
  s.bus.queue = {0xCD, 0x34, 0x12};
  EXPECT_EQ(s.cpu.step(), 18);
  EXPECT_EQ(s.bus.inta_cycles, 3);
  EXPECT_EQ(s.cpu.regs.pc, 0x1234);
  EXPECT_EQ(s.stacked(), 0x0102);
}

TEST(Interrupts, EiTakesEffectAfterTheNextInstruction) {
  Sys s;
  s.cpu.set_intr(true);
  s.code(0x0100, {0xFB, 0xC9});  // EI; RET -- the classic handler exit
  s.code(0x2000, {0x00});
  s.bus.mem[0xF000] = 0x00;
  s.bus.mem[0xF001] = 0x20;
  s.cpu.step();  // EI
  s.cpu.step();  // RET runs before the interrupt
  EXPECT_EQ(s.cpu.last().kind, StepKind::instruction);
  EXPECT_EQ(s.cpu.regs.pc, 0x2000);
  s.cpu.step();
  EXPECT_EQ(s.cpu.last().irq, Interrupt::intr);
  EXPECT_EQ(s.stacked(), 0x2000);
}

TEST(Interrupts, EiThenDiTakesNoInterrupt) {
  Sys s;
  s.cpu.set_intr(true);
  s.code(0x0100, {0xFB, 0xF3, 0x00, 0x00});
  for (int i = 0; i < 4; ++i) {
    s.cpu.step();
    EXPECT_EQ(s.cpu.last().kind, StepKind::instruction);
  }
}

TEST(Interrupts, PriorityTrapThen75Then65Then55ThenIntr) {
  Sys s;
  unmask_and_enable(s, 0x08);
  s.cpu.step();
  // Every vector: EI; NOP; NOP.
  for (std::uint16_t v : {0x24, 0x2C, 0x34, 0x3C, 0x38}) s.code(v, {0xFB, 0x00, 0x00});
  s.cpu.set_intr(true);
  s.cpu.set_rst55(true);
  s.cpu.set_rst65(true);
  s.cpu.set_rst75(true);
  s.cpu.set_trap(true);
  const Interrupt order[] = {Interrupt::trap, Interrupt::rst75, Interrupt::rst65, Interrupt::rst55,
                             Interrupt::intr};
  for (Interrupt want : order) {
    s.cpu.step();
    ASSERT_EQ(s.cpu.last().kind, StepKind::interrupt);
    EXPECT_EQ(s.cpu.last().irq, want);
    if (want == Interrupt::trap) s.cpu.set_trap(false);
    if (want == Interrupt::rst65) s.cpu.set_rst65(false);
    if (want == Interrupt::rst55) s.cpu.set_rst55(false);
    if (want == Interrupt::intr) s.cpu.set_intr(false);
    if (want == Interrupt::trap) {
      // TRAP does not look at IE, but it cleared it: the handler's EI and
      // the EI delay come first.
      EXPECT_FALSE(s.cpu.ie());
    }
    s.cpu.step();  // EI
    s.cpu.step();  // delay
  }
}

TEST(Interrupts, TrapIsNonMaskableAndRimShowsThePreviousIe) {
  Sys s;
  s.code(0x0100, {0x00});
  s.code(0x0024, {0x20});  // RIM
  s.cpu.set_trap(true);
  s.cpu.step();
  EXPECT_EQ(s.cpu.last().irq, Interrupt::trap);
  EXPECT_EQ(s.cpu.regs.pc, 0x0024);
  s.cpu.step();  // RIM: IE before TRAP was 0
  EXPECT_EQ(s.cpu.regs.a & 0x08, 0);

  Sys e;
  e.code(0x0100, {0xFB, 0x00, 0x00});
  e.code(0x0024, {0x20, 0x20});
  e.cpu.step();  // EI
  e.cpu.set_trap(true);
  e.cpu.step();  // TRAP is taken even in the EI delay
  EXPECT_EQ(e.cpu.last().irq, Interrupt::trap);
  EXPECT_FALSE(e.cpu.ie());
  e.cpu.step();  // first RIM: IE before the TRAP (1)
  EXPECT_EQ(e.cpu.regs.a & 0x08, 0x08);
  e.cpu.step();  // second RIM: the current IE (0)
  EXPECT_EQ(e.cpu.regs.a & 0x08, 0);
}

TEST(Interrupts, TrapNeedsAnEdgeAndTheLevel) {
  Sys s;
  s.code(0x0100, {0x00, 0x00, 0x00});
  s.cpu.set_trap(true);
  s.cpu.set_trap(false);  // edge seen but the level is gone
  s.cpu.step();
  EXPECT_EQ(s.cpu.last().kind, StepKind::instruction);
}

TEST(Interrupts, HaltWaitsAndAnInterruptWakesIt) {
  Sys s;
  unmask_and_enable(s, 0x08);
  s.code(0x0102, {0x76});  // HLT
  s.cpu.step();
  EXPECT_TRUE(s.cpu.halted());
  for (int i = 0; i < 5; ++i) EXPECT_EQ(s.cpu.step(), kHaltIdleTStates);
  EXPECT_EQ(s.cpu.last().kind, StepKind::idle);
  s.cpu.set_rst75(true);
  EXPECT_EQ(s.cpu.step(), 12);
  EXPECT_FALSE(s.cpu.halted());
  EXPECT_EQ(s.cpu.regs.pc, 0x003C);
  EXPECT_EQ(s.stacked(), 0x0103);  // the instruction after HLT
}

TEST(Interrupts, HaltWithInterruptsDisabledOnlyTrapWakes) {
  Sys s;
  s.code(0x0100, {0x76});
  s.cpu.step();
  s.cpu.set_rst75(true);
  s.cpu.set_rst65(true);
  s.cpu.set_intr(true);
  for (int i = 0; i < 3; ++i) {
    s.cpu.step();
    EXPECT_EQ(s.cpu.last().kind, StepKind::idle);
  }
  s.cpu.set_trap(true);
  s.cpu.step();
  EXPECT_EQ(s.cpu.last().irq, Interrupt::trap);
}

TEST(Interrupts, The8080HasOnlyIntr) {
  Sys s(Mode::i8080);
  EXPECT_THROW(s.cpu.set_trap(true), std::logic_error);
  EXPECT_THROW(s.cpu.set_rst75(true), std::logic_error);
  EXPECT_THROW(s.cpu.set_rst65(true), std::logic_error);
  EXPECT_THROW(s.cpu.set_rst55(true), std::logic_error);
  EXPECT_NO_THROW(s.cpu.set_trap(false));
}

TEST(Trace, LineFormatIsStable) {
  Sys s;
  s.code(0x0100, {0x21, 0x34, 0x12, 0x76});
  s.cpu.step();
  EXPECT_EQ(trace_line(s.cpu.last(), s.cpu.regs),
            "T=         0 PC=0100 OP=21 LXI H,1234     A=00 F=00 B=00 C=00 D=00 E=00 H=12 L=34 SP=F000 +10");
  s.cpu.step();
  s.cpu.step();
  EXPECT_EQ(trace_line(s.cpu.last(), s.cpu.regs),
            "T=        15 PC=0104 OP=-- IDLE           A=00 F=00 B=00 C=00 D=00 E=00 H=12 L=34 SP=F000 +1");
  s.cpu.set_trap(true);
  s.cpu.step();
  EXPECT_EQ(trace_line(s.cpu.last(), s.cpu.regs),
            "T=        16 PC=0104 OP=-- INT TRAP       A=00 F=00 B=00 C=00 D=00 E=00 H=12 L=34 SP=EFFE +12");
}

TEST(Disassembler, CoversTheMnemonics) {
  EXPECT_EQ(disassemble({0x3E, 0x12, 0}, Mode::i8085), "MVI A,12");
  EXPECT_EQ(disassemble({0x7E, 0, 0}, Mode::i8085), "MOV A,M");
  EXPECT_EQ(disassemble({0xCD, 0x34, 0x12}, Mode::i8085), "CALL 1234");
  EXPECT_EQ(disassemble({0xF5, 0, 0}, Mode::i8085), "PUSH PSW");
  EXPECT_EQ(disassemble({0x31, 0x00, 0xF0}, Mode::i8085), "LXI SP,F000");
  EXPECT_EQ(disassemble({0xFE, 0x0A, 0}, Mode::i8085), "CPI 0A");
  EXPECT_EQ(disassemble({0x20, 0, 0}, Mode::i8085), "RIM");
  EXPECT_EQ(disassemble({0x20, 0, 0}, Mode::i8080), "NOP");
  EXPECT_EQ(disassemble({0x08, 0, 0}, Mode::i8085), "UNDOC DSUB");
  EXPECT_EQ(disassemble({0xE8, 0, 0}, Mode::i8085), "RPE");
  EXPECT_EQ(disassemble({0xFF, 0, 0}, Mode::i8085), "RST 7");
}

}  // namespace
}  // namespace i8085
