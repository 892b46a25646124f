// The Verilated interp_core at W = 24 behind the contour::Engine seam
// (`contour ... --engine rtl`).
#pragma once

#include <memory>
#include <string>

#include "interp/engine.hpp"

namespace contour::rtl {

class RtlEngine final : public Engine {
 public:
  RtlEngine();
  ~RtlEngine() override;
  std::string name() const override { return "rtl"; }
  // Throws InputError outside the accepted domain (the host's validation),
  // std::runtime_error if the core does not end the move.
  RunResult run(const Move& m) override;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace contour::rtl
