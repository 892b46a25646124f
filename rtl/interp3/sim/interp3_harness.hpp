// A C++ harness around a Verilated interp3_core (any W): clock, reset,
// loading a move, one command clock at a time, and the observable state as
// the golden model's contour::State3. Used by the regression (tb/interp3)
// and by the CLI's pulse stage "rtl" (interp3_stage.cpp).
//
// Traces: FST, only when asked for (a file name in the constructor, or the
// environment variable CONTOUR_FST=FILE). close_trace() ends the waveform
// (a checker calls it at the first mismatch, so the trace ends at the bug).
#pragma once

#include <verilated.h>
#include <verilated_fst_c.h>

#include <cstdint>
#include <cstdlib>
#include <memory>
#include <optional>
#include <string>

#include "interp/linear3.hpp"
#include "interp/types.hpp"

namespace contour::rtl3 {

template <class V, unsigned W>
class Interp3Harness {
 public:
  static constexpr unsigned kWidth = W;

  explicit Interp3Harness(std::string fst_path = "") : ctx_(std::make_unique<VerilatedContext>()) {
    if (fst_path.empty()) {
      if (const char* env = std::getenv("CONTOUR_FST")) fst_path = env;
    }
    if (!fst_path.empty()) ctx_->traceEverOn(true);
    top_ = std::make_unique<V>(ctx_.get());
    if (!fst_path.empty()) {
      trace_ = std::make_unique<VerilatedFstC>();
      top_->trace(trace_.get(), 99);
      trace_->open(fst_path.c_str());
    }
    top_->i_clk = 0;
    top_->i_rst = 1;
    top_->i_load = 0;
    top_->i_cmd = 0;
    top_->eval();
    tick();
    top_->i_rst = 0;
  }

  ~Interp3Harness() {
    close_trace();
    top_->final();
  }
  Interp3Harness(const Interp3Harness&) = delete;
  Interp3Harness& operator=(const Interp3Harness&) = delete;

  V& top() { return *top_; }
  std::uint64_t clocks() const { return clocks_; }

  // One clock: the inputs set by the caller are sampled at the rising edge.
  void tick() {
    top_->i_clk = 0;
    top_->eval();
    dump();
    top_->i_clk = 1;
    top_->eval();
    dump();
    ++clocks_;
  }

  void close_trace() {
    if (trace_) {
      dump();
      trace_->close();
      trace_.reset();
    }
  }

  // A synchronous reset clock.
  void reset() {
    top_->i_rst = 1;
    top_->i_load = 0;
    top_->i_cmd = 0;
    tick();
    top_->i_rst = 0;
    pulses_ = 0;
  }

  // Loads the move (XE, YE, ZE) in one clock. Throws InputError outside the
  // accepted domain (the host's validation, Linear3<W>::validate).
  void load(std::int64_t xe, std::int64_t ye, std::int64_t ze) {
    Linear3<W>::validate(xe, ye, ze);
    auto mag = [](std::int64_t v) { return static_cast<std::uint64_t>(v < 0 ? -v : v); };
    top_->i_xe = mag(xe);
    top_->i_ye = mag(ye);
    top_->i_ze = mag(ze);
    top_->i_xneg = xe < 0;
    top_->i_yneg = ye < 0;
    top_->i_zneg = ze < 0;
    top_->i_load = 1;
    top_->i_cmd = 0;
    tick();
    top_->i_load = 0;
    pulses_ = 0;
  }

  // One clock with the command input at `cmd`; returns the output pulse of
  // that clock's step, if any (registered: visible after the edge, with the
  // state after the step).
  std::optional<Pulse> step(bool cmd = true) {
    top_->i_cmd = cmd;
    tick();
    top_->i_cmd = 0;
    pulses_ += strobes();
    return pulse();
  }

  // The pulse currently on the outputs. More than one strobe at once is
  // reported as nothing (the caller sees a count mismatch); strobes() tells.
  std::optional<Pulse> pulse() const {
    if (strobes() != 1) return std::nullopt;
    Pulse p;
    if (top_->o_step_x) p = Pulse{Axis::X, static_cast<std::int8_t>(top_->o_dir_x ? -1 : +1)};
    if (top_->o_step_y) p = Pulse{Axis::Y, static_cast<std::int8_t>(top_->o_dir_y ? -1 : +1)};
    if (top_->o_step_z) p = Pulse{Axis::Z, static_cast<std::int8_t>(top_->o_dir_z ? -1 : +1)};
    return p;
  }

  // Number of step strobes high on the outputs now (0 or 1 if correct).
  unsigned strobes() const {
    return unsigned{top_->o_step_x != 0} + unsigned{top_->o_step_y != 0} + unsigned{top_->o_step_z != 0};
  }

  bool done() const { return top_->o_done; }

  // The observable state as Linear3<W>::state() gives it; the pulse count
  // is the number of strobes seen by step() since the load.
  State3 state() const {
    State3 s;
    s.x = signed_mag(top_->o_x, top_->o_dir_x);
    s.y = signed_mag(top_->o_y, top_->o_dir_y);
    s.z = signed_mag(top_->o_z, top_->o_dir_z);
    s.dxy = sign_extend(top_->o_exy);
    s.dxz = sign_extend(top_->o_exz);
    s.dyz = sign_extend(top_->o_eyz);
    s.pulses = pulses_;
    s.done = top_->o_done;
    return s;
  }

 private:
  static std::int64_t signed_mag(std::uint64_t mag, bool neg) {
    const auto m = static_cast<std::int64_t>(mag & ((std::uint64_t{1} << W) - 1));
    return neg ? -m : m;
  }
  static std::int64_t sign_extend(std::uint64_t raw) {
    const std::uint64_t v = raw & ((std::uint64_t{1} << (W + 2)) - 1);
    return (v & (std::uint64_t{1} << (W + 1))) ? static_cast<std::int64_t>(v) - (std::int64_t{1} << (W + 2))
                                               : static_cast<std::int64_t>(v);
  }

  void dump() {
    if (trace_) trace_->dump(static_cast<std::uint64_t>(ctx_->time()));
    ctx_->timeInc(1);
  }

  std::unique_ptr<VerilatedContext> ctx_;
  std::unique_ptr<V> top_;
  std::unique_ptr<VerilatedFstC> trace_;
  std::uint64_t clocks_ = 0;
  std::uint64_t pulses_ = 0;
};

}  // namespace contour::rtl3
