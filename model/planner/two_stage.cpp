#include "planner/two_stage.hpp"

#include <cmath>
#include <stdexcept>

#include "interp/linear3.hpp"

namespace contour::planner {

std::vector<StepChord> chords_in_steps(const std::vector<Sample>& samples, double steps_per_mm) {
  if (!(steps_per_mm > 0) || !std::isfinite(steps_per_mm))
    throw std::invalid_argument("steps per mm must be > 0 (got " + std::to_string(steps_per_mm) + ")");
  std::vector<StepChord> out;
  if (samples.empty()) return out;
  auto steps = [&](double mm) {
    const double v = std::nearbyint(mm * steps_per_mm);
    if (std::fabs(v) > 9e15) throw std::invalid_argument("position " + std::to_string(mm) + " mm is out of range in steps");
    return static_cast<std::int64_t>(v);
  };
  std::int64_t px = steps(samples[0].p.x), py = steps(samples[0].p.y), pz = steps(samples[0].p.z);
  out.reserve(samples.size() - 1);
  for (std::size_t n = 1; n < samples.size(); ++n) {
    const std::int64_t x = steps(samples[n].p.x), y = steps(samples[n].p.y), z = steps(samples[n].p.z);
    out.push_back({x - px, y - py, z - pz});
    px = x, py = y, pz = z;
  }
  return out;
}

std::vector<TimedPulse> two_stage_model(const std::vector<StepChord>& chords, double cycle_s) {
  std::vector<TimedPulse> out;
  for (std::size_t n = 0; n < chords.size(); ++n) {
    const StepChord& c = chords[n];
    Linear3<24> l(c.dx, c.dy, c.dz);  // throws InputError beyond 2^24 - 1 steps per cycle
    const double t0 = static_cast<double>(n) * cycle_s;
    const double N = static_cast<double>(l.total_pulses());
    std::uint64_t j = 0;
    while (auto p = l.step()) {
      ++j;
      out.push_back({t0 + static_cast<double>(j) * cycle_s / N, *p});
    }
  }
  return out;
}

std::map<std::string, PulseStage>& pulse_stages() {
  static std::map<std::string, PulseStage> table{{"model", two_stage_model}};
  return table;
}

}  // namespace contour::planner
