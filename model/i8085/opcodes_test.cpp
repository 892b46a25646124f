// Result and flags of every opcode, in both modes. Each case gives the code,
// the state before (on top of a default state) and the registers and memory
// expected after; every register not named must be unchanged, PC must be
// past the instruction unless named. Expected values are worked out by hand
// from the Intel 8080/8085 Assembly Language Programming Manual (flag rules:
// docs/i8085.md) or, for the 64 register-ALU opcodes and their immediates, by
// a reference written here independently of the simulator (nibble sums).
#include <gtest/gtest.h>

#include <functional>
#include <set>
#include <string>
#include <vector>

#include "i8085/test_util.hpp"

namespace i8085 {
namespace {

using test::MemPoke;

constexpr const char* kDefault = "A=00 F=00 B=01 C=02 D=03 E=04 H=20 L=00 SP=F000 PC=0100";

struct Case {
  std::string name;
  std::vector<std::uint8_t> code;
  std::string before;
  std::string after85;  // "-": not run in 8085 mode
  std::string after80;  // "=": as after85 (F gets the 8080's bit 1); "-": not run
  std::function<void(const Cpu&, const RamBus&)> extra;
};

const char* kRegName[8] = {"B", "C", "D", "E", "H", "L", "M", "A"};

// Spec text setting register r (M: memory at HL = 2000) to v.
std::string set_reg(int r, unsigned v) {
  char buf[32];
  if (r == 6) std::snprintf(buf, sizeof buf, "M2000=%02X", v & 0xFF);
  else std::snprintf(buf, sizeof buf, "%s=%02X", kRegName[r], v & 0xFF);
  return buf;
}

std::string hex(unsigned v, int width) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "%0*X", width, v);
  return buf;
}

// Independent reference for the eight ALU operations: nibble sums, the
// subtraction as A + ~v + 1 - borrow (Intel's definition of AC for it).
struct AluRef {
  std::uint8_t result;
  std::uint8_t f;  // S Z AC P CY, no fixed bits
};

AluRef alu_ref(int op, unsigned a, unsigned v, bool cy, Mode mode) {
  unsigned r = 0;
  bool c = false, ac = false;
  switch (op) {
    case 0: case 1: {
      const unsigned cin = (op == 1 && cy) ? 1 : 0;
      r = a + v + cin;
      c = r > 0xFF;
      ac = (a & 0xF) + (v & 0xF) + cin > 0xF;
      break;
    }
    case 2: case 3: case 7: {
      const unsigned borrow = (op == 3 && cy) ? 1 : 0;
      r = (a - v - borrow) & 0x1FF;
      c = a < v + borrow;
      ac = (a & 0xF) + ((~v) & 0xF) + (1 - borrow) > 0xF;
      break;
    }
    case 4:
      r = a & v;
      ac = mode == Mode::i8085 ? true : (((a | v) >> 3) & 1) != 0;
      break;
    case 5: r = a ^ v; break;
    default: r = a | v; break;
  }
  r &= 0xFF;
  int ones = 0;
  for (int i = 0; i < 8; ++i) ones += (r >> i) & 1;
  std::uint8_t f = 0;
  if (r & 0x80) f |= 0x80;
  if (r == 0) f |= 0x40;
  if (ac) f |= 0x10;
  if (ones % 2 == 0) f |= 0x04;
  if (c) f |= 0x01;
  return {static_cast<std::uint8_t>(op == 7 ? a : r), f};
}

// The case list, in the order the groups below add them.
struct Cases {
  void add(std::string name, std::vector<std::uint8_t> code, std::string before, std::string after85,
           std::string after80 = "=", std::function<void(const Cpu&, const RamBus&)> extra = nullptr) {
    list.push_back({std::move(name), std::move(code), std::move(before), std::move(after85), std::move(after80),
                    std::move(extra)});
  }
  std::vector<Case> list;
};

const char* kRpName[4] = {"BC", "DE", "HL", "SP"};

// NOP; LXI INX DCX DAD on each register pair; loads and stores.
void add_transfer_cases(Cases& cs) {
  cs.add("NOP", {0x00}, "F=D5", "");

  // LXI, INX, DCX, DAD on each register pair.
  for (int rp = 0; rp < 4; ++rp) {
    const auto p = static_cast<std::uint8_t>(rp << 4);
    cs.add(std::string("LXI ") + kRpName[rp], {static_cast<std::uint8_t>(0x01 | p), 0x34, 0x12}, "",
           std::string(kRpName[rp]) + "=1234");
    cs.add(std::string("INX ") + kRpName[rp], {static_cast<std::uint8_t>(0x03 | p)},
           std::string("F=D5 ") + kRpName[rp] + "=FFFF", std::string(kRpName[rp]) + "=0000");
    cs.add(std::string("DCX ") + kRpName[rp], {static_cast<std::uint8_t>(0x0B | p)},
           std::string("F=00 ") + kRpName[rp] + "=0000", std::string(kRpName[rp]) + "=FFFF");
  }
  cs.add("DAD B carry", {0x09}, "HL=FFFF BC=0001 F=D4", "HL=0000 F=D5");
  cs.add("DAD D no carry clears CY", {0x19}, "HL=1234 DE=1111 F=D5", "HL=2345 F=D4");
  cs.add("DAD H", {0x29}, "HL=8001 F=00", "HL=0002 F=01");
  cs.add("DAD SP", {0x39}, "HL=1000 SP=F000 F=00", "HL=0000 F=01");

  cs.add("STAX B", {0x02}, "A=77 BC=2010", "M2010=77");
  cs.add("STAX D", {0x12}, "A=66 DE=2011", "M2011=66");
  cs.add("LDAX B", {0x0A}, "BC=2010 M2010=99", "A=99");
  cs.add("LDAX D", {0x1A}, "DE=2011 M2011=98", "A=98");
  cs.add("SHLD", {0x22, 0x10, 0x20}, "HL=1234", "M2010=34 M2011=12");
  cs.add("LHLD", {0x2A, 0x10, 0x20}, "M2010=34 M2011=12", "HL=1234");
  cs.add("STA", {0x32, 0x10, 0x20}, "A=42", "M2010=42");
  cs.add("LDA", {0x3A, 0x10, 0x20}, "M2010=24", "A=24");
}

void add_increment_cases(Cases& cs) {
  // INR / DCR / MVI on each register and M. INR: 0F -> 10 sets AC only;
  // FF -> 00 sets Z P AC. DCR: 00 -> FF: S P, no AC (low nibble wrapped);
  // 01 -> 00: Z P AC. CY is kept.
  for (int r = 0; r < 8; ++r) {
    const std::string n = kRegName[r];
    const auto y = static_cast<std::uint8_t>(r << 3);
    cs.add("INR " + n + " 0F", {static_cast<std::uint8_t>(0x04 | y)}, "F=01 " + set_reg(r, 0x0F),
           "F=11 " + set_reg(r, 0x10));
    cs.add("INR " + n + " FF", {static_cast<std::uint8_t>(0x04 | y)}, "F=80 " + set_reg(r, 0xFF),
           "F=54 " + set_reg(r, 0x00));
    cs.add("DCR " + n + " 00", {static_cast<std::uint8_t>(0x05 | y)}, "F=01 " + set_reg(r, 0x00),
           "F=85 " + set_reg(r, 0xFF));
    cs.add("DCR " + n + " 01", {static_cast<std::uint8_t>(0x05 | y)}, "F=00 " + set_reg(r, 0x01),
           "F=54 " + set_reg(r, 0x00));
    cs.add("MVI " + n, {static_cast<std::uint8_t>(0x06 | y), 0x5A}, "F=D5", set_reg(r, 0x5A));
  }
}

void add_rotate_and_carry_cases(Cases& cs) {
  // Rotates: only CY changes.
  cs.add("RLC", {0x07}, "A=85 F=D4", "A=0B F=D5");
  cs.add("RLC no carry", {0x07}, "A=41 F=01", "A=82 F=00");
  cs.add("RRC", {0x0F}, "A=01 F=00", "A=80 F=01");
  cs.add("RAL", {0x17}, "A=85 F=00", "A=0A F=01");
  cs.add("RAL carry in", {0x17}, "A=40 F=01", "A=81 F=00");
  cs.add("RAR", {0x1F}, "A=01 F=01", "A=80 F=01");
  cs.add("RAR carry out", {0x1F}, "A=6B F=00", "A=35 F=01");
  // DAA: manual's example, A = 9B: +06 (low digit > 9) then +60 (high digit
  // > 9): A = 01, CY = 1, AC = 1 (carry out of bit 3 of 9B + 06).
  cs.add("DAA manual example", {0x27}, "A=9B F=00", "A=01 F=11");
  cs.add("DAA after AC", {0x27}, "A=12 F=10", "A=18 F=04");
  cs.add("DAA nothing to do", {0x27}, "A=45 F=00", "A=45 F=00");
  cs.add("CMA", {0x2F}, "A=51 F=D5", "A=AE");
  cs.add("STC", {0x37}, "F=D4", "F=D5");
  cs.add("CMC set", {0x3F}, "F=00", "F=01");
  cs.add("CMC clear", {0x3F}, "F=D5", "F=D4");
}

void add_move_cases(Cases& cs) {
  // MOV r,r' (and HLT at 76).
  for (int d = 0; d < 8; ++d)
    for (int s = 0; s < 8; ++s) {
      if (d == 6 && s == 6) {
        cs.add("HLT", {0x76}, "", "", "=", [](const Cpu& c, const RamBus&) { EXPECT_TRUE(c.halted()); });
        continue;
      }
      const auto op = static_cast<std::uint8_t>(0x40 | d << 3 | s);
      std::string name = std::string("MOV ") + kRegName[d] + "," + kRegName[s];
      // Give the source a distinctive value (H and L stay 20/00 when they
      // are the address of M).
      if (s == 6) {
        cs.add(name, {op}, "F=D5 M2000=C3", d == 4 ? "H=C3" : d == 5 ? "L=C3" : set_reg(d, 0xC3));
      } else if (d == 6) {
        const unsigned v = s == 4 ? 0x20 : s == 5 ? 0x00 : 0x3C;
        cs.add(name, {op}, std::string("M2000=FF") + ((s == 4 || s == 5) ? "" : " " + set_reg(s, 0x3C)),
               set_reg(6, v));
      } else {
        cs.add(name, {op}, set_reg(s, 0x3C), set_reg(d, 0x3C));
      }
    }
}

void add_alu_cases(Cases& cs) {
  // ALU with a register or M, and with an immediate: reference model, with
  // operands that exercise carries (A=3A, v=C7 / A=85, v=85 / A=0C, v=23).
  struct Pair { unsigned a, v; bool cy; };
  const Pair pairs[] = {{0x3A, 0xC7, true}, {0x85, 0x85, false}, {0x0C, 0x23, true}};
  for (int op = 0; op < 8; ++op) {
    for (int s = 0; s < 8; ++s) {
      const auto code = static_cast<std::uint8_t>(0x80 | op << 3 | s);
      for (const Pair& p : pairs) {
        const unsigned v = s == 7 ? p.a : s == 4 ? 0x20 : s == 5 ? 0x00 : p.v;
        std::string before = "A=" + hex(p.a, 2) + (p.cy ? " F=01" : " F=00");
        if (s != 7 && s != 4 && s != 5) before += " " + set_reg(s, p.v);
        const std::string name = "ALU " + hex(code, 2) + " A=" + hex(p.a, 2) + " v=" + hex(v, 2);
        const AluRef r85 = alu_ref(op, p.a, v, p.cy, Mode::i8085);
        const AluRef r80 = alu_ref(op, p.a, v, p.cy, Mode::i8080);
        cs.add(name, {code}, before, "A=" + hex(r85.result, 2) + " F=" + hex(r85.f, 2),
               "A=" + hex(r80.result, 2) + " F=" + hex(r80.f | 0x02, 2));
      }
    }
    const auto imm = static_cast<std::uint8_t>(0xC6 | op << 3);
    for (const Pair& p : pairs) {
      const AluRef r85 = alu_ref(op, p.a, p.v, p.cy, Mode::i8085);
      const AluRef r80 = alu_ref(op, p.a, p.v, p.cy, Mode::i8080);
      cs.add("ALU imm " + hex(imm, 2), {imm, static_cast<std::uint8_t>(p.v)},
             "A=" + hex(p.a, 2) + (p.cy ? " F=01" : " F=00"), "A=" + hex(r85.result, 2) + " F=" + hex(r85.f, 2),
             "A=" + hex(r80.result, 2) + " F=" + hex(r80.f | 0x02, 2));
    }
  }
  // Worked examples of the manual, by hand.
  cs.add("SUB A (manual): Z P AC", {0x97}, "A=3E F=01", "A=00 F=54");
  cs.add("SUI 23 from 0C (manual): S AC CY", {0xD6, 0x23}, "A=0C", "A=E9 F=91");
  cs.add("ADD: 2E + 6C = 9A: S P AC", {0x81}, "A=2E C=6C", "A=9A F=94");
  cs.add("ANA on 8085 sets AC, on 8080 bit 3 of A|v", {0xA0}, "A=F0 B=30 F=01", "A=30 F=14", "A=30 F=06");
  cs.add("ANI on 8080: bit 3 of A|v set", {0xE6, 0x0F}, "A=F8", "A=08 F=10", "A=08 F=12");
  cs.add("XRA A clears A, CY, AC", {0xAF}, "A=5A F=11", "A=00 F=44");
  cs.add("CMP equal", {0xB8}, "A=42 B=42 F=01", "F=54");
  cs.add("CMP less: borrow, no AC", {0xB8}, "A=41 B=42 F=00", "F=85");
  cs.add("SBB with borrow in", {0x98}, "A=10 B=0F F=01", "A=00 F=44");
}

void add_branch_cases(Cases& cs) {
  // Jumps, calls, returns: each condition taken and not taken.
  const char* cc_name[8] = {"NZ", "Z", "NC", "C", "PO", "PE", "P", "M"};
  const char* f_true[8] = {"F=00", "F=40", "F=00", "F=01", "F=00", "F=04", "F=00", "F=80"};
  const char* f_false[8] = {"F=40", "F=00", "F=01", "F=00", "F=04", "F=00", "F=80", "F=00"};
  for (int cc = 0; cc < 8; ++cc) {
    const auto y = static_cast<std::uint8_t>(cc << 3);
    const std::string n = cc_name[cc];
    cs.add("J" + n + " taken", {static_cast<std::uint8_t>(0xC2 | y), 0x34, 0x12}, f_true[cc], "PC=1234");
    cs.add("J" + n + " not taken", {static_cast<std::uint8_t>(0xC2 | y), 0x34, 0x12}, f_false[cc], "");
    cs.add("C" + n + " taken", {static_cast<std::uint8_t>(0xC4 | y), 0x34, 0x12}, f_true[cc],
           "PC=1234 SP=EFFE MEFFE=03 MEFFF=01");
    cs.add("C" + n + " not taken", {static_cast<std::uint8_t>(0xC4 | y), 0x34, 0x12}, f_false[cc], "");
    cs.add("R" + n + " taken", {static_cast<std::uint8_t>(0xC0 | y)}, std::string(f_true[cc]) + " MF000=34 MF001=12",
           "PC=1234 SP=F002");
    cs.add("R" + n + " not taken", {static_cast<std::uint8_t>(0xC0 | y)},
           std::string(f_false[cc]) + " MF000=34 MF001=12", "");
  }
  cs.add("JMP", {0xC3, 0x34, 0x12}, "", "PC=1234");
  cs.add("CALL", {0xCD, 0x34, 0x12}, "", "PC=1234 SP=EFFE MEFFE=03 MEFFF=01");
  cs.add("RET", {0xC9}, "MF000=34 MF001=12", "PC=1234 SP=F002");
  for (int n = 0; n < 8; ++n)
    cs.add("RST " + std::to_string(n), {static_cast<std::uint8_t>(0xC7 | n << 3)}, "",
           "PC=" + hex(static_cast<unsigned>(n * 8), 4) + " SP=EFFE MEFFE=01 MEFFF=01");
}

void add_stack_cases(Cases& cs) {
  // Stack.
  for (int rp = 0; rp < 3; ++rp) {
    const auto p = static_cast<std::uint8_t>(rp << 4);
    cs.add(std::string("PUSH ") + kRpName[rp], {static_cast<std::uint8_t>(0xC5 | p)},
           std::string(kRpName[rp]) + "=1234", "SP=EFFE MEFFE=34 MEFFF=12");
    cs.add(std::string("POP ") + kRpName[rp], {static_cast<std::uint8_t>(0xC1 | p)}, "MF000=78 MF001=56",
           std::string(kRpName[rp]) + "=5678 SP=F002");
  }
  cs.add("PUSH PSW", {0xF5}, "A=12 F=D5", "SP=EFFE MEFFE=D5 MEFFF=12", "SP=EFFE MEFFE=D7 MEFFF=12");
  cs.add("POP PSW forces the fixed bits", {0xF1}, "MF000=FF MF001=12", "A=12 F=D5 SP=F002", "A=12 F=D7 SP=F002");
  cs.add("POP PSW zero", {0xF1}, "A=FF F=D5 MF000=00 MF001=00", "A=00 F=00 SP=F002", "A=00 F=02 SP=F002");
  cs.add("XTHL", {0xE3}, "HL=1234 MF000=78 MF001=56", "HL=5678 MF000=34 MF001=12");
  cs.add("PCHL", {0xE9}, "HL=1234", "PC=1234");
  cs.add("SPHL", {0xF9}, "HL=1234", "SP=1234");
  cs.add("XCHG", {0xEB}, "DE=1234 HL=5678", "DE=5678 HL=1234");
}

void add_io_and_control_cases(Cases& cs) {
  // I/O and interrupt control.
  cs.add("OUT", {0xD3, 0x42}, "A=99", "", "=", [](const Cpu&, const RamBus& b) {
    ASSERT_EQ(b.outs.size(), 1u);
    EXPECT_EQ(b.outs[0].port, 0x42);
    EXPECT_EQ(b.outs[0].value, 0x99);
  });
  cs.add("IN", {0xDB, 0x07}, "", "A=FF");  // RamBus inputs default to FF
  cs.add("EI", {0xFB}, "", "", "=", [](const Cpu& c, const RamBus&) { EXPECT_TRUE(c.ie()); });
  cs.add("DI", {0xF3}, "", "", "=", [](const Cpu& c, const RamBus&) { EXPECT_FALSE(c.ie()); });
  cs.add("RIM after reset: masks set", {0x20}, "A=00", "A=07", "");
  cs.add("SIM sets masks (MSE)", {0x30}, "A=0D", "", "", [](const Cpu& c, const RamBus&) {
    if (c.mode() == Mode::i8085) {
      EXPECT_EQ(c.masks(), 0x05);
    }
  });
  cs.add("SIM without MSE keeps masks", {0x30}, "A=05", "", "", [](const Cpu& c, const RamBus&) {
    if (c.mode() == Mode::i8085) {
      EXPECT_EQ(c.masks(), 0x07);
    }
  });
  cs.add("SIM sets SOD (SDE)", {0x30}, "A=C0", "", "", [](const Cpu& c, const RamBus&) {
    if (c.mode() == Mode::i8085) {
      EXPECT_TRUE(c.sod());
    }
  });
}

void add_undocumented_and_alias_cases(Cases& cs) {
  // The 8085's undocumented opcodes: a one-byte NOP here (docs/i8085.md);
  // on the 8080 the same opcodes are NOP / JMP / RET / CALL aliases.
  for (std::uint8_t op : {0x08, 0x10, 0x18, 0x28, 0x38})
    cs.add("8080 NOP alias " + hex(op, 2), {op, 0x34, 0x12}, "F=D5", "", "");
  for (std::uint8_t op : {0x20, 0x30})
    cs.add("8080 NOP alias " + hex(op, 2), {op}, "A=0D F=D5", "-", "");
  for (std::uint8_t op : {0x08, 0x10, 0x18, 0x28, 0x38, 0xCB, 0xD9, 0xDD, 0xED, 0xFD})
    cs.add("8085 undocumented " + hex(op, 2), {op, 0x34, 0x12}, "F=D5 MF000=78 MF001=56", "", "-",
           [](const Cpu& c, const RamBus&) { EXPECT_TRUE(c.last().undocumented); });
  cs.add("8080 CB = JMP", {0xCB, 0x34, 0x12}, "", "-", "PC=1234");
  cs.add("8080 D9 = RET", {0xD9}, "MF000=34 MF001=12", "-", "PC=1234 SP=F002");
  for (std::uint8_t op : {0xDD, 0xED, 0xFD})
    cs.add("8080 " + hex(op, 2) + " = CALL", {op, 0x34, 0x12}, "", "-", "PC=1234 SP=EFFE MEFFE=03 MEFFF=01");
}

std::vector<Case> all_cases() {
  Cases cs;
  add_transfer_cases(cs);
  add_increment_cases(cs);
  add_rotate_and_carry_cases(cs);
  add_move_cases(cs);
  add_alu_cases(cs);
  add_branch_cases(cs);
  add_stack_cases(cs);
  add_io_and_control_cases(cs);
  add_undocumented_and_alias_cases(cs);
  return cs.list;
}

// Runs one case in one mode; returns false if it does not apply.
bool run_case(const Case& c, Mode mode) {
  const bool m85 = mode == Mode::i8085;
  std::string after = m85 ? c.after85 : (c.after80 == "=" ? c.after85 : c.after80);
  if (after == "-") return false;
  const bool f_from_85 = !m85 && c.after80 == "=";
  SCOPED_TRACE(c.name + (m85 ? " [8085]" : " [8080]"));

  test::Rig rig(mode);
  Regs before{};
  std::vector<MemPoke> mem;
  test::apply(kDefault, before, &mem);
  test::apply(c.before, before, &mem);
  before.f = static_cast<std::uint8_t>(before.f | fixed_flags(mode));
  for (const auto& p : mem) rig.bus.mem[p.addr] = p.value;
  rig.load(c.code, before.pc);
  rig.cpu.regs = before;

  Regs want = before;
  want.pc = static_cast<std::uint16_t>(before.pc + instruction_length(c.code[0], mode));
  std::vector<MemPoke> want_mem;
  test::apply(after, want, &want_mem);
  if (f_from_85) want.f = static_cast<std::uint8_t>(want.f | fixed_flags(mode));

  rig.cpu.step();
  EXPECT_EQ(test::show(rig.cpu.regs), test::show(want));
  for (const auto& p : want_mem) EXPECT_EQ(rig.bus.mem[p.addr], p.value) << "memory " << std::hex << p.addr;
  if (c.extra) c.extra(rig.cpu, rig.bus);
  return true;
}

void run_all(Mode mode) {
  std::set<int> covered;
  for (const Case& c : all_cases())
    if (run_case(c, mode)) covered.insert(c.code[0]);
  EXPECT_EQ(covered.size(), 256u) << "opcodes without a result test";
}

TEST(Opcodes, EveryOpcodeResultAndFlags8085) { run_all(Mode::i8085); }
TEST(Opcodes, EveryOpcodeResultAndFlags8080) { run_all(Mode::i8080); }

// All A, operand and carry-in values for the eight ALU operations, against
// the reference above.
TEST(Opcodes, AluExhaustiveAgainstReference) {
  for (Mode mode : {Mode::i8085, Mode::i8080}) {
    test::Rig rig(mode);
    int failures = 0;
    for (int op = 0; op < 8 && failures < 10; ++op)
      for (unsigned a = 0; a < 256; ++a)
        for (unsigned v = 0; v < 256; ++v)
          for (int cy = 0; cy < 2; ++cy) {
            rig.bus.mem[0x0100] = static_cast<std::uint8_t>(0xC6 | op << 3);
            rig.bus.mem[0x0101] = static_cast<std::uint8_t>(v);
            rig.cpu.regs.pc = 0x0100;
            rig.cpu.regs.a = static_cast<std::uint8_t>(a);
            rig.cpu.regs.f = static_cast<std::uint8_t>((cy ? 1 : 0) | fixed_flags(mode));
            rig.cpu.step();
            const AluRef r = alu_ref(op, a, v, cy != 0, mode);
            const auto want_f = static_cast<std::uint8_t>(r.f | fixed_flags(mode));
            if (rig.cpu.regs.a != r.result || rig.cpu.regs.f != want_f) {
              if (++failures <= 10)
                ADD_FAILURE() << "op " << op << " a=" << a << " v=" << v << " cy=" << cy << ": got A="
                              << int(rig.cpu.regs.a) << " F=" << int(rig.cpu.regs.f) << ", want A="
                              << int(r.result) << " F=" << int(want_f);
            }
          }
  }
}

// DAA after ADD of two BCD numbers gives their BCD sum, CY = sum > 99.
TEST(Opcodes, DaaAfterAddIsBcdAddition) {
  for (Mode mode : {Mode::i8085, Mode::i8080}) {
    test::Rig rig(mode);
    for (int x = 0; x < 100; ++x)
      for (int y = 0; y < 100; ++y) {
        rig.bus.mem[0x0100] = 0xC6;  // ADI y
        rig.bus.mem[0x0101] = static_cast<std::uint8_t>((y / 10) << 4 | (y % 10));
        rig.bus.mem[0x0102] = 0x27;  // DAA
        rig.cpu.regs.pc = 0x0100;
        rig.cpu.regs.a = static_cast<std::uint8_t>((x / 10) << 4 | (x % 10));
        rig.cpu.step();
        rig.cpu.step();
        const int s = x + y;
        ASSERT_EQ(rig.cpu.regs.a, ((s % 100) / 10) << 4 | (s % 10)) << x << "+" << y;
        ASSERT_EQ((rig.cpu.regs.f & flag::CY) != 0, s > 99) << x << "+" << y;
      }
  }
}

}  // namespace
}  // namespace i8085
