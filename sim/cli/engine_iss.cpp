// Engine "iss": the 8085 program sw8085/interp/interp.a80 on the C++
// instruction-set simulator (model/i8085), with the board of
// docs/board8085.md modelled in C++ (sw8085/interp/host.hpp).
#include "registry.hpp"
#include "sw8085/interp/host.hpp"

namespace contour::cli {
namespace {

const EngineRegistrar kIss{{"iss", "the 8085 program (sw8085/interp) on the C++ ISS",
                            [] { return std::make_unique<sw8085::ProgramEngine>("iss", i8085::make_iss); }}};

}  // namespace
}  // namespace contour::cli
