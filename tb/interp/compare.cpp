#include "compare.hpp"

#include <algorithm>
#include <sstream>

namespace contour::tb {
namespace {

std::string step_text(const std::vector<StepRecord>& v, std::size_t i) {
  if (i >= v.size()) return "(none)";
  return to_string(v[i].pulse) + "  " + to_string(v[i].state);
}

}  // namespace

std::optional<std::string> compare_runs(const Move& m, const RunResult& model, const RunResult& rtl) {
  std::ostringstream o;
  if (!(model.initial_state == rtl.initial_state)) {
    o << describe(m) << ": initial state differs\n  model: " << to_string(model.initial_state)
      << "\n  rtl:   " << to_string(rtl.initial_state);
    return o.str();
  }
  const std::size_t n = std::max(model.steps.size(), rtl.steps.size());
  for (std::size_t i = 0; i < n; ++i) {
    const bool same = i < model.steps.size() && i < rtl.steps.size() &&
                      model.steps[i].pulse == rtl.steps[i].pulse && model.steps[i].state == rtl.steps[i].state;
    if (same) continue;
    o << describe(m) << ": first difference at pulse " << i + 1 << " (model " << model.steps.size()
      << " pulses, rtl " << rtl.steps.size() << ")\n";
    const std::size_t from = i >= 3 ? i - 3 : 0;
    for (std::size_t j = from; j < std::min(n, i + 3); ++j) {
      o << (j == i ? "> " : "  ") << "#" << j + 1 << "\n      model: " << step_text(model.steps, j)
        << "\n      rtl:   " << step_text(rtl.steps, j) << "\n";
    }
    return o.str();
  }
  if (!(model.final_state == rtl.final_state)) {
    o << describe(m) << ": final state differs\n  model: " << to_string(model.final_state)
      << "\n  rtl:   " << to_string(rtl.final_state);
    return o.str();
  }
  return std::nullopt;
}

}  // namespace contour::tb
