// Engine "rtl": the Verilated interp_core (rtl/interp, W = 24), driven
// cycle by cycle with the command input held high.
// Without Verilator at configure time rtl/interp builds no library and the
// engine is simply absent.
#include "registry.hpp"

#if __has_include("rtl_engine.hpp")
#include "rtl_engine.hpp"

namespace contour::cli {
namespace {

const EngineRegistrar kRtl{{"rtl", "the Verilog core, Verilated (rtl/interp, W = 24)",
                            [] { return std::make_unique<rtl::RtlEngine>(); }}};

}  // namespace
}  // namespace contour::cli
#endif
