#include "interp3_stage.hpp"

#include <cstdint>
#include <stdexcept>
#include <string>

#include "Vinterp3_w24.h"
#include "interp3_harness.hpp"

namespace contour::rtl3 {

std::vector<TimedStep> run_chords(const std::vector<Chord>& chords, double cycle_s) {
  Interp3Harness<Vinterp3_w24, 24> h;
  std::vector<TimedStep> out;
  auto mag = [](std::int64_t v) { return static_cast<std::uint64_t>(v < 0 ? -v : v); };
  for (std::size_t n = 0; n < chords.size(); ++n) {
    const Chord& c = chords[n];
    h.load(c.dx, c.dy, c.dz);  // throws InputError beyond 2^24 - 1 steps
    const std::uint64_t total = mag(c.dx) + mag(c.dy) + mag(c.dz);
    const double t0 = static_cast<double>(n) * cycle_s;
    const double N = static_cast<double>(total);
    auto where = [&] {
      return "chord " + std::to_string(n) + " (" + std::to_string(c.dx) + ", " + std::to_string(c.dy) + ", " +
             std::to_string(c.dz) + ")";
    };
    // One command clock per pulse: each must give exactly one pulse.
    for (std::uint64_t j = 1; j <= total; ++j) {
      const auto p = h.step(true);
      if (!p)
        throw std::runtime_error("rtl: " + where() + ": command clock " + std::to_string(j) + " of " +
                                 std::to_string(total) + " gave " + std::to_string(h.strobes()) + " pulses");
      out.push_back({t0 + static_cast<double>(j) * cycle_s / N, *p});
    }
    if (!h.done()) throw std::runtime_error("rtl: " + where() + ": not done after " + std::to_string(total) + " pulses");
  }
  return out;
}

}  // namespace contour::rtl3
