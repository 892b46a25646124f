// Pulse-by-pulse, state-by-state comparison of a Verilated interp3_core
// (through Interp3Harness) with the golden model Linear3<W>.
//
// After the load both initial states must agree; then in every clock the
// command input is driven (high, or low in the clocks a gap pattern says)
// and the model steps once per high command: the pulse of the clock (none,
// or the axis and sign) and the state after it must be identical. Once the
// model is done, a few more command clocks must give no pulse and leave the
// state alone. The first difference stops the run; the report shows it
// with both sides' values and the pulses around it.
#pragma once

#include <cstdint>
#include <cstdio>
#include <deque>
#include <functional>
#include <optional>
#include <string>

#include "interp/linear3.hpp"
#include "interp3_harness.hpp"

namespace contour::rtl3 {

struct Move3 {
  std::int64_t xe = 0, ye = 0, ze = 0;
};

inline std::string describe(const Move3& m) {
  return "(" + std::to_string(m.xe) + ", " + std::to_string(m.ye) + ", " + std::to_string(m.ze) + ")";
}

inline std::string show(const std::optional<Pulse>& p) { return p ? to_string(*p) : std::string("--"); }

inline std::string show(const State3& s) {
  char b[200];
  std::snprintf(b, sizeof b, "x=%lld y=%lld z=%lld Exy=%lld Exz=%lld Eyz=%lld n=%llu done=%d",
                static_cast<long long>(s.x), static_cast<long long>(s.y), static_cast<long long>(s.z),
                static_cast<long long>(s.dxy), static_cast<long long>(s.dxz), static_cast<long long>(s.dyz),
                static_cast<unsigned long long>(s.pulses), s.done ? 1 : 0);
  return b;
}

// One clock of the comparison.
struct Clock3 {
  std::uint64_t clock = 0;  // command clocks since the load (0: the load)
  bool cmd = false;
  std::optional<Pulse> model, rtl;
  unsigned rtl_strobes = 0;  // step strobes high at once (more than 1: a bug)
  State3 ms, rs;
  bool same() const { return model == rtl && rtl_strobes == (rtl ? 1u : 0u) && ms == rs; }
};

struct Compare3Options {
  // Command input per clock after the load (clock numbers from 1); empty:
  // always high.
  std::function<bool(std::uint64_t)> cmd;
  // Stop after this many model pulses (0: run the move to its end), for
  // long moves checked on a prefix; the next load abandons the move.
  std::uint64_t max_pulses = 0;
  unsigned context_before = 4;
  unsigned context_after = 2;
};

// Runs `rtl_move` on the core and `model_move` on Linear3<W> (the same
// move, except when a test wants to see a difference reported). Returns an
// empty string when identical, else the report.
template <unsigned W, class H>
std::string compare_move(H& h, const Move3& rtl_move, const Move3& model_move, const Compare3Options& o = {}) {
  Linear3<W> model(model_move.xe, model_move.ye, model_move.ze);
  h.load(rtl_move.xe, rtl_move.ye, rtl_move.ze);
  std::deque<Clock3> window;
  std::optional<Clock3> first;
  unsigned after = 0;
  auto record = [&](Clock3 c) {
    if (first) {
      window.push_back(c);
      ++after;
      return;
    }
    if (!c.same()) first = c;
    window.push_back(std::move(c));
    while (!first && window.size() > o.context_before) window.pop_front();
  };
  Clock3 start;
  start.ms = model.state();
  start.rs = h.state();
  record(start);
  std::uint64_t clock = 0, idle_after_done = 0;
  while (!(first && after >= o.context_after)) {
    if (model.done() && ++idle_after_done > 3) break;  // 3 command clocks after the end
    if (o.max_pulses && model.state().pulses >= o.max_pulses) break;
    ++clock;
    const bool cmd = o.cmd ? o.cmd(clock) : true;
    Clock3 c;
    c.clock = clock;
    c.cmd = cmd;
    if (cmd) c.model = model.step();
    c.rtl = h.step(cmd);
    c.rtl_strobes = h.strobes();
    c.ms = model.state();
    c.rs = h.state();
    record(std::move(c));
    if (clock > 8 * (model.total_pulses() + 8) && !o.max_pulses) break;  // runaway guard
  }
  if (!first) return "";
  h.close_trace();
  std::string r = "move " + describe(rtl_move) + " at W = " + std::to_string(W);
  if (rtl_move.xe != model_move.xe || rtl_move.ye != model_move.ye || rtl_move.ze != model_move.ze)
    r += " (model: " + describe(model_move) + ")";
  r += ": first difference at command clock " + std::to_string(first->clock) + ", model pulse " +
       std::to_string(first->ms.pulses) + "\n";
  r += "  clock cmd  model pulse, state after it / rtl pulse, state after it\n";
  for (const auto& c : window) {
    const bool here = c.clock == first->clock;
    char head[40];
    std::snprintf(head, sizeof head, "%s %5llu  %d ", here ? ">" : " ", static_cast<unsigned long long>(c.clock),
                  c.cmd ? 1 : 0);
    r += std::string(head) + " model " + show(c.model) + " " + show(c.ms) + "\n";
    const std::string rp = c.rtl_strobes > 1 ? std::to_string(c.rtl_strobes) + " strobes" : show(c.rtl);
    r += std::string(11, ' ') + (c.same() ? "   rtl " : "!  rtl ") + rp + " " + show(c.rs) + "\n";
  }
  return r;
}

template <unsigned W, class H>
std::string compare_move(H& h, const Move3& m, const Compare3Options& o = {}) {
  return compare_move<W>(h, m, m, o);
}

}  // namespace contour::rtl3
