// The machine "cpu" of `contour sim85 --engine cpu`: the Verilated 8085 CPU
// of rtl/cpu8085 (docs/cpu8085.md; harness tb/cpu8085/cpu_machine.hpp)
// behind the same i8085::Machine interface as the ISS, so output and the
// final `T-states: N` line are produced by the same runner.
// CONTOUR_FST=FILE writes the waveform (FST) of the run.
#if __has_include("cpu_machine.hpp")
#include "cpu_machine.hpp"
#include "i8085/machine.hpp"

namespace {

std::unique_ptr<i8085::Machine> make(i8085::Bus& bus, i8085::Mode mode) { return cpu8085::make_cpu_machine(bus, mode); }

const i8085::MachineRegistrar kCpu{{"cpu", "the Verilog 8085 CPU rtl/cpu8085, Verilated (8085 only)", make}};

}  // namespace
#endif
