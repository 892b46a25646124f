// The Verilated interp_core at W = 24 behind the contour::Engine seam: the
// engine "core" of `contour line|arc --engine core`, registered by
// sim/cli/engine_core.cpp.
#pragma once

#include <memory>
#include <string>

#include "interp/engine.hpp"

namespace contour::rtl {

class CoreEngine final : public Engine {
 public:
  CoreEngine();
  ~CoreEngine() override;
  std::string name() const override { return "core"; }
  // Throws InputError outside the accepted domain (the host's validation),
  // std::runtime_error if the core does not end the move.
  RunResult run(const Move& m) override;
  RunResult stream(const Move& m, const StepFn& on_step) override;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace contour::rtl
