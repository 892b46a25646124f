// Engine "8085": the 8085 program sw8085/interp/interp.a80 on the Verilated
// 8085 board rtl/board8085 (its CPU, ROM, RAM, mailbox, edge counter and
// step port in Verilog; docs/board8085.md), driven by the same host as the
// "iss" engine (sw8085/interp/host.hpp).
#include <stdexcept>

#include "registry.hpp"
#include "sw8085/interp/board_factory.hpp"
#include "sw8085/interp/host.hpp"

namespace contour::cli {
namespace {

std::unique_ptr<Engine> make() {
  auto factory = sw8085::board_factory();
  if (!factory) throw std::runtime_error("engine 8085: the Verilated board rtl/board8085 is not built (needs Verilator)");
  return std::make_unique<sw8085::ProgramEngine>("8085", factory);
}

const EngineRegistrar k8085{{"8085", "the 8085 program (sw8085/interp) on the Verilated 8085 board", make}};

}  // namespace
}  // namespace contour::cli
