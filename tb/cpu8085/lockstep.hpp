// Lockstep of the Verilated cpu8085 against the C++ ISS (model/i8085): both
// run the same program from identical memories; after every step (one
// instruction, interrupt acknowledge or idle T-state) the kind of step, its
// PC, its T-states, the cumulative T-state count, all registers and flags,
// HALT, IE, and the memory and port writes of the step must be equal.
// Interrupt pins are changed on both before the same step, i.e. at the same
// T-state. The first divergence is reported with both trace lines and the
// ISS's preceding trace lines.
#pragma once

#include <array>
#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "i8085/cpu.hpp"
#include "i8085/machine.hpp"

namespace cpu8085::tb {

struct Access {
  bool io = false;
  std::uint16_t addr = 0;
  std::uint8_t value = 0;
  friend bool operator==(const Access&, const Access&) = default;
  friend bool operator<(const Access& a, const Access& b) {
    return a.io != b.io ? a.io < b.io : a.addr != b.addr ? a.addr < b.addr : a.value < b.value;
  }
};

// 64 KiB RAM; IN returns in_value(port, n) for the n-th IN (same function on
// both sides); INTA returns the bytes queued in `inta_bytes`, then RST 7.
class LogBus : public i8085::Bus {
 public:
  std::uint8_t read(std::uint16_t a) override { return mem[a]; }
  void write(std::uint16_t a, std::uint8_t v) override {
    mem[a] = v;
    log.push_back({false, a, v});
  }
  std::uint8_t in(std::uint8_t port) override { return in_value ? in_value(port, ins++) : 0xFF; }
  void out(std::uint8_t port, std::uint8_t v) override { log.push_back({true, port, v}); }
  std::uint8_t inta() override {
    if (inta_pos < inta_bytes.size()) return inta_bytes[inta_pos++];
    return 0xFF;
  }

  std::array<std::uint8_t, 65536> mem{};
  std::vector<Access> log;
  std::function<std::uint8_t(std::uint8_t port, std::uint64_t n)> in_value;
  std::uint64_t ins = 0;
  std::vector<std::uint8_t> inta_bytes;
  std::size_t inta_pos = 0;
};

struct Pins {
  bool trap = false, rst75 = false, rst65 = false, rst55 = false, intr = false;
};

class Lockstep {
 public:
  // `image` is loaded into both memories.
  explicit Lockstep(const std::array<std::uint8_t, 65536>& image, const std::string& fst_path = "");

  // Both machines' registers (e.g. PC = 0x0100 for a CP/M program).
  void set_regs(const i8085::Regs& r);
  void set_pins(const Pins& p);
  // Bytes the next INTR acknowledges will read, on both sides.
  void queue_inta(const std::vector<std::uint8_t>& bytes);
  void set_in_value(std::function<std::uint8_t(std::uint8_t, std::uint64_t)> f);

  // One step on both; false on a divergence (see report()).
  bool step();

  std::uint64_t tstates() const { return iss_->tstates(); }
  std::uint64_t steps() const { return steps_; }
  bool halted() const { return iss_->halted(); }
  bool ie() const { return iss_->ie(); }
  const i8085::Step& last() const { return iss_->last(); }
  i8085::Regs regs() const { return iss_->regs(); }
  const std::string& report() const { return report_; }
  std::uint8_t mem(std::uint16_t a) const { return iss_bus_.mem[a]; }
  // Changes one byte on one side only: for testing the divergence report.
  void poke_rtl_side(std::uint16_t a, std::uint8_t v) { rtl_bus_.mem[a] = v; }

 private:
  LogBus iss_bus_, rtl_bus_;
  std::unique_ptr<i8085::Machine> iss_, rtl_;
  std::deque<std::string> context_;
  std::uint64_t steps_ = 0;
  std::string report_;
};

}  // namespace cpu8085::tb
