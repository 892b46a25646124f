#include "board_machine.hpp"

#include <array>
#include <cstring>
#include <stdexcept>

#include "Vboard8085.h"
#include "Vboard8085___024root.h"
#include "debug_ports.hpp"
#include "harness.hpp"
#include "one_eval_clock.hpp"
#include "sw8085/interp/host.hpp"

#if VERILATOR_VERSION_INTEGER == 5006000
// The model's rising-edge region (one_eval_clock.hpp): the input region
// (the mailbox's write port follows the host's pins) then the NBA region,
// each under its one trigger, as the model's eval() runs them; of the NBA
// region its one function, the clocked blocks, called directly (no trigger
// set and tested, no trace activity flag: this path writes no waveform; a
// model whose NBA region had another function would not link).
void Vboard8085___024root___eval_ico(Vboard8085___024root* vlSelf);
void Vboard8085___024root___nba_sequent__TOP__0(Vboard8085___024root* vlSelf);
#endif

namespace board8085 {

namespace {

#if VERILATOR_VERSION_INTEGER == 5006000
void posedge(Vboard8085___024root* r) {
  r->__VicoTriggered.at(0) = true;
  Vboard8085___024root___eval_ico(r);
  Vboard8085___024root___nba_sequent__TOP__0(r);
}
constexpr cpu8085::OneEvalClock<Vboard8085>::Posedge kPosedge = &posedge;
#else
constexpr cpu8085::OneEvalClock<Vboard8085>::Posedge kPosedge = nullptr;
#endif

constexpr std::uint16_t kRamBase = 0x2000, kRamSize = 0x800, kMailbox = 0x3000;

class BoardMachine final : public i8085::Machine {
 public:
  explicit BoardMachine(i8085::Bus& bus) : bus_(bus), h_("", "board"), clock_(h_, !contour::tb::fst_request("").empty(), kPosedge) {
    // The host's own bus (sw8085/interp): its mailbox bytes are compared
    // with one memcmp per step instead of 256 virtual reads.
    if (auto* board_bus = dynamic_cast<contour::sw8085::BoardBus*>(&bus)) host_mailbox_ = board_bus->mailbox().data();
    top().i_intr_vec = 0xFF;
    // The first eval (in the harness) ran the memories' initial blocks: load
    // after it. The memories are reached through the model's root members
    // (Verilator 5 names them after the hierarchy; a different naming fails
    // to compile). Not `public_flat_rw`: on Verilator 5.006 its scopes
    // deadlock the model's destructor.
    auto* r = top().rootp;
    for (std::uint32_t a = 0; a < 0x2000; ++a)
      r->board8085__DOT__u_rom__DOT__mem[a] = bus_.read(static_cast<std::uint16_t>(a));
    for (std::uint32_t a = 0; a < kRamSize; ++a)
      r->board8085__DOT__u_ram__DOT__mem[a] = bus_.read(static_cast<std::uint16_t>(kRamBase + a));
    for (std::uint32_t a = 0; a < 0x100; ++a) poke_mailbox(a, bus_.read(static_cast<std::uint16_t>(kMailbox + a)));
    reset();
  }

  i8085::Mode mode() const override { return i8085::Mode::i8085; }

  void reset() override {
    h_.hold_reset(1);
    last_ = i8085::Step{};
  }

  int step() override {
    sync_mailbox();
    i8085::Step s;
    s.t_before = t_;
    s.mode = i8085::Mode::i8085;
#if VERILATOR_VERSION_INTEGER == 5006000
    if (clock_.direct()) {
      // The one-eval path with the rising edge called directly
      // (one_eval_clock.hpp): the same T-states, the path's tests hoisted
      // out of the loop.
      auto& t = top();
      clock_.posedge_loop_begin();
      do {
        if (t.o_cpu_wr) forward_write();
        posedge(t.rootp);
        ++t_;
      } while (!t.o_retire);
    } else
#endif
    {
      do {
        clock_.low();
        forward_write();
        clock_.high();
        ++t_;
      } while (!top().o_retire);
    }
    s.pc = top().o_dbg_ipc;
    s.tstates = static_cast<int>(t_ - s.t_before);
    describe_unit(s);
    last_ = s;
    return s.tstates;
  }

  std::uint64_t tstates() const override { return t_; }

  i8085::Regs regs() const override {
    return cpu8085::regs_of(top().o_dbg_regs, static_cast<std::uint16_t>(top().o_dbg_sp),
                            static_cast<std::uint16_t>(top().o_dbg_pc));
  }

  void set_regs(const i8085::Regs&) override {
    throw std::logic_error("board8085: the board has no register load; programs start from reset");
  }

  bool halted() const override { return top().o_halted != 0; }
  bool ie() const override { return top().o_ie != 0; }
  const i8085::Step& last() const override { return last_; }
  void set_trap(bool level) override { top().i_trap = level; }
  void set_rst75(bool level) override { top().i_cmd = level; }
  void set_rst65(bool level) override { top().i_rst65 = level; }
  void set_rst55(bool level) override { top().i_rst55 = level; }
  void set_intr(bool level) override { top().i_intr = level; }

 private:
  Vboard8085& top() { return h_.top(); }
  const Vboard8085& top() const { return h_.top(); }

  // A CPU write of this T-state goes to the host's Bus too.
  void forward_write() {
    if (!top().o_cpu_wr) return;
    const std::uint16_t a = top().o_cpu_addr;
    const std::uint8_t v = top().o_cpu_dout;
    if (top().o_cpu_io) {
      bus_.out(static_cast<std::uint8_t>(a & 0xFF), v);
    } else {
      bus_.write(a, v);
      if ((a >> 8) == (kMailbox >> 8)) shadow_[a & 0xFF] = v;
    }
  }

  // What retired, in the ISS's Step terms.
  void describe_unit(i8085::Step& s) const {
    const auto kind = static_cast<cpu8085::RetireKind>(top().o_dbg_kind);
    if (kind == cpu8085::RetireKind::instruction) {
      s.kind = i8085::StepKind::instruction;
      s.bytes[0] = top().o_dbg_op;
      s.length = cpu8085::opcode_table().length[s.bytes[0]];
      for (int i = 1; i < s.length; ++i)
        s.bytes[static_cast<std::size_t>(i)] = bus_.read(static_cast<std::uint16_t>(s.pc + i));
      s.undocumented = cpu8085::opcode_table().undocumented[s.bytes[0]];
    } else if (kind == cpu8085::RetireKind::acknowledge || kind == cpu8085::RetireKind::intr) {
      s.kind = i8085::StepKind::interrupt;
      s.irq = cpu8085::interrupt_of(top().o_dbg_irq);
    } else {
      s.kind = i8085::StepKind::idle;
    }
  }

  // Host writes to the mailbox since the last step go into the board's.
  void sync_mailbox() {
    if (host_mailbox_ != nullptr) {
      if (std::memcmp(host_mailbox_, shadow_.data(), shadow_.size()) == 0) return;
      for (std::uint32_t a = 0; a < 0x100; ++a)
        if (host_mailbox_[a] != shadow_[a]) poke_mailbox(a, host_mailbox_[a]);
      return;
    }
    for (std::uint32_t a = 0; a < 0x100; ++a) {
      const std::uint8_t v = bus_.read(static_cast<std::uint16_t>(kMailbox + a));
      if (v != shadow_[a]) poke_mailbox(a, v);
    }
  }

  void poke_mailbox(std::uint32_t a, std::uint8_t v) {
    auto* r = top().rootp;
    r->board8085__DOT__u_mbx__DOT__u_cpu_copy__DOT__mem[a] = v;
    r->board8085__DOT__u_mbx__DOT__u_host_copy__DOT__mem[a] = v;
    shadow_[a] = v;
  }

  i8085::Bus& bus_;
  contour::tb::Harness<Vboard8085> h_;
  cpu8085::OneEvalClock<Vboard8085> clock_;
  const std::uint8_t* host_mailbox_ = nullptr;  // the host's BoardBus mailbox, if it is one
  std::array<std::uint8_t, 256> shadow_{};
  std::uint64_t t_ = 0;
  i8085::Step last_{};
};

}  // namespace

std::unique_ptr<i8085::Machine> make_board_machine(i8085::Bus& bus, i8085::Mode mode) {
  if (mode != i8085::Mode::i8085) throw std::invalid_argument("board8085: the board's CPU is an 8085");
  return std::make_unique<BoardMachine>(bus);
}

}  // namespace board8085
