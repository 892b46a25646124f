// The Verilated cpu8085 (rtl/cpu8085/cpu8085.v) as an i8085::Machine: the
// same interface as the ISS, so `contour sim85 --engine rtl` and the lockstep
// regression (tb/cpu8085) drive both the same way.
//
// One clock of the model is one T-state. The bus is served from an
// i8085::Bus like the ISS's: a read strobe (T2) calls read()/in()/inta() and
// presents the byte in T3, a write strobe (T2) calls write()/out().
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "i8085/cpu.hpp"
#include "i8085/machine.hpp"

namespace cpu8085 {

struct RtlOptions {
  std::string fst_path;  // write an FST waveform here when not empty
};

// The RTL CPU exists only as an 8085: Mode::i8080 throws std::invalid_argument.
std::unique_ptr<i8085::Machine> make_rtl_machine(i8085::Bus& bus, i8085::Mode mode,
                                                 const RtlOptions& opt = {});

// The opcodes the ISS runs as undocumented NOPs (docs/i8085.md); the RTL
// runs them the same way and the machine flags them the same way.
bool is_undocumented_8085(std::uint8_t op);

}  // namespace cpu8085
