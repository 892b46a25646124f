// Pulse-by-pulse and state-by-state comparison of two runs of one move.
#pragma once

#include <deque>
#include <optional>
#include <sstream>
#include <string>

#include "core_harness.hpp"
#include "interp/engine.hpp"

namespace contour::tb {

// Nothing if the runs agree on the initial state, every pulse, the state
// after every pulse and the final state; otherwise a report naming the
// first differing pulse with both sides' values and a few pulses of
// context.
std::optional<std::string> compare_runs(const Move& m, const RunResult& model, const RunResult& rtl);

// Lock-step comparison of a Verilated core (harness `h`) with a model
// interpolator (Linear<W> or Circular<W>, freshly built for `m`), the
// command held high, at most `limit` pulses. Leaves the core idle.
template <class H, class Interp>
std::optional<std::string> lockstep(H& h, const Move& m, const rtl::Block& b, Interp& model,
                                    std::uint64_t limit) {
  struct Pair {
    std::uint64_t n;
    std::optional<Pulse> mp;
    State ms;
    std::optional<rtl::Observed> rp;
  };
  std::deque<Pair> window;  // the last few pulses, for context
  auto report = [&](const std::string& what, std::uint64_t at, int after) {
    // A few pulses after the first difference, then the context.
    for (int i = 0; i < after; ++i) {
      Pair p{at + 1 + std::uint64_t(i), model.step(), model.state(), std::nullopt};
      h.tick();
      p.rp = h.pulse();
      if (p.rp) p.rp->state.pulses = p.n;
      window.push_back(p);
    }
    std::ostringstream o;
    o << describe(m) << ": " << what << " at pulse " << at << "\n";
    for (const Pair& p : window) {
      o << (p.n == at ? "> " : "  ") << "#" << p.n << "\n      model: "
        << (p.mp ? to_string(*p.mp) + "  " + to_string(p.ms) : std::string("(no pulse)"))
        << "\n      rtl:   "
        << (p.rp ? to_string(p.rp->pulse) + "  " + to_string(p.rp->state) : std::string("(no pulse)")) << "\n";
    }
    h.close_trace();
    h.reset();
    return o.str();
  };
  if (!h.push(b)) return describe(m) + ": queue full";
  h.drain_queue();
  State got0 = h.state();
  if (!(got0 == model.state())) {
    h.close_trace();
    return describe(m) + ": initial state differs\n  model: " + to_string(model.state()) +
           "\n  rtl:   " + to_string(got0);
  }
  h.top().i_cmd = 1;
  std::uint64_t n = 0;
  while (!model.done() && n < limit) {
    Pair p{++n, model.step(), model.state(), std::nullopt};
    h.tick();
    p.rp = h.pulse();
    if (p.rp) p.rp->state.pulses = n;
    window.push_back(p);
    if (window.size() > 4) window.pop_front();
    const bool same = p.rp && p.mp && p.rp->pulse == *p.mp && p.rp->state == p.ms &&
                      p.rp->last == model.done();
    if (!same) return report("first difference", n, 2);
  }
  h.top().i_cmd = 0;
  h.tick();
  if (model.done()) {
    // Nothing more may come out, and the core must say done.
    h.top().i_cmd = 1;
    h.tick();
    h.tick();
    h.top().i_cmd = 0;
    if (h.pulse() || h.top().o_busy) return report("pulse or busy after the end", n + 1, 0);
  } else {
    h.reset();  // a cut run
  }
  return std::nullopt;
}

}  // namespace contour::tb
