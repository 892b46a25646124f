// Pulse stage "rtl" of `contour gcode FILE --pulses --engine rtl`: each
// cycle's chord runs on the Verilated 3-axis core (rtl/interp3, W = 24).
// Without Verilator at configure time rtl/interp3 builds no library and
// the stage is simply absent.
#if __has_include("interp3_stage.hpp")
#include "interp3_stage.hpp"

namespace contour::cli {
namespace {

const planner::PulseStageRegistrar kRtl3{"rtl", rtl3::rtl_pulse_stage};

}  // namespace
}  // namespace contour::cli
#endif
