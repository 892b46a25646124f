// The "rtl" machine of `contour sim85 --engine rtl`: the Verilated 8085 CPU
// of rtl/cpu8085 (docs/cpu8085.md) behind the same i8085::Machine interface
// as the ISS, so output and the final `T-states: N` line are produced by the
// same runner. CPU8085_FST=path writes the waveform (FST) of the run.
#include <cstdlib>

#include "i8085/machine.hpp"
#include "rtl_machine.hpp"

namespace {

std::unique_ptr<i8085::Machine> make(i8085::Bus& bus, i8085::Mode mode) {
  cpu8085::RtlOptions opt;
  if (const char* p = std::getenv("CPU8085_FST"); p != nullptr) opt.fst_path = p;
  return cpu8085::make_rtl_machine(bus, mode, opt);
}

const i8085::MachineRegistrar kRtl{{"rtl", "the Verilog CPU rtl/cpu8085, Verilated (8085 only)", make}};

}  // namespace
