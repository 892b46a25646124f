// A C++ harness around a Verilated interp3_core (any W), on the one harness
// base (tb/common/harness.hpp: clock, reset, FST on request): loading a
// move, one command clock at a time, and the observable state as the
// golden model's contour::State3. Used by the regression (tb/interp3) and
// by the chord stage (interp3_stage.hpp).
#pragma once

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "harness.hpp"
#include "interp/linear3.hpp"
#include "interp/types.hpp"

namespace contour::rtl3 {

template <class V, unsigned W>
class Interp3Harness : public tb::Harness<V> {
 public:
  using tb::Harness<V>::top;
  using tb::Harness<V>::tick;

  // Constructed in reset: one reset clock with no load and no command.
  // `plusargs`: the model's run-time options, e.g. +verilator+rand+reset+2.
  explicit Interp3Harness(std::string fst_path = "", const std::vector<std::string>& plusargs = {})
      : tb::Harness<V>(std::move(fst_path), "TOP", plusargs) {
    reset();
  }

  void reset() {
    top().i_load = 0;
    top().i_cmd = 0;
    this->hold_reset(1);
    pulses_ = 0;
  }

  // Loads the move (XE, YE, ZE): the load clock, then the clocks in which
  // the core prepares it (o_ready low, kPrepClocks of them), so that the
  // next step() can pulse. Throws InputError outside the accepted domain
  // (the host's validation, Linear3<W>::validate).
  void load(std::int64_t xe, std::int64_t ye, std::int64_t ze) {
    Linear3<W>::validate(xe, ye, ze);
    auto mag = [](std::int64_t v) { return static_cast<std::uint64_t>(v < 0 ? -v : v); };
    top().i_xe = mag(xe);
    top().i_ye = mag(ye);
    top().i_ze = mag(ze);
    top().i_xneg = xe < 0;
    top().i_yneg = ye < 0;
    top().i_zneg = ze < 0;
    top().i_load = 1;
    top().i_cmd = 0;
    tick();
    top().i_load = 0;
    for (unsigned k = 0; !top().o_ready; ++k) {
      if (k == kPrepClocks) throw std::runtime_error("interp3_core: not ready " + std::to_string(k) + " clocks after a load");
      tick();
    }
    pulses_ = 0;
  }

  // Clocks after the load clock in which the core prepares a move
  // (docs/rtl-3axis.md, "Timing").
  static constexpr unsigned kPrepClocks = 4;

  bool ready() const { return top().o_ready; }

  // One clock with the command input at `cmd`; returns the output pulse of
  // that clock's step, if any (registered: visible after the edge, with the
  // state after the step).
  std::optional<Pulse> step(bool cmd = true) {
    top().i_cmd = cmd;
    tick();
    top().i_cmd = 0;
    pulses_ += strobes();
    return pulse();
  }

  // The pulse currently on the outputs. More than one strobe at once is
  // reported as nothing (the caller sees a count mismatch); strobes() tells.
  std::optional<Pulse> pulse() const {
    if (strobes() != 1) return std::nullopt;
    Pulse p;
    if (top().o_step_x) p = Pulse{Axis::X, static_cast<std::int8_t>(top().o_dir_x ? -1 : +1)};
    if (top().o_step_y) p = Pulse{Axis::Y, static_cast<std::int8_t>(top().o_dir_y ? -1 : +1)};
    if (top().o_step_z) p = Pulse{Axis::Z, static_cast<std::int8_t>(top().o_dir_z ? -1 : +1)};
    return p;
  }

  // Number of step strobes high on the outputs now (0 or 1 if correct).
  unsigned strobes() const {
    return unsigned{top().o_step_x != 0} + unsigned{top().o_step_y != 0} + unsigned{top().o_step_z != 0};
  }

  bool done() const { return top().o_done; }

  // The observable state as Linear3<W>::state() gives it; the pulse count
  // is the number of strobes seen by step() since the load.
  State3 state() const {
    State3 s;
    s.x = signed_mag(top().o_x, top().o_dir_x);
    s.y = signed_mag(top().o_y, top().o_dir_y);
    s.z = signed_mag(top().o_z, top().o_dir_z);
    s.dxy = sign_extend(top().o_exy);
    s.dxz = sign_extend(top().o_exz);
    s.dyz = sign_extend(top().o_eyz);
    s.pulses = pulses_;
    s.done = top().o_done;
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

  std::uint64_t pulses_ = 0;
};

}  // namespace contour::rtl3
