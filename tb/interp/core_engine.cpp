#include "core_engine.hpp"

#include <stdexcept>

#include "Vinterp_w24.h"
#include "core_harness.hpp"

namespace contour::rtl {

struct CoreEngine::Impl {
  CoreHarness<Vinterp_w24, 24> h;
};

CoreEngine::CoreEngine() : impl_(std::make_unique<Impl>()) {}
CoreEngine::~CoreEngine() = default;

RunResult CoreEngine::run(const Move& m) { return stream(m, {}); }

RunResult CoreEngine::stream(const Move& m, const StepFn& on_step) {
  const Block b = make_block<24>(m);
  RunResult r = impl_->h.run(b, pulse_bound(m), on_step);
  if (!r.final_state.done)
    throw std::runtime_error("core: the core did not end '" + describe(m) + "' within " +
                             std::to_string(pulse_bound(m)) + " pulses");
  return r;
}

}  // namespace contour::rtl
