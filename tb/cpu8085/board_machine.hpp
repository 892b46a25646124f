// The Verilated board (rtl/board8085, docs/board8085.md) as an
// i8085::Machine, so that a host written for the ISS on a C++ model of the
// board (e.g. sw8085/interp's Host and BoardBus) runs the program on the
// Verilog board instead: `factory = board8085::make_board_machine` (the
// engine "cpu" of sim/cli).
//
// The CPU reads its own ROM, RAM, mailbox and I/O ports. The given Bus is
// the host's view: at construction its 0x0000-0x27FF and 0x3000-0x30FF are
// copied into the board's memories; before each step, mailbox bytes the host
// changed in the Bus are copied in (a simulation backdoor: instantaneous, as
// between two ISS steps); every memory and port write of the CPU is
// forwarded to the Bus (write / out), so the host sees what the CPU wrote.
// IN 11h is answered by the board's own edge counter of RST 7.5 (i_cmd).
// set_regs is not available (the board has no debug load): it throws.
#pragma once

#include <memory>

#include "i8085/cpu.hpp"
#include "i8085/machine.hpp"

namespace board8085 {

// Mode::i8080 throws std::invalid_argument.
std::unique_ptr<i8085::Machine> make_board_machine(i8085::Bus& bus, i8085::Mode mode);

}  // namespace board8085
