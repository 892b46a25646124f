// One T-state of a Verilated 8085 model (cpu8085, board8085) with one
// eval() instead of two (docs/cpu8085.md "Speed").
//
// In these designs every flop is clocked by the rising edge of i_clk and
// no logic follows an input combinationally (no input-driven region): an
// eval() with the clock low runs nothing but Verilator's bookkeeping. What
// it does is store i_clk = 0, the value the next eval() compares with to
// see a rising edge (Verilator 5.006: the root's __Vtrigrprev__TOP__i_clk).
// OneEvalClock stores that 0 itself and evaluates the rising edge only.
// It falls back to the harness's two evals (clock_low, clock_high) when a
// waveform is written (it shows both edges) and when the model has no such
// member (another Verilator release): the compiler picks the path.
//
// A machine may also give it its model's rising-edge region itself
// (`posedge`, Verilator 5.006's _eval_nba, with _eval_ico before it on a
// model that has one, each under its trigger): the eval() of such a model
// runs those two and nothing else on a rising edge, but spends about 130
// x86 instructions in its trigger loops, eval_step and endOfEval around
// them (docs/cpu8085.md "Speed"). The machine declares those functions
// only under VERILATOR_VERSION_INTEGER 5006000 (another release: eval()).
// The first rising edge still goes through eval() (the model's initial
// evaluation, if the harness has not done it).
#pragma once

#include <type_traits>
#include <utility>

#include "harness.hpp"

namespace cpu8085 {

// Whether a Verilated root class stores the clock's previous value where
// OneEvalClock expects it.
template <class Root, class = void>
struct HasClockTrigger : std::false_type {};
template <class Root>
struct HasClockTrigger<Root, std::void_t<decltype(std::declval<Root&>().__Vtrigrprev__TOP__i_clk)>>
    : std::true_type {};

template <class V>
class OneEvalClock {
 public:
  using Root = std::remove_pointer_t<decltype(std::declval<V&>().rootp)>;
  // The root's header must be included (an incomplete root would silently
  // take the two-eval path).
  static_assert(sizeof(Root) > 0, "include the model's V*___024root.h");
  static constexpr bool kSupported = HasClockTrigger<Root>::value;

  // The model's rising-edge region, called instead of eval() (see above).
  using Posedge = void (*)(Root*);

  // `waveform`: a waveform is being written (the two-eval path).
  OneEvalClock(contour::tb::Harness<V>& h, bool waveform, Posedge posedge = nullptr)
      : h_(h), one_eval_(kSupported && !waveform), posedge_(posedge) {}

  bool one_eval() const { return one_eval_; }
  // The rising edge is the machine's posedge function alone (one eval
  // done): a machine may then run its own loop, calling it directly with
  // i_clk held at 1 (posedge_loop_begin()).
  bool direct() const { return one_eval_ && posedge_ != nullptr && primed_; }
  void posedge_loop_begin() { h_.top().i_clk = 1; }

  // Before the bus is served: the clock low (nothing to do on one eval).
  void low() {
    if (!one_eval_) h_.clock_low();
  }
  // The rising edge that ends the T-state.
  void high() {
    if constexpr (kSupported) {
      if (one_eval_) {
        V& top = h_.top();
        top.i_clk = 1;
        if (posedge_ != nullptr && primed_) {
          posedge_(top.rootp);
          return;
        }
        top.rootp->__Vtrigrprev__TOP__i_clk = 0;
        top.eval();
        primed_ = true;
        return;
      }
    }
    h_.clock_high();
  }

 private:
  contour::tb::Harness<V>& h_;
  bool one_eval_;
  Posedge posedge_;
  bool primed_ = false;  // one eval() done
};

}  // namespace cpu8085
