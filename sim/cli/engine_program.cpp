// Engines "iss" and "cpu": the 8085 program sw8085/interp/interp.a80 on the
// two 8085s, driven by the same host (sw8085/interp/host.hpp), which is
// given the machine here:
//   iss  the C++ instruction-set simulator (model/i8085), with the board of
//        docs/board8085.md modelled in C++ (the host's BoardBus);
//   cpu  the Verilog 8085 board rtl/board8085 (its CPU, ROM, RAM, mailbox,
//        edge counter and step port in Verilog), Verilated (tb/cpu8085);
//        absent when Verilator was not there at configure time.
#include "registry.hpp"
#include "sw8085/interp/host.hpp"
#if __has_include("board_machine.hpp")
#include "board_machine.hpp"
#endif

namespace contour::cli {
namespace {

std::unique_ptr<Engine> program_on(const char* name, i8085::MachineFactory machine) {
  return std::make_unique<sw8085::ProgramEngine>(name, std::move(machine));
}

const EngineRegistrar kIss{
    {"iss", "the 8085 program (sw8085/interp) on the C++ ISS", [] { return program_on("iss", i8085::make_iss); }}};

#if __has_include("board_machine.hpp")
const EngineRegistrar kCpu{{"cpu", "the 8085 program (sw8085/interp) on the Verilog 8085 board, Verilated",
                            [] { return program_on("cpu", board8085::make_board_machine); }}};
#endif

}  // namespace
}  // namespace contour::cli
