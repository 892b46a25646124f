// The Verilated cpu8085 (rtl/cpu8085, docs/cpu8085.md) as an
// i8085::Machine: the same interface as the ISS, so `contour sim85 --engine
// cpu` and the lockstep regression (tb/cpu8085) drive both the same way.
//
// One clock of the model is one T-state. The bus is served from an
// i8085::Bus like the ISS's: a read strobe (T2) calls read()/in()/inta() and
// presents the byte in T3, a write strobe (T2) calls write()/out().
#pragma once

#include <memory>
#include <string>

#include "i8085/cpu.hpp"
#include "i8085/machine.hpp"

namespace cpu8085 {

// The Verilog CPU exists only as an 8085: Mode::i8080 throws
// std::invalid_argument. `fst_path` (or CONTOUR_FST) asks for a waveform.
std::unique_ptr<i8085::Machine> make_cpu_machine(i8085::Bus& bus, i8085::Mode mode, std::string fst_path = "");

}  // namespace cpu8085
