// Engine "cpu": the 8085 program sw8085/interp/interp.a80 on the Verilog
// 8085 board rtl/board8085 (its CPU, ROM, RAM, mailbox, edge counter and
// step port in Verilog; docs/board8085.md), Verilated (tb/cpu8085), driven
// by the same host as the engine "iss" (sw8085/interp/host.hpp).
#include "registry.hpp"

#if __has_include("board_machine.hpp")
#include "board_machine.hpp"
#include "sw8085/interp/host.hpp"

namespace contour::cli {
namespace {

const EngineRegistrar kCpu{{"cpu", "the 8085 program (sw8085/interp) on the Verilog 8085 board, Verilated",
                            [] { return std::make_unique<sw8085::ProgramEngine>("cpu", board8085::make_board_machine); }}};

}  // namespace
}  // namespace contour::cli
#endif
