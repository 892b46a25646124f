// The Verilated cpu8085 alone against the Intel 8085AH data sheet (the
// instruction set table's T-state column, the interrupt section), with no
// reference to the ISS: the lockstep tests prove RTL == ISS, these pin the
// RTL to the book. Undocumented opcodes: this project runs them as 4-T NOPs
// (docs/i8085.md).
#include <gtest/gtest.h>

#include "i8085/system.hpp"
#include "cpu_machine.hpp"

namespace {

using i8085::Regs;

// Data sheet T-states; `taken` selects the larger figure of Jcc / Ccc / Rcc.
int datasheet_tstates(std::uint8_t op, bool taken) {
  const int x = op >> 6, y = (op >> 3) & 7, z = op & 7;
  if (i8085::is_undocumented_8085(op)) return 4;
  if (op == 0x76) return 5;                                   // HLT
  if (x == 1) return (y == 6 || z == 6) ? 7 : 4;              // MOV
  if (x == 2) return z == 6 ? 7 : 4;                          // ALU r / M
  if (x == 0) {
    switch (z) {
      case 0: return 4;                                       // NOP RIM SIM
      case 1: return 10;                                      // LXI DAD
      case 2: return (y < 4) ? 7 : (y == 4 || y == 5) ? 16 : 13;  // STAX LDAX SHLD LHLD STA LDA
      case 3: return 6;                                       // INX DCX
      case 4: case 5: return y == 6 ? 10 : 4;                 // INR DCR
      case 6: return y == 6 ? 10 : 7;                         // MVI
      default: return 4;                                      // rotates DAA CMA STC CMC
    }
  }
  switch (z) {
    case 0: return taken ? 12 : 6;                            // Rcc
    case 1: return (op == 0xE9 || op == 0xF9) ? 6 : 10;       // POP RET PCHL SPHL
    case 2: return taken ? 10 : 7;                            // Jcc
    case 3:
      if (op == 0xE3) return 16;                              // XTHL
      if (op == 0xEB || op == 0xF3 || op == 0xFB) return 4;   // XCHG DI EI
      return 10;                                              // JMP OUT IN
    case 4: return taken ? 18 : 9;                            // Ccc
    case 5: return op == 0xCD ? 18 : 12;                      // CALL PUSH
    case 6: return 7;                                         // ALU immediate
    default: return 12;                                       // RST
  }
}

struct Rig {
  i8085::RamBus bus;
  std::unique_ptr<i8085::Machine> cpu = cpu8085::make_cpu_machine(bus, i8085::Mode::i8085);
};

TEST(Datasheet, TStatesOfEveryOpcode) {
  for (int op = 0; op < 256; ++op) {
    for (int f : {0x00, 0xD5}) {  // every condition false, then true (NZ NC PO P are the other way round)
      Rig r;
      r.bus.mem[0x4000] = static_cast<std::uint8_t>(op);
      r.bus.mem[0x4001] = 0x00;
      r.bus.mem[0x4002] = 0x80;
      Regs q{};
      q.f = static_cast<std::uint8_t>(f);
      q.pc = 0x4000;
      q.sp = 0xC000;
      r.cpu->set_regs(q);
      const int t = r.cpu->step();
      const int cc = (op >> 3) & 7;
      // Conditions 0, 2, 4, 6 (NZ NC PO P) hold when the flag is clear.
      const bool taken = ((cc & 1) != 0) == (f != 0);
      EXPECT_EQ(t, datasheet_tstates(static_cast<std::uint8_t>(op), taken))
          << "opcode " << std::hex << op << " F=" << f;
    }
  }
}

TEST(Datasheet, HaltIsFiveTStatesThenIdleUntilAnInterrupt) {
  Rig r;
  r.bus.mem[0] = 0x76;
  EXPECT_EQ(r.cpu->step(), 5);
  EXPECT_TRUE(r.cpu->halted());
  for (int i = 0; i < 10; ++i) EXPECT_EQ(r.cpu->step(), 1);
  EXPECT_EQ(r.cpu->last().kind, i8085::StepKind::idle);
  r.cpu->set_trap(true);  // TRAP is not maskable: wakes with IE off
  EXPECT_EQ(r.cpu->step(), 12);
  EXPECT_EQ(r.cpu->last().irq, i8085::Interrupt::trap);
  EXPECT_FALSE(r.cpu->halted());
  EXPECT_EQ(r.cpu->regs().pc, 0x0024);
  EXPECT_EQ(r.bus.mem[0xFFFF], 0x00);  // return address 0x0001 pushed below SP = 0
  EXPECT_EQ(r.bus.mem[0xFFFE], 0x01);
}

// EI enables interrupts after the instruction that follows it.
TEST(Datasheet, EiTakesEffectAfterTheNextInstruction) {
  Rig r;
  const std::uint8_t prog[] = {0x31, 0x00, 0x80,  // LXI SP,8000
                               0x3E, 0x08, 0x30,  // MVI A,08 / SIM: unmask all
                               0xFB,              // EI
                               0x00, 0x00};       // NOP NOP
  std::copy(std::begin(prog), std::end(prog), r.bus.mem.begin());
  for (int i = 0; i < 3; ++i) r.cpu->step();
  r.cpu->set_rst55(true);
  r.cpu->step();  // EI
  EXPECT_EQ(r.cpu->last().bytes[0], 0xFB);
  r.cpu->step();  // the NOP after EI still runs
  EXPECT_EQ(r.cpu->last().kind, i8085::StepKind::instruction);
  EXPECT_EQ(r.cpu->regs().pc, 0x0008);
  EXPECT_EQ(r.cpu->step(), 12);
  EXPECT_EQ(r.cpu->last().irq, i8085::Interrupt::rst55);
  EXPECT_EQ(r.cpu->regs().pc, 0x002C);
  EXPECT_FALSE(r.cpu->ie());
}

// RST 7.5 latches a rising edge even while masked; RIM shows it; unmasking
// takes it (vector 3C), and the acknowledge clears the latch. Priorities:
// TRAP, 7.5, 6.5, 5.5, then INTR. Pins are held for a whole step, since the
// RTL samples them on clock edges.
TEST(Datasheet, Rst75LatchMasksAndPriorities) {
  Rig r;
  const std::uint8_t prog[] = {0x31, 0x00, 0x80,  // LXI SP,8000
                               0x3E, 0x0F, 0x30,  // MVI A,0F / SIM: mask all
                               0x00,              // NOP (RST 7.5 pulse here)
                               0x20,              // RIM
                               0x3E, 0x08, 0x30,  // MVI A,08 / SIM: unmask all
                               0xFB, 0x00};       // EI NOP
  std::copy(std::begin(prog), std::end(prog), r.bus.mem.begin());
  for (std::uint16_t v : {0x24, 0x2C, 0x34, 0x3C}) {  // handlers: EI NOP
    r.bus.mem[v] = 0xFB;
    r.bus.mem[v + 1] = 0x00;
  }
  for (int i = 0; i < 3; ++i) r.cpu->step();
  r.cpu->set_rst75(true);
  r.cpu->step();  // NOP: RST 7.5 masked and IE off, latched only
  r.cpu->set_rst75(false);
  r.cpu->step();  // RIM: SID 0, I7.5 1, I6.5 0, I5.5 0, IE 0, masks 111
  EXPECT_EQ(r.cpu->regs().a, 0x47);
  r.cpu->set_rst65(true);
  r.cpu->set_rst55(true);
  r.cpu->set_intr(true);
  for (int i = 0; i < 4; ++i) r.cpu->step();  // MVI SIM EI NOP
  EXPECT_EQ(r.cpu->last().kind, i8085::StepKind::instruction);
  EXPECT_EQ(r.cpu->step(), 12);
  EXPECT_EQ(r.cpu->last().irq, i8085::Interrupt::rst75);
  EXPECT_EQ(r.cpu->regs().pc, 0x003C);
  r.cpu->step();  // EI
  r.cpu->step();  // NOP
  EXPECT_EQ(r.cpu->step(), 12);
  EXPECT_EQ(r.cpu->last().irq, i8085::Interrupt::rst65);  // 7.5 latch was cleared
  r.cpu->set_rst65(false);
  r.cpu->step();
  r.cpu->step();
  r.cpu->step();
  EXPECT_EQ(r.cpu->last().irq, i8085::Interrupt::rst55);
  EXPECT_EQ(r.cpu->regs().pc, 0x002C);
  r.cpu->set_rst55(false);
  r.bus.mem[0x0000] = 0x00;
  r.cpu->step();
  r.cpu->step();
  const int t = r.cpu->step();  // INTR: the default INTA byte is RST 7 (FF)
  EXPECT_EQ(r.cpu->last().irq, i8085::Interrupt::intr);
  EXPECT_EQ(t, 12);
  EXPECT_EQ(r.cpu->regs().pc, 0x0038);
  r.cpu->set_intr(false);
  r.cpu->set_trap(true);
  r.cpu->set_rst75(true);
  r.cpu->step();
  EXPECT_EQ(r.cpu->last().irq, i8085::Interrupt::trap);  // over everything, IE off
  EXPECT_EQ(r.cpu->regs().pc, 0x0024);
}

}  // namespace
