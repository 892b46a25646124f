#include "i8085/cpu.hpp"

#include <stdexcept>

namespace i8085 {

Bus::~Bus() = default;

namespace {

constexpr std::array<std::uint8_t, 256> make_szp() {
  std::array<std::uint8_t, 256> t{};
  for (int v = 0; v < 256; ++v) {
    int ones = 0;
    for (int b = 0; b < 8; ++b) ones += (v >> b) & 1;
    std::uint8_t f = 0;
    if (v & 0x80) f |= flag::S;
    if (v == 0) f |= flag::Z;
    if ((ones & 1) == 0) f |= flag::P;
    t[static_cast<std::size_t>(v)] = f;
  }
  return t;
}
constexpr std::array<std::uint8_t, 256> kSzp = make_szp();

std::uint8_t szp(unsigned v) { return kSzp[v & 0xFF]; }


// Opcode fields: x = bits 7-6, y = bits 5-3, z = bits 2-0; rp = bits 5-4,
// a register pair (0 BC, 1 DE, 2 HL, 3 SP or PSW).
constexpr int op_x(std::uint8_t op) { return op >> 6; }
constexpr int op_y(std::uint8_t op) { return (op >> 3) & 7; }
constexpr int op_z(std::uint8_t op) { return op & 7; }
constexpr int op_rp(std::uint8_t op) { return (op >> 4) & 3; }

}  // namespace

Cpu::Cpu(Bus& bus, Mode mode) : bus_(bus), mode_(mode) { reset(); }

void Cpu::reset() {
  regs = Regs{};
  regs.f = fixed_flags(mode_);
  halted_ = false;
  ie_ = false;
  ei_delay_ = false;
  from_inta_ = false;
  masks_ = 0x07;
  trap_latch_ = false;
  rst75_latch_ = false;
  sod_ = false;
  rim_after_trap_ = false;
  ie_before_trap_ = false;
  last_ = Step{};
  last_.mode = mode_;
}

void Cpu::set_trap(bool level) {
  if (level && mode_ == Mode::i8080) throw std::logic_error("the 8080 has no TRAP input");
  if (level && !trap_level_) trap_latch_ = true;
  trap_level_ = level;
}

void Cpu::set_rst75(bool level) {
  if (level && mode_ == Mode::i8080) throw std::logic_error("the 8080 has no RST 7.5 input");
  if (level && !rst75_level_) rst75_latch_ = true;
  rst75_level_ = level;
}

void Cpu::set_rst65(bool level) {
  if (level && mode_ == Mode::i8080) throw std::logic_error("the 8080 has no RST 6.5 input");
  rst65_level_ = level;
}

void Cpu::set_rst55(bool level) {
  if (level && mode_ == Mode::i8080) throw std::logic_error("the 8080 has no RST 5.5 input");
  rst55_level_ = level;
}

void Cpu::set_intr(bool level) { intr_level_ = level; }

std::uint8_t Cpu::rim_value() const {
  const bool ie = rim_after_trap_ ? ie_before_trap_ : ie_;
  return static_cast<std::uint8_t>((masks_ & 0x07) | (ie ? 0x08 : 0) | (rst55_level_ ? 0x10 : 0) |
                                   (rst65_level_ ? 0x20 : 0) | (rst75_latch_ ? 0x40 : 0));
}

std::uint8_t Cpu::fetch8() {
  std::uint8_t v;
  if (from_inta_) {
    v = bus_.inta();
  } else {
    v = read(regs.pc);
    regs.pc = static_cast<std::uint16_t>(regs.pc + 1);
  }
  if (last_.length < 3) last_.bytes[last_.length++] = v;
  return v;
}

std::uint16_t Cpu::fetch16() {
  const std::uint8_t lo = fetch8();
  const std::uint8_t hi = fetch8();
  return static_cast<std::uint16_t>(hi << 8 | lo);
}

void Cpu::push(std::uint16_t v) {
  regs.sp = static_cast<std::uint16_t>(regs.sp - 1);
  write(regs.sp, static_cast<std::uint8_t>(v >> 8));
  regs.sp = static_cast<std::uint16_t>(regs.sp - 1);
  write(regs.sp, static_cast<std::uint8_t>(v & 0xFF));
}

std::uint16_t Cpu::pop() {
  const std::uint8_t lo = read(regs.sp);
  regs.sp = static_cast<std::uint16_t>(regs.sp + 1);
  const std::uint8_t hi = read(regs.sp);
  regs.sp = static_cast<std::uint16_t>(regs.sp + 1);
  return static_cast<std::uint16_t>(hi << 8 | lo);
}

std::uint8_t Cpu::get_reg(int r) {
  switch (r) {
    case 0: return regs.b;
    case 1: return regs.c;
    case 2: return regs.d;
    case 3: return regs.e;
    case 4: return regs.h;
    case 5: return regs.l;
    case 6: return read(regs.hl());
    default: return regs.a;
  }
}

void Cpu::set_reg(int r, std::uint8_t v) {
  switch (r) {
    case 0: regs.b = v; break;
    case 1: regs.c = v; break;
    case 2: regs.d = v; break;
    case 3: regs.e = v; break;
    case 4: regs.h = v; break;
    case 5: regs.l = v; break;
    case 6: write(regs.hl(), v); break;
    default: regs.a = v; break;
  }
}

std::uint16_t Cpu::get_rp(int rp) const {
  switch (rp) {
    case 0: return regs.bc();
    case 1: return regs.de();
    case 2: return regs.hl();
    default: return regs.sp;
  }
}

void Cpu::set_rp(int rp, std::uint16_t v) {
  const auto hi = static_cast<std::uint8_t>(v >> 8);
  const auto lo = static_cast<std::uint8_t>(v & 0xFF);
  switch (rp) {
    case 0: regs.b = hi; regs.c = lo; break;
    case 1: regs.d = hi; regs.e = lo; break;
    case 2: regs.h = hi; regs.l = lo; break;
    default: regs.sp = v; break;
  }
}

bool Cpu::condition(int cc) const {
  switch (cc) {
    case 0: return !(regs.f & flag::Z);
    case 1: return (regs.f & flag::Z) != 0;
    case 2: return !(regs.f & flag::CY);
    case 3: return (regs.f & flag::CY) != 0;
    case 4: return !(regs.f & flag::P);
    case 5: return (regs.f & flag::P) != 0;
    case 6: return !(regs.f & flag::S);
    default: return (regs.f & flag::S) != 0;
  }
}

// ADD ADC SUB SBB ANA XRA ORA CMP. Subtraction is the addition of the
// one's complement with carry-in = NOT borrow, as the 8080/8085 ALU does it:
// AC is the carry out of bit 3 of that addition, CY the inverted carry out
// of bit 7 (a borrow).
void Cpu::alu(int op, std::uint8_t v) {
  const unsigned a = regs.a;
  const std::uint8_t fixed = fixed_flags(mode_);
  const bool cy = (regs.f & flag::CY) != 0;
  unsigned r = 0;
  std::uint8_t f = 0;
  switch (op) {
    case 0:  // ADD
    case 1: {  // ADC
      const unsigned cin = (op == 1 && cy) ? 1u : 0u;
      r = a + v + cin;
      f = static_cast<std::uint8_t>(szp(r) | ((r >> 8) & 1u ? flag::CY : 0) | ((a ^ v ^ r) & 0x10u));
      break;
    }
    case 2:  // SUB
    case 3:  // SBB
    case 7: {  // CMP
      const unsigned cin = (op == 3 && cy) ? 0u : 1u;
      const unsigned nv = static_cast<std::uint8_t>(~v);
      r = a + nv + cin;
      f = static_cast<std::uint8_t>(szp(r) | ((r >> 8) & 1u ? 0 : flag::CY) | ((a ^ nv ^ r) & 0x10u));
      break;
    }
    case 4:  // ANA: the 8085 sets AC; the 8080 sets it to bit 3 of (A | v).
      r = a & v;
      f = szp(r);
      if (mode_ == Mode::i8085 || ((a | v) & 0x08)) f |= flag::AC;
      break;
    case 5:  // XRA
      r = a ^ v;
      f = szp(r);
      break;
    default:  // ORA
      r = a | v;
      f = szp(r);
      break;
  }
  regs.f = static_cast<std::uint8_t>(f | fixed);
  if (op != 7) regs.a = static_cast<std::uint8_t>(r);
}

std::uint8_t Cpu::inr(std::uint8_t v) {
  const auto r = static_cast<std::uint8_t>(v + 1);
  regs.f = static_cast<std::uint8_t>((regs.f & flag::CY) | szp(r) | ((r & 0x0F) == 0 ? flag::AC : 0) |
                                     fixed_flags(mode_));
  return r;
}

// DCR adds 0xFF: AC is the carry out of bit 3, i.e. set unless the low
// nibble wrapped from 0 to F.
std::uint8_t Cpu::dcr(std::uint8_t v) {
  const auto r = static_cast<std::uint8_t>(v - 1);
  regs.f = static_cast<std::uint8_t>((regs.f & flag::CY) | szp(r) | ((r & 0x0F) != 0x0F ? flag::AC : 0) |
                                     fixed_flags(mode_));
  return r;
}

void Cpu::daa() {
  const unsigned a = regs.a;
  unsigned corr = 0;
  bool cy = (regs.f & flag::CY) != 0;
  const unsigned lo = a & 0x0F;
  if (lo > 9 || (regs.f & flag::AC)) corr |= 0x06;
  if ((a >> 4) > 9 || cy || ((a >> 4) >= 9 && lo > 9)) {
    corr |= 0x60;
    cy = true;
  }
  const unsigned r = a + corr;
  regs.f = static_cast<std::uint8_t>(szp(r) | (cy ? flag::CY : 0) | ((a ^ corr ^ r) & 0x10u) |
                                     fixed_flags(mode_));
  regs.a = static_cast<std::uint8_t>(r);
}

// An undocumented 8085 opcode: executed as a one-byte NOP of 4 T-states and
// flagged in last(), so that a program relying on one is reported
// (docs/i8085.md).
int Cpu::undocumented() {
  last_.undocumented = true;
  return 4;
}

// The opcode map: x = bits 7-6 picks a quarter, z = bits 2-0 a column of
// quarters 0 and 3, y = bits 5-3 the row (a register, condition or
// operation). Each entry is one instruction group. Flattened: the groups
// are inlined here, so that the split costs the hot loop no calls.
[[gnu::flatten]] int Cpu::execute(std::uint8_t op) {
  const int y = op_y(op), z = op_z(op);
  const bool m85 = is_8085();
  switch (op_x(op)) {
    case 1: return halt_or_move(op);
    case 2: alu(y, get_reg(z)); return z == 6 ? 7 : 4;
    case 0:
      switch (z) {
        case 0: return nop_rim_sim(op);
        case 1: return lxi_or_dad(op);
        case 2: return load_or_store(y);
        case 3: return inx_or_dcx(op);
        case 4: set_reg(y, inr(get_reg(y))); return y == 6 ? 10 : (m85 ? 4 : 5);
        case 5: set_reg(y, dcr(get_reg(y))); return y == 6 ? 10 : (m85 ? 4 : 5);
        case 6: set_reg(y, fetch8()); return y == 6 ? 10 : 7;  // MVI
        default: return rotate_or_carry(y);
      }
    default:
      switch (z) {
        case 0: return return_if(y);
        case 1: return pop_or_return(op);
        case 2: return jump_if(y);
        case 3: return jmp_out_in_xthl_xchg_di_ei(op);
        case 4: return call_if(y);
        case 5: return push_or_call(op);
        case 6: alu(y, fetch8()); return 7;  // ALU immediate
        default: call(static_cast<std::uint16_t>(y * 8)); return m85 ? 12 : 11;  // RST
      }
  }
}

int Cpu::halt_or_move(std::uint8_t op) {
  const bool m85 = is_8085();
  if (op == 0x76) {  // HLT
    halted_ = true;
    return m85 ? 5 : 7;
  }
  const int dst = op_y(op), src = op_z(op);
  set_reg(dst, get_reg(src));
  if (dst == 6 || src == 6) return 7;
  return m85 ? 4 : 5;
}

int Cpu::nop_rim_sim(std::uint8_t op) {
  if (!is_8085()) return 4;  // the 8080's NOP and its aliases
  if (op == 0x20) {  // RIM
    regs.a = rim_value();
    rim_after_trap_ = false;
    return 4;
  }
  if (op == 0x30) {  // SIM
    const std::uint8_t a = regs.a;
    if (a & 0x08) masks_ = a & 0x07;
    if (a & 0x10) rst75_latch_ = false;
    if (a & 0x40) sod_ = (a & 0x80) != 0;
    return 4;
  }
  if (op != 0x00) return undocumented();
  return 4;  // NOP
}

int Cpu::lxi_or_dad(std::uint8_t op) {
  const int rp = op_rp(op);
  if ((op_y(op) & 1) == 0) {  // LXI
    set_rp(rp, fetch16());
    return 10;
  }
  // DAD
  const std::uint32_t r = static_cast<std::uint32_t>(regs.hl()) + get_rp(rp);
  set_rp(2, static_cast<std::uint16_t>(r));
  regs.f = static_cast<std::uint8_t>((regs.f & ~flag::CY) | ((r >> 16) & 1u ? flag::CY : 0));
  return 10;
}

// STAX LDAX SHLD LHLD STA LDA.
int Cpu::load_or_store(int y) {
  switch (y) {
    case 0: write(regs.bc(), regs.a); return 7;  // STAX B
    case 2: write(regs.de(), regs.a); return 7;  // STAX D
    case 4: {  // SHLD
      const std::uint16_t a = fetch16();
      write(a, regs.l);
      write(static_cast<std::uint16_t>(a + 1), regs.h);
      return 16;
    }
    case 6: write(fetch16(), regs.a); return 13;  // STA
    case 1: regs.a = read(regs.bc()); return 7;   // LDAX B
    case 3: regs.a = read(regs.de()); return 7;   // LDAX D
    case 5: {  // LHLD
      const std::uint16_t a = fetch16();
      regs.l = read(a);
      regs.h = read(static_cast<std::uint16_t>(a + 1));
      return 16;
    }
    default: regs.a = read(fetch16()); return 13;  // LDA
  }
}

int Cpu::inx_or_dcx(std::uint8_t op) {
  const int rp = op_rp(op);
  set_rp(rp, static_cast<std::uint16_t>(get_rp(rp) + ((op_y(op) & 1) ? -1 : 1)));
  return is_8085() ? 6 : 5;
}

void Cpu::set_carry(bool c) { regs.f = static_cast<std::uint8_t>((regs.f & ~flag::CY) | (c ? flag::CY : 0)); }

// RLC RRC RAL RAR DAA CMA STC CMC.
int Cpu::rotate_or_carry(int y) {
  const std::uint8_t a = regs.a;
  const bool cy = (regs.f & flag::CY) != 0;
  switch (y) {
    case 0: regs.a = static_cast<std::uint8_t>(a << 1 | a >> 7); set_carry(a & 0x80); break;  // RLC
    case 1: regs.a = static_cast<std::uint8_t>(a >> 1 | a << 7); set_carry(a & 0x01); break;  // RRC
    case 2: regs.a = static_cast<std::uint8_t>(a << 1 | (cy ? 1 : 0)); set_carry(a & 0x80); break;  // RAL
    case 3: regs.a = static_cast<std::uint8_t>(a >> 1 | (cy ? 0x80 : 0)); set_carry(a & 0x01); break;  // RAR
    case 4: daa(); break;
    case 5: regs.a = static_cast<std::uint8_t>(~a); break;  // CMA
    case 6: set_carry(true); break;                         // STC
    default: set_carry(!cy); break;                         // CMC
  }
  return 4;
}

// Rcc.
int Cpu::return_if(int cc) {
  const bool m85 = is_8085();
  if (condition(cc)) {
    regs.pc = pop();
    return m85 ? 12 : 11;
  }
  return m85 ? 6 : 5;
}

// POP, and RET (D9 is an RET alias on the 8080, SHLX on the 8085) PCHL SPHL.
int Cpu::pop_or_return(std::uint8_t op) {
  const int rp = op_rp(op);
  const bool m85 = is_8085();
  if ((op_y(op) & 1) == 0) {  // POP
    const std::uint16_t v = pop();
    if (rp == 3) {
      regs.a = static_cast<std::uint8_t>(v >> 8);
      regs.f = static_cast<std::uint8_t>((v & flag::kDefined) | fixed_flags(mode_));
    } else {
      set_rp(rp, v);
    }
    return 10;
  }
  switch (rp) {
    case 1:
      if (m85) return undocumented();  // SHLX
      [[fallthrough]];
    case 0: regs.pc = pop(); return 10;  // RET
    case 2: regs.pc = regs.hl(); return m85 ? 6 : 5;  // PCHL
    default: regs.sp = regs.hl(); return m85 ? 6 : 5;  // SPHL
  }
}

// Jcc.
int Cpu::jump_if(int cc) {
  const std::uint16_t a = fetch16();
  if (condition(cc)) {
    regs.pc = a;
    return 10;
  }
  return is_8085() ? 7 : 10;
}

// JMP (CB is a JMP alias on the 8080, RSTV on the 8085) OUT IN XTHL XCHG DI EI.
int Cpu::jmp_out_in_xthl_xchg_di_ei(std::uint8_t op) {
  switch (op_y(op)) {
    case 1:
      if (is_8085()) return undocumented();  // RSTV
      [[fallthrough]];
    case 0: regs.pc = fetch16(); return 10;  // JMP
    case 2: bus_.out(fetch8(), regs.a); return 10;  // OUT
    case 3: regs.a = bus_.in(fetch8()); return 10;  // IN
    case 4: return xthl();
    case 5: {  // XCHG
      std::swap(regs.d, regs.h);
      std::swap(regs.e, regs.l);
      return 4;
    }
    case 6: ie_ = false; ei_delay_ = false; return 4;  // DI
    default: ie_ = true; ei_delay_ = true; return 4;   // EI
  }
}

int Cpu::xthl() {
  const std::uint8_t lo = read(regs.sp);
  const std::uint8_t hi = read(static_cast<std::uint16_t>(regs.sp + 1));
  write(regs.sp, regs.l);
  write(static_cast<std::uint16_t>(regs.sp + 1), regs.h);
  regs.l = lo;
  regs.h = hi;
  return is_8085() ? 16 : 18;
}

void Cpu::call(std::uint16_t a) {
  push(regs.pc);
  regs.pc = a;
}

// Ccc.
int Cpu::call_if(int cc) {
  const bool m85 = is_8085();
  const std::uint16_t a = fetch16();
  if (condition(cc)) {
    call(a);
    return m85 ? 18 : 17;
  }
  return m85 ? 9 : 11;
}

// PUSH, and CALL (DD ED FD are CALL aliases on the 8080, JNX5 LHLX JK on the
// 8085).
int Cpu::push_or_call(std::uint8_t op) {
  const int y = op_y(op), rp = op_rp(op);
  const bool m85 = is_8085();
  if ((y & 1) == 0) {  // PUSH
    push(rp == 3 ? static_cast<std::uint16_t>(regs.a << 8 | regs.f) : get_rp(rp));
    return m85 ? 12 : 11;
  }
  if (y != 1 && m85) return undocumented();  // JNX5 LHLX JK
  call(fetch16());
  return m85 ? 18 : 17;
}

Interrupt Cpu::pending(bool maskable_allowed) const {
  if (mode_ == Mode::i8085) {
    if (trap_latch_ && trap_level_) return Interrupt::trap;
    if (!maskable_allowed) return Interrupt::none;
    if (rst75_latch_ && !(masks_ & 0x04)) return Interrupt::rst75;
    if (rst65_level_ && !(masks_ & 0x02)) return Interrupt::rst65;
    if (rst55_level_ && !(masks_ & 0x01)) return Interrupt::rst55;
  }
  if (maskable_allowed && intr_level_) return Interrupt::intr;
  return Interrupt::none;
}

int Cpu::acknowledge(Interrupt irq) {
  halted_ = false;
  last_.kind = StepKind::interrupt;
  last_.irq = irq;
  if (irq == Interrupt::trap) {
    trap_latch_ = false;
    ie_before_trap_ = ie_;
    rim_after_trap_ = true;
  }
  ie_ = false;
  std::uint16_t vector = 0;
  switch (irq) {
    case Interrupt::trap: vector = kTrapVector; break;
    case Interrupt::rst75: vector = kRst75Vector; rst75_latch_ = false; break;
    case Interrupt::rst65: vector = kRst65Vector; break;
    case Interrupt::rst55: vector = kRst55Vector; break;
    default: {  // INTR: execute the instruction the bus supplies
      from_inta_ = true;
      const std::uint8_t op = fetch8();
      const int t = execute(op);
      from_inta_ = false;
      return t;
    }
  }
  push(regs.pc);
  regs.pc = vector;
  return kVectoredAckTStates;
}

int Cpu::step() {
  last_ = Step{};
  last_.t_before = t_;
  last_.pc = regs.pc;
  last_.mode = mode_;
  const bool maskable_allowed = ie_ && !ei_delay_;
  ei_delay_ = false;
  int t;
  if (const Interrupt irq = pending(maskable_allowed); irq != Interrupt::none) {
    t = acknowledge(irq);
  } else if (halted_) {
    last_.kind = StepKind::idle;
    t = kHaltIdleTStates;
  } else {
    t = execute(fetch8());
  }
  last_.tstates = t;
  t_ += static_cast<std::uint64_t>(t);
  return t;
}

bool is_undocumented_8085(std::uint8_t op) {
  switch (op) {
    case 0x08: case 0x10: case 0x18: case 0x28: case 0x38:
    case 0xCB: case 0xD9: case 0xDD: case 0xED: case 0xFD:
      return true;
    default:
      return false;
  }
}

int instruction_length(std::uint8_t op, Mode mode) {
  if (mode == Mode::i8085 && is_undocumented_8085(op)) return 1;
  const int x = op >> 6, z = op & 7;
  if (x == 0) {
    if (z == 1 && ((op >> 3) & 1) == 0) return 3;              // LXI
    if (z == 2 && ((op >> 3) & 7) >= 4) return 3;              // SHLD LHLD STA LDA
    if (z == 6) return 2;                                      // MVI
    return 1;
  }
  if (x == 3) {
    if (z == 2 || z == 4) return 3;                            // Jcc Ccc
    if (z == 6) return 2;                                      // ALU immediate
    if (op == 0xC3 || op == 0xCB || op == 0xCD || op == 0xDD || op == 0xED || op == 0xFD) return 3;
    if (op == 0xD3 || op == 0xDB) return 2;                    // OUT IN
  }
  return 1;
}

}  // namespace i8085
