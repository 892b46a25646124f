// Engine "core": the Verilated interp_core (rtl/interp, W = 24; its
// harness tb/interp/core_engine.hpp), driven cycle by cycle with the
// command input held high. Without Verilator at configure time tb/ builds
// no harness and the engine is simply absent.
#include "registry.hpp"

#if __has_include("core_engine.hpp")
#include "core_engine.hpp"

namespace contour::cli {
namespace {

const EngineRegistrar kCore{{"core", "the Verilog interpolator core rtl/interp, Verilated (W = 24)",
                             [] { return std::make_unique<rtl::CoreEngine>(); }}};

}  // namespace
}  // namespace contour::cli
#endif
