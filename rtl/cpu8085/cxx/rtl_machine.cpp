#include "rtl_machine.hpp"

#include <stdexcept>

#include "Vcpu8085.h"
#include "verilated.h"
#include "verilated_fst_c.h"

namespace cpu8085 {

bool is_undocumented_8085(std::uint8_t op) {
  switch (op) {
    case 0x08: case 0x10: case 0x18: case 0x28: case 0x38:
    case 0xCB: case 0xD9: case 0xDD: case 0xED: case 0xFD:
      return true;
    default:
      return false;
  }
}

namespace {

// o_cycle / o_dbg_kind / o_dbg_irq encodings of cpu8085.v.
constexpr int kCycleMr = 1;
constexpr int kKindInstr = 0, kKindIack = 1, kKindIntr = 2;

class RtlMachine final : public i8085::Machine {
 public:
  RtlMachine(i8085::Bus& bus, const RtlOptions& opt) : bus_(bus), ctx_(new VerilatedContext) {
    if (!opt.fst_path.empty()) ctx_->traceEverOn(true);
    top_ = std::make_unique<Vcpu8085>(ctx_.get(), "cpu");
    if (!opt.fst_path.empty()) {
      fst_ = std::make_unique<VerilatedFstC>();
      top_->trace(fst_.get(), 99);
      fst_->open(opt.fst_path.c_str());
    }
    reset();
  }

  ~RtlMachine() override {
    top_->final();
    if (fst_) fst_->close();
  }

  i8085::Mode mode() const override { return i8085::Mode::i8085; }

  void reset() override {
    top_->i_rst = 1;
    raw_clock();
    top_->i_rst = 0;
    last_ = i8085::Step{};
  }

  int step() override {
    i8085::Step s;
    s.t_before = t_;
    s.mode = i8085::Mode::i8085;
    std::array<std::uint8_t, 3> operand{};
    int operands = 0;
    std::array<std::uint8_t, 3> inta{};
    int intas = 0;
    std::uint8_t opcode = 0;
    bool have_opcode = false;
    do {
      top_->i_clk = 0;
      top_->eval();
      dump();
      const std::uint16_t addr = top_->o_addr;
      if (top_->o_rd) {
        std::uint8_t v;
        if (top_->o_io) {
          v = bus_.in(static_cast<std::uint8_t>(addr & 0xFF));
        } else {
          v = bus_.read(addr);
          if (top_->o_cycle == 0 && !have_opcode) {
            opcode = v;
            have_opcode = true;
          } else if (top_->o_cycle == kCycleMr && operands < 2 && have_opcode &&
                     addr == static_cast<std::uint16_t>(top_->o_dbg_pc)) {
            operand[static_cast<std::size_t>(operands++)] = v;
          }
        }
        top_->i_din = v;
      }
      if (top_->o_inta) {
        const std::uint8_t v = bus_.inta();
        if (intas < 3) inta[static_cast<std::size_t>(intas++)] = v;
        top_->i_din = v;
      }
      if (top_->o_wr) {
        if (top_->o_io)
          bus_.out(static_cast<std::uint8_t>(addr & 0xFF), top_->o_dout);
        else
          bus_.write(addr, top_->o_dout);
      }
      top_->i_clk = 1;
      top_->eval();
      ++t_;
      dump();
    } while (!top_->o_retire);

    const int kind = top_->o_dbg_kind;
    s.pc = top_->o_dbg_ipc;
    s.tstates = static_cast<int>(t_ - s.t_before);
    if (kind == kKindInstr) {
      s.kind = i8085::StepKind::instruction;
      s.bytes[0] = opcode;
      s.length = static_cast<std::uint8_t>(i8085::instruction_length(opcode, i8085::Mode::i8085));
      for (int i = 1; i < s.length; ++i) {
        // A conditional jump or call not taken does not read its high byte
        // (that is what makes it 7 / 9 T-states); the trace still shows it.
        s.bytes[static_cast<std::size_t>(i)] =
            i <= operands ? operand[static_cast<std::size_t>(i - 1)]
                          : bus_.read(static_cast<std::uint16_t>(s.pc + i));
      }
      s.undocumented = is_undocumented_8085(opcode);
    } else if (kind == kKindIack || kind == kKindIntr) {
      s.kind = i8085::StepKind::interrupt;
      switch (top_->o_dbg_irq) {
        case 1: s.irq = i8085::Interrupt::trap; break;
        case 2: s.irq = i8085::Interrupt::rst75; break;
        case 3: s.irq = i8085::Interrupt::rst65; break;
        case 4: s.irq = i8085::Interrupt::rst55; break;
        default: s.irq = i8085::Interrupt::intr; break;
      }
      if (kind == kKindIntr) {
        s.bytes = inta;
        s.length = static_cast<std::uint8_t>(intas);
      }
    } else {
      s.kind = i8085::StepKind::idle;
    }
    last_ = s;
    return s.tstates;
  }

  std::uint64_t tstates() const override { return t_; }

  i8085::Regs regs() const override {
    const std::uint64_t r = top_->o_dbg_regs;
    auto byte = [r](int i) { return static_cast<std::uint8_t>(r >> (8 * i)); };
    i8085::Regs q{};
    q.a = byte(7);
    q.f = byte(6);
    q.b = byte(5);
    q.c = byte(4);
    q.d = byte(3);
    q.e = byte(2);
    q.h = byte(1);
    q.l = byte(0);
    q.sp = top_->o_dbg_sp;
    q.pc = top_->o_dbg_pc;
    return q;
  }

  void set_regs(const i8085::Regs& q) override {
    std::uint64_t r = 0;
    for (std::uint8_t v : {q.a, q.f, q.b, q.c, q.d, q.e, q.h, q.l}) r = r << 8 | v;
    top_->i_dbg_regs = r;
    top_->i_dbg_pc = q.pc;
    top_->i_dbg_sp = q.sp;
    top_->i_dbg_load = 1;
    raw_clock();
    top_->i_dbg_load = 0;
  }

  bool halted() const override { return top_->o_halted != 0; }
  bool ie() const override { return top_->o_ie != 0; }
  const i8085::Step& last() const override { return last_; }
  void set_trap(bool level) override { top_->i_trap = level; }
  void set_rst75(bool level) override { top_->i_rst75 = level; }
  void set_rst65(bool level) override { top_->i_rst65 = level; }
  void set_rst55(bool level) override { top_->i_rst55 = level; }
  void set_intr(bool level) override { top_->i_intr = level; }

 private:
  // A clock that is not a T-state: reset and debug loads. No bus traffic.
  void raw_clock() {
    top_->i_clk = 0;
    top_->eval();
    top_->i_clk = 1;
    top_->eval();
  }

  void dump() {
    if (!fst_) return;
    ctx_->time(ctx_->time() + 1);
    fst_->dump(ctx_->time());
  }

  i8085::Bus& bus_;
  std::unique_ptr<VerilatedContext> ctx_;
  std::unique_ptr<Vcpu8085> top_;
  std::unique_ptr<VerilatedFstC> fst_;
  std::uint64_t t_ = 0;
  i8085::Step last_{};
};

}  // namespace

std::unique_ptr<i8085::Machine> make_rtl_machine(i8085::Bus& bus, i8085::Mode mode, const RtlOptions& opt) {
  if (mode != i8085::Mode::i8085)
    throw std::invalid_argument("the RTL CPU (rtl/cpu8085) is an 8085 only: --cpu 8080 needs --engine iss");
  return std::make_unique<RtlMachine>(bus, opt);
}

}  // namespace cpu8085
