#include "rtl_engine.hpp"

#include <stdexcept>

#include "Vinterp_w24.h"
#include "core_harness.hpp"

namespace contour::rtl {

struct RtlEngine::Impl {
  CoreHarness<Vinterp_w24, 24> h;
};

RtlEngine::RtlEngine() : impl_(std::make_unique<Impl>()) {}
RtlEngine::~RtlEngine() = default;

RunResult RtlEngine::run(const Move& m) {
  const Block b = make_block<24>(m);
  RunResult r = impl_->h.run(b, pulse_bound(m));
  if (!r.final_state.done)
    throw std::runtime_error("rtl: the core did not end '" + describe(m) + "' within " +
                             std::to_string(pulse_bound(m)) + " pulses");
  return r;
}

}  // namespace contour::rtl
