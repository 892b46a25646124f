// A C++ harness around a Verilated interp_core (any W): clock, reset,
// pushing blocks, running moves, reading the observable state as the
// golden model's contour::State. Used by the regression (tb/interp) and by
// the CLI's `--engine rtl`.
//
// Traces: FST, only when asked for (a file name in the constructor, or the
// environment variable CONTOUR_FST=FILE). A failing check calls
// close_trace() first, so the waveform ends at the bug.
#pragma once

#include <verilated.h>
#include <verilated_fst_c.h>

#include <cstdint>
#include <cstdlib>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "interp/engine.hpp"

namespace contour::rtl {

// A block as interp_core takes it (see rtl/interp/blk_prep.v).
struct Block {
  bool arc = false, cw = false, sxn = false, syn = false;
  std::uint8_t q = 0, k = 0;
  std::uint64_t xs = 0, ys = 0, xe = 0, ye = 0;  // magnitudes
};

// What the host does before writing a block: validate at width W and
// derive the start quadrant and the crossings (Circular<W>::validate).
// Throws InputError for a move outside the accepted domain.
template <unsigned W>
Block make_block(const Move& m) {
  validate<W>(m);
  auto mag = [](std::int64_t v) { return static_cast<std::uint64_t>(v < 0 ? -v : v); };
  Block b;
  if (m.is_arc()) {
    const auto plan = Circular<W>::validate(m.xs, m.ys, m.xe, m.ye, m.sense);
    b.arc = true;
    b.cw = m.sense == Sense::CW;
    b.q = static_cast<std::uint8_t>(plan.q_start);
    b.k = static_cast<std::uint8_t>(plan.crossings);
    b.xs = mag(m.xs);
    b.ys = mag(m.ys);
  } else {
    b.sxn = m.xe < 0;
    b.syn = m.ye < 0;
  }
  b.xe = mag(m.xe);
  b.ye = mag(m.ye);
  return b;
}

// One observed output pulse with the state after it.
struct Observed {
  Pulse pulse;
  State state;
  bool last = false;     // the pulse that ended its move
  std::uint64_t cycle = 0;
};

template <class V, unsigned W>
class CoreHarness {
 public:
  static constexpr unsigned kWidth = W;

  explicit CoreHarness(std::string fst_path = "") : ctx_(std::make_unique<VerilatedContext>()) {
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
    top_->i_abort = 0;
    top_->i_cmd = 0;
    top_->i_push = 0;
    top_->eval();
    tick();
    tick();
    top_->i_rst = 0;
  }

  ~CoreHarness() {
    close_trace();
    top_->final();
  }
  CoreHarness(const CoreHarness&) = delete;
  CoreHarness& operator=(const CoreHarness&) = delete;

  V& top() { return *top_; }
  std::uint64_t cycle() const { return cycle_; }

  // One clock: inputs set by the caller are sampled at the rising edge.
  void tick() {
    top_->i_clk = 0;
    top_->eval();
    dump();
    top_->i_clk = 1;
    top_->eval();
    dump();
    ++cycle_;
  }

  void close_trace() {
    if (trace_) {
      dump();
      trace_->close();
      trace_.reset();
    }
  }

  void reset() {
    top_->i_rst = 1;
    top_->i_push = 0;
    top_->i_cmd = 0;
    tick();
    top_->i_rst = 0;
  }

  // Presents a block for one clock; returns false if the queue was full
  // (the block is then not taken).
  bool push(const Block& b) {
    const bool full = top_->o_full;
    top_->i_push = 1;
    top_->i_arc = b.arc;
    top_->i_cw = b.cw;
    top_->i_sxn = b.sxn;
    top_->i_syn = b.syn;
    top_->i_q = b.q;
    top_->i_k = b.k;
    top_->i_xs = b.xs;
    top_->i_ys = b.ys;
    top_->i_xe = b.xe;
    top_->i_ye = b.ye;
    tick();
    top_->i_push = 0;
    return !full;
  }

  // The output pulse of the current clock (registered in the DUT), if any.
  std::optional<Observed> pulse() const {
    if (!top_->o_pulse) return std::nullopt;
    Observed o;
    o.pulse.axis = top_->o_pulse_y ? Axis::Y : Axis::X;
    o.pulse.sign = top_->o_pulse_neg ? -1 : +1;
    o.state = state();
    o.last = top_->o_pulse_last;
    o.cycle = cycle_;
    return o;
  }

  // The observable state as the model reports it (pulse count excluded:
  // the caller counts pulses).
  State state() const {
    State s;
    const auto xm = static_cast<std::int64_t>(top_->o_xmag);
    const auto ym = static_cast<std::int64_t>(top_->o_ymag);
    s.x = top_->o_xneg ? -xm : xm;
    s.y = top_->o_yneg ? -ym : ym;
    const std::uint64_t draw = static_cast<std::uint64_t>(top_->o_d) & ((std::uint64_t{1} << (W + 2)) - 1);
    s.d = (draw & (std::uint64_t{1} << (W + 1))) ? static_cast<std::int64_t>(draw) - (std::int64_t{1} << (W + 2))
                                                   : static_cast<std::int64_t>(draw);
    s.quadrant = top_->o_arc ? top_->o_q : 0;
    s.crossings_left = top_->o_arc ? top_->o_k : 0;
    s.done = !top_->o_busy;
    return s;
  }

  // Waits (command low) until every queued block has been loaded.
  void drain_queue(unsigned max_cycles = 16) {
    top_->i_cmd = 0;
    for (unsigned i = 0; i < max_cycles && top_->o_level != 0; ++i) tick();
    if (top_->o_level != 0) throw std::runtime_error("rtl: the queue did not drain");
  }

  // Runs one block to its end with the command held high: returns the
  // initial state and every pulse. Stops after `max_pulses` (a runaway).
  RunResult run(const Block& b, std::uint64_t max_pulses) {
    RunResult r;
    if (!push(b)) throw std::runtime_error("rtl: queue full");
    drain_queue();
    r.initial_state = state();
    top_->i_cmd = 1;
    std::uint64_t n = 0;
    bool last = r.initial_state.done;
    while (!last && n < max_pulses) {
      tick();
      if (auto o = pulse()) {
        o->state.pulses = ++n;
        r.steps.push_back({o->pulse, o->state});
        last = o->last;
      } else if (!top_->o_busy) {
        break;  // done without a last pulse: the checker reports it
      }
    }
    top_->i_cmd = 0;
    tick();
    r.final_state = state();
    r.final_state.pulses = n;
    return r;
  }

 private:
  void dump() {
    if (trace_) trace_->dump(static_cast<std::uint64_t>(ctx_->time()));
    ctx_->timeInc(1);
  }

  std::unique_ptr<VerilatedContext> ctx_;
  std::unique_ptr<V> top_;
  std::unique_ptr<VerilatedFstC> trace_;
  std::uint64_t cycle_ = 0;
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
