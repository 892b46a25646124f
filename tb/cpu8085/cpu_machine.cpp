#include "cpu_machine.hpp"

#include <array>
#include <stdexcept>

#include "Vcpu8085.h"
#include "Vcpu8085___024root.h"
#include "debug_ports.hpp"
#include "harness.hpp"
#include "one_eval_clock.hpp"

#if VERILATOR_VERSION_INTEGER == 5006000
// The model's rising-edge region (one_eval_clock.hpp): the NBA region's one
// function, the clocked blocks, which the NBA region (_eval_nba) runs
// under its one trigger, the rising edge of i_clk (the model has no input
// region: no logic follows a pin). Called directly: no trigger set and
// tested, no trace activity flag (this path writes no waveform). A model
// whose NBA region had another function would not link (the name changes)
// or fail OneEvalClock.SameUnitsAsTwoEvals.
void Vcpu8085___024root___nba_sequent__TOP__0(Vcpu8085___024root* vlSelf);
#endif

namespace cpu8085 {

namespace {

#if VERILATOR_VERSION_INTEGER == 5006000
constexpr OneEvalClock<Vcpu8085>::Posedge kPosedge = &Vcpu8085___024root___nba_sequent__TOP__0;
#else
constexpr OneEvalClock<Vcpu8085>::Posedge kPosedge = nullptr;
#endif

// o_cycle of cpu8085.v: a memory read that is not an opcode fetch.
constexpr int kCycleMr = 1;

// The bytes the CPU read while one unit ran: its opcode, its operands (at
// most two, read at the PC), the bytes an INTR acknowledge took (at most 3).
struct UnitBytes {
  std::uint8_t opcode = 0;
  bool have_opcode = false;
  std::array<std::uint8_t, 2> operand{};
  int operands = 0;
  std::array<std::uint8_t, 3> inta{};
  int intas = 0;
};

class CpuMachine final : public i8085::Machine {
 public:
  CpuMachine(i8085::Bus& bus, const std::string& fst_path)
      : bus_(bus), h_(fst_path, "cpu"), clock_(h_, !contour::tb::fst_request(fst_path).empty(), kPosedge) {
    reset();
  }

  i8085::Mode mode() const override { return i8085::Mode::i8085; }

  void reset() override {
    h_.hold_reset(1);
    last_ = i8085::Step{};
  }

  int step() override {
    i8085::Step s;
    s.t_before = t_;
    s.mode = i8085::Mode::i8085;
    UnitBytes u;
#if VERILATOR_VERSION_INTEGER == 5006000
    if (clock_.direct()) {
      // The one-eval path with the model's rising-edge function called
      // directly (one_eval_clock.hpp): the same T-states, the loop's
      // tests of the path hoisted out of it; the bus served only in a
      // T-state with a strobe.
      auto& top = h_.top();
      clock_.posedge_loop_begin();
      do {
        if (top.o_rd | top.o_wr | top.o_inta) serve_bus(u);
        Vcpu8085___024root___nba_sequent__TOP__0(top.rootp);
        ++t_;
      } while (!top.o_retire);
    } else
#endif
    {
      do {
        clock_.low();
        serve_bus(u);
        clock_.high();
        ++t_;
      } while (!h_.top().o_retire);
    }
    s.pc = h_.top().o_dbg_ipc;
    s.tstates = static_cast<int>(t_ - s.t_before);
    describe_unit(s, u);
    last_ = s;
    return s.tstates;
  }

  std::uint64_t tstates() const override { return t_; }

  i8085::Regs regs() const override {
    return regs_of(h_.top().o_dbg_regs, static_cast<std::uint16_t>(h_.top().o_dbg_sp),
                   static_cast<std::uint16_t>(h_.top().o_dbg_pc));
  }

  void set_regs(const i8085::Regs& q) override {
    std::uint64_t r = 0;
    for (std::uint8_t v : {q.a, q.f, q.b, q.c, q.d, q.e, q.h, q.l}) r = r << 8 | v;
    auto& top = h_.top();
    top.i_dbg_regs = r;
    top.i_dbg_pc = q.pc;
    top.i_dbg_sp = q.sp;
    top.i_dbg_load = 1;
    h_.tick();  // not a T-state: no bus traffic
    top.i_dbg_load = 0;
  }

  bool halted() const override { return h_.top().o_halted != 0; }
  bool ie() const override { return h_.top().o_ie != 0; }
  const i8085::Step& last() const override { return last_; }
  void set_trap(bool level) override { h_.top().i_trap = level; }
  void set_rst75(bool level) override { h_.top().i_rst75 = level; }
  void set_rst65(bool level) override { h_.top().i_rst65 = level; }
  void set_rst55(bool level) override { h_.top().i_rst55 = level; }
  void set_intr(bool level) override { h_.top().i_intr = level; }

 private:
  // The bus strobes of this T-state, served from the Bus; what was read is
  // kept in `u` for the trace.
  void serve_bus(UnitBytes& u) {
    auto& top = h_.top();
    const std::uint16_t addr = top.o_addr;
    if (top.o_rd) top.i_din = top.o_io ? bus_.in(static_cast<std::uint8_t>(addr & 0xFF)) : read_memory(addr, u);
    if (top.o_inta) {
      const std::uint8_t v = bus_.inta();
      if (u.intas < 3) u.inta[static_cast<std::size_t>(u.intas++)] = v;
      top.i_din = v;
    }
    if (top.o_wr) {
      if (top.o_io)
        bus_.out(static_cast<std::uint8_t>(addr & 0xFF), top.o_dout);
      else
        bus_.write(addr, top.o_dout);
    }
  }

  std::uint8_t read_memory(std::uint16_t addr, UnitBytes& u) {
    const auto& top = h_.top();
    const std::uint8_t v = bus_.read(addr);
    if (top.o_cycle == 0 && !u.have_opcode) {
      u.opcode = v;
      u.have_opcode = true;
    } else if (top.o_cycle == kCycleMr && u.operands < 2 && u.have_opcode &&
               addr == static_cast<std::uint16_t>(top.o_dbg_pc)) {
      u.operand[static_cast<std::size_t>(u.operands++)] = v;
    }
    return v;
  }

  // What retired, in the ISS's Step terms.
  void describe_unit(i8085::Step& s, const UnitBytes& u) const {
    const auto kind = static_cast<RetireKind>(h_.top().o_dbg_kind);
    if (kind == RetireKind::instruction) {
      s.kind = i8085::StepKind::instruction;
      s.bytes[0] = u.opcode;
      s.length = opcodes_.length[u.opcode];
      for (int i = 1; i < s.length; ++i) {
        // A conditional jump or call not taken does not read its high byte
        // (that is what makes it 7 / 9 T-states); the trace still shows it.
        s.bytes[static_cast<std::size_t>(i)] = i <= u.operands ? u.operand[static_cast<std::size_t>(i - 1)]
                                                               : bus_.read(static_cast<std::uint16_t>(s.pc + i));
      }
      s.undocumented = opcodes_.undocumented[u.opcode];
    } else if (kind == RetireKind::acknowledge || kind == RetireKind::intr) {
      s.kind = i8085::StepKind::interrupt;
      s.irq = interrupt_of(h_.top().o_dbg_irq);
      if (kind == RetireKind::intr) {
        s.bytes = u.inta;
        s.length = static_cast<std::uint8_t>(u.intas);
      }
    } else {
      s.kind = i8085::StepKind::idle;
    }
  }

  i8085::Bus& bus_;
  const OpcodeTable& opcodes_ = opcode_table();
  contour::tb::Harness<Vcpu8085> h_;
  OneEvalClock<Vcpu8085> clock_;
  std::uint64_t t_ = 0;
  i8085::Step last_{};
};

}  // namespace

std::unique_ptr<i8085::Machine> make_cpu_machine(i8085::Bus& bus, i8085::Mode mode, std::string fst_path) {
  if (mode != i8085::Mode::i8085)
    throw std::invalid_argument("the Verilog CPU (rtl/cpu8085) is an 8085 only: --cpu 8080 needs --engine iss");
  return std::make_unique<CpuMachine>(bus, fst_path);
}

}  // namespace cpu8085
