// The Verilated board rtl/board8085 (docs/board8085.md) as the machine of a
// Host: the engine "8085". Empty when the board is not built (no Verilator).
#pragma once

#include "i8085/machine.hpp"

namespace contour::sw8085 {

i8085::MachineFactory board_factory();

}  // namespace contour::sw8085
