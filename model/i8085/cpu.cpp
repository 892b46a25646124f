#include "i8085/cpu.hpp"

#include <stdexcept>
#include <utility>

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

// Flags S Z AC P of INR and DCR by result (CY and the fixed bits apart).
// INR: AC = the low nibble of the result is 0. DCR adds 0xFF: AC is the
// carry out of bit 3, i.e. set unless the low nibble wrapped from 0 to F.
constexpr std::array<std::uint8_t, 256> make_incdec(bool dec) {
  std::array<std::uint8_t, 256> t{};
  for (int r = 0; r < 256; ++r) {
    const bool ac = dec ? (r & 0x0F) != 0x0F : (r & 0x0F) == 0;
    t[static_cast<std::size_t>(r)] = static_cast<std::uint8_t>(kSzp[static_cast<std::size_t>(r)] | (ac ? flag::AC : 0));
  }
  return t;
}
constexpr std::array<std::uint8_t, 256> kInr = make_incdec(false);
constexpr std::array<std::uint8_t, 256> kDcr = make_incdec(true);

constexpr bool is85(Mode m) { return m == Mode::i8085; }

}  // namespace

Cpu::Cpu(Bus& bus, Mode mode) : bus_(bus), mem_(bus.memory()), mode_(mode) { reset(); }

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
  update_attention();
}

void Cpu::set_trap(bool level) {
  if (level && mode_ == Mode::i8080) throw std::logic_error("the 8080 has no TRAP input");
  if (level && !trap_level_) trap_latch_ = true;
  trap_level_ = level;
  update_attention();
}

void Cpu::set_rst75(bool level) {
  if (level && mode_ == Mode::i8080) throw std::logic_error("the 8080 has no RST 7.5 input");
  if (level && !rst75_level_) rst75_latch_ = true;
  rst75_level_ = level;
  update_attention();
}

void Cpu::set_rst65(bool level) {
  if (level && mode_ == Mode::i8080) throw std::logic_error("the 8080 has no RST 6.5 input");
  rst65_level_ = level;
  update_attention();
}

void Cpu::set_rst55(bool level) {
  if (level && mode_ == Mode::i8080) throw std::logic_error("the 8080 has no RST 5.5 input");
  rst55_level_ = level;
  update_attention();
}

void Cpu::set_intr(bool level) {
  intr_level_ = level;
  update_attention();
}

// Conservative: true whenever pending() might not be `none`, or the step
// is not a plain instruction (halted, EI delay).
void Cpu::update_attention() {
  const bool maskable = ie_ && (intr_level_ || (rst75_latch_ && !(masks_ & 0x04)) ||
                                (rst65_level_ && !(masks_ & 0x02)) || (rst55_level_ && !(masks_ & 0x01)));
  attention_ = halted_ || ei_delay_ || trap_latch_ || maskable;
}

std::uint8_t Cpu::rim_value() const {
  const bool ie = rim_after_trap_ ? ie_before_trap_ : ie_;
  return static_cast<std::uint8_t>((masks_ & 0x07) | (ie ? 0x08 : 0) | (rst55_level_ ? 0x10 : 0) |
                                   (rst65_level_ ? 0x20 : 0) | (rst75_latch_ ? 0x40 : 0));
}

// ---- Memory, operands, stack, registers -----------------------------------

template <bool D>
[[gnu::always_inline]] inline void Cpu::wr(std::uint16_t a, std::uint8_t v) {
  if constexpr (D)
    mem_[a] = v;
  else
    bus_.write(a, v);
}

// An operand byte at PC (from bus.inta() during an INTR acknowledge, which
// only the slow path, D = false, runs), recorded in last().
template <bool D>
[[gnu::always_inline]] inline std::uint8_t Cpu::imm8() {
  std::uint8_t v;
  if constexpr (D) {  // the fast path: the opcode is the only byte so far
    v = mem_[regs.pc];
    regs.pc = static_cast<std::uint16_t>(regs.pc + 1);
    last_.bytes[1] = v;
    last_.length = 2;
    return v;
  }
  if (from_inta_) {
    v = bus_.inta();
  } else {
    v = bus_.read(regs.pc);
    regs.pc = static_cast<std::uint16_t>(regs.pc + 1);
  }
  if (last_.length < 3) last_.bytes[last_.length++] = v;
  return v;
}

template <bool D>
[[gnu::always_inline]] inline std::uint16_t Cpu::imm16() {
  if constexpr (D) {  // the fast path: two bytes at PC, recorded at once
    const std::uint16_t pc = regs.pc;
    const std::uint8_t lo = mem_[pc], hi = mem_[static_cast<std::uint16_t>(pc + 1)];
    regs.pc = static_cast<std::uint16_t>(pc + 2);
    last_.bytes[1] = lo;
    last_.bytes[2] = hi;
    last_.length = 3;
    return static_cast<std::uint16_t>(hi << 8 | lo);
  }
  const std::uint8_t lo = imm8<D>();
  const std::uint8_t hi = imm8<D>();
  return static_cast<std::uint16_t>(hi << 8 | lo);
}

template <bool D>
[[gnu::always_inline]] inline void Cpu::push(std::uint16_t v) {
  regs.sp = static_cast<std::uint16_t>(regs.sp - 1);
  wr<D>(regs.sp, static_cast<std::uint8_t>(v >> 8));
  regs.sp = static_cast<std::uint16_t>(regs.sp - 1);
  wr<D>(regs.sp, static_cast<std::uint8_t>(v & 0xFF));
}

template <bool D>
[[gnu::always_inline]] inline std::uint16_t Cpu::pop() {
  const std::uint8_t lo = rd<D>(regs.sp);
  const std::uint8_t hi = rd<D>(static_cast<std::uint16_t>(regs.sp + 1));
  regs.sp = static_cast<std::uint16_t>(regs.sp + 2);
  return static_cast<std::uint16_t>(hi << 8 | lo);
}

// Register R of an opcode field: 0 B, 1 C, 2 D, 3 E, 4 H, 5 L, 6 M, 7 A.
template <bool D, int R>
std::uint8_t Cpu::get_r() {
  if constexpr (R == 0) return regs.b;
  else if constexpr (R == 1) return regs.c;
  else if constexpr (R == 2) return regs.d;
  else if constexpr (R == 3) return regs.e;
  else if constexpr (R == 4) return regs.h;
  else if constexpr (R == 5) return regs.l;
  else if constexpr (R == 6) return rd<D>(regs.hl());
  else return regs.a;
}

template <bool D, int R>
void Cpu::set_r(std::uint8_t v) {
  if constexpr (R == 0) regs.b = v;
  else if constexpr (R == 1) regs.c = v;
  else if constexpr (R == 2) regs.d = v;
  else if constexpr (R == 3) regs.e = v;
  else if constexpr (R == 4) regs.h = v;
  else if constexpr (R == 5) regs.l = v;
  else if constexpr (R == 6) wr<D>(regs.hl(), v);
  else regs.a = v;
}

// Register pair RP: 0 BC, 1 DE, 2 HL, 3 SP.
template <int RP>
std::uint16_t Cpu::get_rp() const {
  if constexpr (RP == 0) return regs.bc();
  else if constexpr (RP == 1) return regs.de();
  else if constexpr (RP == 2) return regs.hl();
  else return regs.sp;
}

template <int RP>
void Cpu::set_rp(std::uint16_t v) {
  const auto hi = static_cast<std::uint8_t>(v >> 8);
  const auto lo = static_cast<std::uint8_t>(v & 0xFF);
  if constexpr (RP == 0) { regs.b = hi; regs.c = lo; }
  else if constexpr (RP == 1) { regs.d = hi; regs.e = lo; }
  else if constexpr (RP == 2) { regs.h = hi; regs.l = lo; }
  else regs.sp = v;
}

// Condition CC: NZ Z NC C PO PE P M.
template <int CC>
bool Cpu::condition() const {
  constexpr std::uint8_t bit = CC < 2 ? flag::Z : CC < 4 ? flag::CY : CC < 6 ? flag::P : flag::S;
  return ((regs.f & bit) != 0) == ((CC & 1) != 0);
}

// ---- Arithmetic -------------------------------------------------------------

// ADD ADC SUB SBB ANA XRA ORA CMP (OP = 0..7). Subtraction is the addition
// of the one's complement with carry-in = NOT borrow, as the 8080/8085 ALU
// does it: AC is the carry out of bit 3 of that addition, CY the inverted
// carry out of bit 7 (a borrow).
template <Mode M, int OP>
void Cpu::alu(std::uint8_t v) {
  const unsigned a = regs.a;
  unsigned r;
  std::uint8_t f;
  if constexpr (OP <= 1) {  // ADD ADC
    const unsigned cin = OP == 1 ? (regs.f & flag::CY) : 0u;
    r = a + v + cin;
    f = static_cast<std::uint8_t>(szp(r) | ((r >> 8) & 1u) | ((a ^ v ^ r) & 0x10u));
  } else if constexpr (OP == 2 || OP == 3 || OP == 7) {  // SUB SBB CMP
    const unsigned cin = OP == 3 ? ((regs.f & flag::CY) ^ 1u) : 1u;
    const unsigned nv = static_cast<std::uint8_t>(~v);
    r = a + nv + cin;
    f = static_cast<std::uint8_t>(szp(r) | (((r >> 8) & 1u) ^ 1u) | ((a ^ nv ^ r) & 0x10u));
  } else if constexpr (OP == 4) {  // ANA: the 8085 sets AC; the 8080 sets it to bit 3 of (A | v).
    r = a & v;
    f = szp(r);
    if (is85(M) || ((a | v) & 0x08)) f |= flag::AC;
  } else if constexpr (OP == 5) {  // XRA
    r = a ^ v;
    f = szp(r);
  } else {  // ORA
    r = a | v;
    f = szp(r);
  }
  regs.f = static_cast<std::uint8_t>(f | fixed_flags(M));
  if constexpr (OP != 7) regs.a = static_cast<std::uint8_t>(r);
}

template <Mode M>
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
  regs.f = static_cast<std::uint8_t>(szp(r) | (cy ? flag::CY : 0) | ((a ^ corr ^ r) & 0x10u) | fixed_flags(M));
  regs.a = static_cast<std::uint8_t>(r);
}

// An undocumented 8085 opcode: executed as a one-byte NOP of 4 T-states and
// flagged in last(), so that a program relying on one is reported
// (docs/i8085.md).
int Cpu::undocumented() {
  last_.undocumented = true;
  return 4;
}

void Cpu::rim() {
  regs.a = rim_value();
  rim_after_trap_ = false;
}

void Cpu::sim() {
  const std::uint8_t a = regs.a;
  if (a & 0x08) masks_ = a & 0x07;
  if (a & 0x10) rst75_latch_ = false;
  if (a & 0x40) sod_ = (a & 0x80) != 0;
  update_attention();
}

// ---- The opcode map ---------------------------------------------------------
// OP's fields: x = bits 7-6 picks a quarter, z = bits 2-0 a column of
// quarters 0 and 3, y = bits 5-3 the row (a register, condition or
// operation), p = bits 5-4 a register pair. Every handler is a template on
// the opcode, so that its fields, registers and T-states are constants.

template <Mode M, bool D, int OP>
[[gnu::always_inline]] inline int Cpu::exec() {
  constexpr int x = OP >> 6, y = (OP >> 3) & 7, z = OP & 7;
  constexpr bool m85 = is85(M);
  if constexpr (OP == 0x76) {  // HLT
    halted_ = true;
    attention_ = true;
    return m85 ? 5 : 7;
  } else if constexpr (x == 1) {  // MOV
    set_r<D, y>(get_r<D, z>());
    return (y == 6 || z == 6) ? 7 : (m85 ? 4 : 5);
  } else if constexpr (x == 2) {  // ALU register
    alu<M, y>(get_r<D, z>());
    return z == 6 ? 7 : 4;
  } else if constexpr (x == 0) {
    return quarter0<M, D, OP>();
  } else {
    return quarter3<M, D, OP>();
  }
}

template <Mode M, bool D, int OP>
[[gnu::always_inline]] inline int Cpu::quarter0() {
  constexpr int y = (OP >> 3) & 7, z = OP & 7, p = (OP >> 4) & 3;
  constexpr bool m85 = is85(M);
  if constexpr (z == 0) {
    if constexpr (!m85 || OP == 0x00) return 4;  // NOP (the 8080's aliases too)
    else if constexpr (OP == 0x20) { rim(); return 4; }
    else if constexpr (OP == 0x30) { sim(); return 4; }
    else return undocumented();
  } else if constexpr (z == 1 && (y & 1) == 0) {  // LXI
    set_rp<p>(imm16<D>());
    return 10;
  } else if constexpr (z == 1) {  // DAD
    const std::uint32_t r = static_cast<std::uint32_t>(regs.hl()) + get_rp<p>();
    set_rp<2>(static_cast<std::uint16_t>(r));
    set_carry((r >> 16) & 1u);
    return 10;
  } else if constexpr (z == 2) {
    return load_store<M, D, OP>();
  } else if constexpr (z == 3) {  // INX DCX
    set_rp<p>(static_cast<std::uint16_t>(get_rp<p>() + ((y & 1) ? 0xFFFF : 1)));
    return m85 ? 6 : 5;
  } else if constexpr (z == 4 || z == 5) {  // INR DCR
    const auto r = static_cast<std::uint8_t>(get_r<D, y>() + (z == 4 ? 1 : 0xFF));
    regs.f = static_cast<std::uint8_t>((regs.f & flag::CY) | (z == 4 ? kInr[r] : kDcr[r]) | fixed_flags(M));
    set_r<D, y>(r);
    return y == 6 ? 10 : (m85 ? 4 : 5);
  } else if constexpr (z == 6) {  // MVI
    set_r<D, y>(imm8<D>());
    return y == 6 ? 10 : 7;
  } else {
    return rotate<M, D, OP>();
  }
}

// STAX LDAX SHLD LHLD STA LDA.
template <Mode M, bool D, int OP>
[[gnu::always_inline]] inline int Cpu::load_store() {
  constexpr int y = (OP >> 3) & 7;
  if constexpr (y == 0) { wr<D>(regs.bc(), regs.a); return 7; }   // STAX B
  else if constexpr (y == 1) { regs.a = rd<D>(regs.bc()); return 7; }  // LDAX B
  else if constexpr (y == 2) { wr<D>(regs.de(), regs.a); return 7; }   // STAX D
  else if constexpr (y == 3) { regs.a = rd<D>(regs.de()); return 7; }  // LDAX D
  else if constexpr (y == 4) {  // SHLD
    const std::uint16_t a = imm16<D>();
    wr<D>(a, regs.l);
    wr<D>(static_cast<std::uint16_t>(a + 1), regs.h);
    return 16;
  } else if constexpr (y == 5) {  // LHLD
    const std::uint16_t a = imm16<D>();
    regs.l = rd<D>(a);
    regs.h = rd<D>(static_cast<std::uint16_t>(a + 1));
    return 16;
  } else if constexpr (y == 6) {  // STA
    wr<D>(imm16<D>(), regs.a);
    return 13;
  } else {  // LDA
    regs.a = rd<D>(imm16<D>());
    return 13;
  }
}

// RLC RRC RAL RAR DAA CMA STC CMC.
template <Mode M, bool D, int OP>
[[gnu::always_inline]] inline int Cpu::rotate() {
  constexpr int y = (OP >> 3) & 7;
  const std::uint8_t a = regs.a;
  const unsigned cy = regs.f & flag::CY;
  if constexpr (y == 0) { regs.a = static_cast<std::uint8_t>(a << 1 | a >> 7); set_carry(a & 0x80); }
  else if constexpr (y == 1) { regs.a = static_cast<std::uint8_t>(a >> 1 | a << 7); set_carry(a & 0x01); }
  else if constexpr (y == 2) { regs.a = static_cast<std::uint8_t>(a << 1 | cy); set_carry(a & 0x80); }
  else if constexpr (y == 3) { regs.a = static_cast<std::uint8_t>(a >> 1 | cy << 7); set_carry(a & 0x01); }
  else if constexpr (y == 4) daa<M>();
  else if constexpr (y == 5) regs.a = static_cast<std::uint8_t>(~a);  // CMA
  else if constexpr (y == 6) set_carry(true);                          // STC
  else set_carry(!cy);                                                 // CMC
  return 4;
}

template <Mode M, bool D, int OP>
[[gnu::always_inline]] inline int Cpu::quarter3() {
  constexpr int y = (OP >> 3) & 7, z = OP & 7;
  constexpr bool m85 = is85(M);
  if constexpr (z == 0) {  // Rcc
    if (!condition<y>()) return m85 ? 6 : 5;
    regs.pc = pop<D>();
    return m85 ? 12 : 11;
  } else if constexpr (z == 1) {
    return pop_ret<M, D, OP>();
  } else if constexpr (z == 2) {  // Jcc
    const std::uint16_t a = imm16<D>();
    if (!condition<y>()) return m85 ? 7 : 10;
    regs.pc = a;
    return 10;
  } else if constexpr (z == 3) {
    return jmp_io_misc<M, D, OP>();
  } else if constexpr (z == 4) {  // Ccc
    const std::uint16_t a = imm16<D>();
    if (!condition<y>()) return m85 ? 9 : 11;
    push<D>(regs.pc);
    regs.pc = a;
    return m85 ? 18 : 17;
  } else if constexpr (z == 5) {
    return push_call<M, D, OP>();
  } else if constexpr (z == 6) {  // ALU immediate
    alu<M, y>(imm8<D>());
    return 7;
  } else {  // RST
    push<D>(regs.pc);
    regs.pc = static_cast<std::uint16_t>(y * 8);
    return m85 ? 12 : 11;
  }
}

// POP, and RET (D9 is an RET alias on the 8080, SHLX on the 8085) PCHL SPHL.
template <Mode M, bool D, int OP>
[[gnu::always_inline]] inline int Cpu::pop_ret() {
  constexpr int p = (OP >> 4) & 3;
  constexpr bool m85 = is85(M);
  if constexpr (((OP >> 3) & 1) == 0) {  // POP
    const std::uint16_t v = pop<D>();
    if constexpr (p == 3) {
      regs.a = static_cast<std::uint8_t>(v >> 8);
      regs.f = static_cast<std::uint8_t>((v & flag::kDefined) | fixed_flags(M));
    } else {
      set_rp<p>(v);
    }
    return 10;
  } else if constexpr (p == 1 && m85) {
    return undocumented();  // SHLX
  } else if constexpr (p <= 1) {
    regs.pc = pop<D>();  // RET
    return 10;
  } else if constexpr (p == 2) {
    regs.pc = regs.hl();  // PCHL
    return m85 ? 6 : 5;
  } else {
    regs.sp = regs.hl();  // SPHL
    return m85 ? 6 : 5;
  }
}

// JMP (CB is a JMP alias on the 8080, RSTV on the 8085) OUT IN XTHL XCHG DI EI.
template <Mode M, bool D, int OP>
[[gnu::always_inline]] inline int Cpu::jmp_io_misc() {
  constexpr int y = (OP >> 3) & 7;
  constexpr bool m85 = is85(M);
  if constexpr (y == 1 && m85) {
    return undocumented();  // RSTV
  } else if constexpr (y <= 1) {
    regs.pc = imm16<D>();  // JMP
    return 10;
  } else if constexpr (y == 2) {
    const std::uint8_t port = imm8<D>();
    bus_.out(port, regs.a);
    return 10;
  } else if constexpr (y == 3) {
    regs.a = bus_.in(imm8<D>());
    return 10;
  } else if constexpr (y == 4) {  // XTHL
    const std::uint16_t sp1 = static_cast<std::uint16_t>(regs.sp + 1);
    const std::uint8_t lo = rd<D>(regs.sp), hi = rd<D>(sp1);
    wr<D>(regs.sp, regs.l);
    wr<D>(sp1, regs.h);
    regs.l = lo;
    regs.h = hi;
    return m85 ? 16 : 18;
  } else if constexpr (y == 5) {  // XCHG
    std::swap(regs.d, regs.h);
    std::swap(regs.e, regs.l);
    return 4;
  } else if constexpr (y == 6) {  // DI
    ie_ = false;
    ei_delay_ = false;
    update_attention();
    return 4;
  } else {  // EI
    ie_ = true;
    ei_delay_ = true;
    attention_ = true;
    return 4;
  }
}

// PUSH, and CALL (DD ED FD are CALL aliases on the 8080, JNX5 LHLX JK on the
// 8085).
template <Mode M, bool D, int OP>
[[gnu::always_inline]] inline int Cpu::push_call() {
  constexpr int y = (OP >> 3) & 7, p = (OP >> 4) & 3;
  constexpr bool m85 = is85(M);
  if constexpr ((y & 1) == 0) {  // PUSH
    if constexpr (p == 3)
      push<D>(static_cast<std::uint16_t>(regs.a << 8 | regs.f));
    else
      push<D>(get_rp<p>());
    return m85 ? 12 : 11;
  } else if constexpr (y != 1 && m85) {
    return undocumented();  // JNX5 LHLX JK
  } else {
    const std::uint16_t a = imm16<D>();
    push<D>(regs.pc);
    regs.pc = a;
    return m85 ? 18 : 17;
  }
}

// One opcode: a switch over all 256, which the compiler turns into a jump
// table, each case the opcode's handler inlined with its fields constant.
#define I8085_CASE(n) \
  case (n): return exec<M, D, (n)>();
#define I8085_CASE4(n) I8085_CASE(n) I8085_CASE((n) + 1) I8085_CASE((n) + 2) I8085_CASE((n) + 3)
#define I8085_CASE16(n) I8085_CASE4(n) I8085_CASE4((n) + 4) I8085_CASE4((n) + 8) I8085_CASE4((n) + 12)
#define I8085_CASE64(n) I8085_CASE16(n) I8085_CASE16((n) + 16) I8085_CASE16((n) + 32) I8085_CASE16((n) + 48)

template <Mode M, bool D>
int Cpu::dispatch(std::uint8_t op) {
  switch (op) {
    I8085_CASE64(0x00)
    I8085_CASE64(0x40)
    I8085_CASE64(0x80)
    I8085_CASE64(0xC0)
  }
  __builtin_unreachable();
}

#undef I8085_CASE64
#undef I8085_CASE16
#undef I8085_CASE4
#undef I8085_CASE

// ---- Steps ------------------------------------------------------------------

// An instruction with nothing pending: the record of last() written field
// by field, no call but the dispatch.
template <Mode M, bool D>
int Cpu::fast_step() {
  const std::uint16_t pc = regs.pc;
  const std::uint8_t op = rd<D>(pc);
  regs.pc = static_cast<std::uint16_t>(pc + 1);
  last_.t_before = t_;
  last_.pc = pc;
  last_.bytes = {op, 0, 0};
  last_.length = 1;
  last_.kind = StepKind::instruction;
  last_.irq = Interrupt::none;
  last_.undocumented = false;
  const int t = dispatch<M, D>(op);
  last_.tstates = t;
  t_ += static_cast<std::uint64_t>(t);
  return t;
}

int Cpu::step() {
  if (attention_) [[unlikely]]
    return step_slow();
  if (mode_ == Mode::i8085) return mem_ ? fast_step<Mode::i8085, true>() : fast_step<Mode::i8085, false>();
  return mem_ ? fast_step<Mode::i8080, true>() : fast_step<Mode::i8080, false>();
}

// One opcode through the Bus (the slow path and INTR acknowledges).
int Cpu::execute(std::uint8_t op) {
  return mode_ == Mode::i8085 ? dispatch<Mode::i8085, false>(op) : dispatch<Mode::i8080, false>(op);
}

int Cpu::step_slow() {
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
    t = execute(imm8<false>());
  }
  last_.tstates = t;
  t_ += static_cast<std::uint64_t>(t);
  update_attention();
  return t;
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
      const int t = execute(imm8<false>());
      from_inta_ = false;
      return t;
    }
  }
  push<false>(regs.pc);
  regs.pc = vector;
  return kVectoredAckTStates;
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
