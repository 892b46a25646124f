// The debug outputs that cpu8085.v (and board8085.v, which passes them on)
// gives a harness at each retire strobe, decoded into the ISS's terms:
// what retired (o_dbg_kind), which interrupt (o_dbg_irq), the registers
// (o_dbg_regs, A F B C D E H L from bit 63 down). Shared by the two
// Verilated 8085 machines (cpu_machine.cpp, board_machine.cpp).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "i8085/cpu.hpp"

namespace cpu8085 {

// o_dbg_kind: what the retire strobe ends.
enum class RetireKind : int { instruction = 0, acknowledge = 1, intr = 2, idle = 3 };

inline i8085::Interrupt interrupt_of(unsigned dbg_irq) {
  switch (dbg_irq) {
    case 1: return i8085::Interrupt::trap;
    case 2: return i8085::Interrupt::rst75;
    case 3: return i8085::Interrupt::rst65;
    case 4: return i8085::Interrupt::rst55;
    default: return i8085::Interrupt::intr;
  }
}

inline i8085::Regs regs_of(std::uint64_t dbg_regs, std::uint16_t sp, std::uint16_t pc) {
  auto byte = [dbg_regs](int i) { return static_cast<std::uint8_t>(dbg_regs >> (8 * i)); };
  return {byte(7), byte(6), byte(5), byte(4), byte(3), byte(2), byte(1), byte(0), sp, pc};
}

// The ISS's instruction_length (8085 mode) and is_undocumented_8085 of
// every opcode, for the machines' trace of a retired instruction: a
// lookup per instruction (the functions' switch costs more).
struct OpcodeTable {
  std::array<std::uint8_t, 256> length{};
  std::array<bool, 256> undocumented{};
  OpcodeTable() {
    for (std::size_t op = 0; op < 256; ++op) {
      const auto o = static_cast<std::uint8_t>(op);
      length[op] = static_cast<std::uint8_t>(i8085::instruction_length(o, i8085::Mode::i8085));
      undocumented[op] = i8085::is_undocumented_8085(o);
    }
  }
};
inline const OpcodeTable& opcode_table() {
  static const OpcodeTable t;
  return t;
}

}  // namespace cpu8085
