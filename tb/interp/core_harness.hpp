// A C++ harness around a Verilated interp_core (any W), on the one harness
// base (tb/common/harness.hpp: clock, reset, FST on request): pushing
// blocks, running moves, reading the observable state as the golden
// model's contour::State. Used by the regression (tb/interp) and by the
// engine "core" (core_engine.hpp).
#pragma once

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "block.hpp"
#include "harness.hpp"
#include "interp/engine.hpp"

namespace contour::rtl {

// One observed output pulse with the state after it.
struct Observed {
  Pulse pulse;
  State state;
  bool last = false;     // the pulse that ended its move
  std::uint64_t cycle = 0;
};

template <class V, unsigned W>
class CoreHarness : public tb::Harness<V> {
 public:
  static constexpr unsigned kWidth = W;
  using tb::Harness<V>::top;
  using tb::Harness<V>::tick;

  explicit CoreHarness(std::string fst_path = "") : tb::Harness<V>(std::move(fst_path)) {
    top().i_abort = 0;
    top().i_cmd = 0;
    top().i_push = 0;
    this->hold_reset(2);
  }

  void reset() {
    top().i_push = 0;
    top().i_cmd = 0;
    this->hold_reset(1);
  }

  // Presents a block for one clock; returns false if the queue was full
  // (the block is then not taken).
  bool push(const Block& b) {
    const bool full = top().o_full;
    top().i_push = 1;
    static_assert(sizeof(top().i_blk) * 8 >= blk::bits(W), "i_blk narrower than the block of interp_block.vh");
    pack_block(top().i_blk, W, b);
    tick();
    top().i_push = 0;
    return !full;
  }

  // The output pulse of the current clock (registered in the DUT), if any.
  std::optional<Observed> pulse() const {
    if (!top().o_pulse) return std::nullopt;
    Observed o;
    o.pulse.axis = top().o_pulse_y ? Axis::Y : Axis::X;
    o.pulse.sign = top().o_pulse_neg ? -1 : +1;
    o.state = state();
    o.last = top().o_pulse_last;
    o.cycle = this->clocks();
    return o;
  }

  // The observable state as the model reports it (pulse count excluded:
  // the caller counts pulses).
  State state() const {
    State s;
    const auto xm = static_cast<std::int64_t>(top().o_xmag);
    const auto ym = static_cast<std::int64_t>(top().o_ymag);
    s.x = top().o_xneg ? -xm : xm;
    s.y = top().o_yneg ? -ym : ym;
    const std::uint64_t draw = static_cast<std::uint64_t>(top().o_d) & ((std::uint64_t{1} << (W + 2)) - 1);
    s.d = (draw & (std::uint64_t{1} << (W + 1))) ? static_cast<std::int64_t>(draw) - (std::int64_t{1} << (W + 2))
                                                   : static_cast<std::int64_t>(draw);
    s.quadrant = top().o_arc ? top().o_q : 0;
    s.crossings = top().o_arc ? top().o_k : 0;
    s.done = !top().o_busy;
    return s;
  }

  // Waits (command low) until every queued block has been loaded.
  void drain_queue(unsigned max_cycles = 16) {
    top().i_cmd = 0;
    for (unsigned i = 0; i < max_cycles && top().o_level != 0; ++i) tick();
    if (top().o_level != 0) throw std::runtime_error("rtl: the queue did not drain");
  }

  // Runs one block to its end with the command held high: returns the
  // initial state and every pulse (with `on_step`: hands each pulse there
  // and keeps none). Stops after `max_pulses` (a runaway).
  RunResult run(const Block& b, std::uint64_t max_pulses, const StepFn& on_step = {}) {
    RunResult r;
    if (!push(b)) throw std::runtime_error("rtl: queue full");
    drain_queue();
    r.initial_state = state();
    top().i_cmd = 1;
    std::uint64_t n = 0;
    bool last = r.initial_state.done;
    while (!last && n < max_pulses) {
      tick();
      if (auto o = pulse()) {
        o->state.pulses = ++n;
        if (on_step) on_step({o->pulse, o->state});
        else r.steps.push_back({o->pulse, o->state});
        last = o->last;
      } else if (!top().o_busy) {
        break;  // done without a last pulse: the checker reports it
      }
    }
    top().i_cmd = 0;
    tick();
    r.final_state = state();
    r.final_state.pulses = n;
    return r;
  }
};

// Upper bound on the pulses of an accepted move (a runaway guard): a line
// has |Xe| + |Ye|, an arc at most 4 quadrants of 2(R + 1) each, plus slack.
inline std::uint64_t pulse_bound(const Move& m) {
  auto mag = [](std::int64_t v) { return static_cast<std::uint64_t>(v < 0 ? -v : v); };
  if (!m.is_arc()) return mag(m.xe) + mag(m.ye);
  const std::uint64_t r = mag(m.xs) + mag(m.ys);  // >= R
  return 10 * (r + 1) + 16;
}

}  // namespace contour::rtl
