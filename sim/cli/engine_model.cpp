// Engine "model": the golden C++ model at W = 24.
#include "registry.hpp"

namespace contour::cli {
namespace {

const EngineRegistrar kModel{{"model", "the golden C++ model (W = 24)",
                              [] { return std::make_unique<ModelEngine>(); }}};

}  // namespace
}  // namespace contour::cli
