// Engine "8085": the 8085 program sw8085/interp/interp.a80 on the Verilog
// 8085 (rtl/cpu8085, Verilated: the "rtl" machine of sim/cli/machine_rtl.cpp),
// with the board's memory map, edge counter and step port in C++
// (sw8085/interp/host.hpp).
#include <stdexcept>

#include "i8085/machine.hpp"
#include "registry.hpp"
#include "sw8085/interp/host.hpp"

namespace contour::cli {
namespace {

std::unique_ptr<i8085::Machine> rtl_cpu(i8085::Bus& bus, i8085::Mode mode) {
  const auto it = i8085::machines().find("rtl");
  if (it == i8085::machines().end()) throw std::runtime_error("engine 8085: the Verilated CPU is not built (needs Verilator)");
  return it->second.make(bus, mode);
}

const EngineRegistrar k8085{{"8085", "the 8085 program (sw8085/interp) on the Verilated 8085 CPU",
                             [] { return std::make_unique<sw8085::ProgramEngine>("8085", rtl_cpu); }}};

}  // namespace
}  // namespace contour::cli
