#include "interp/engine.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace contour {

std::string describe(const Move& m) {
  if (!m.is_arc()) return "line " + std::to_string(m.xe) + " " + std::to_string(m.ye);
  return "arc " + std::to_string(m.xs) + " " + std::to_string(m.ys) + " " + std::to_string(m.xe) + " " +
         std::to_string(m.ye) + (m.sense == Sense::CW ? " cw" : " ccw");
}

double deviation(const Move& m, std::int64_t x, std::int64_t y) {
  if (m.is_arc()) {
    const double r = std::sqrt(static_cast<double>(m.xs * m.xs + m.ys * m.ys));
    return std::fabs(std::hypot(static_cast<double>(x), static_cast<double>(y)) - r);
  }
  const double len = std::hypot(static_cast<double>(m.xe), static_cast<double>(m.ye));
  if (len == 0) return std::hypot(static_cast<double>(x), static_cast<double>(y));
  // |Xe*y - Ye*x| / |(Xe, Ye)|, in long double: the products reach 2^48.
  const long double cross = static_cast<long double>(m.xe) * y - static_cast<long double>(m.ye) * x;
  return static_cast<double>(std::fabs(cross) / len);
}

double max_deviation(const Move& m, const RunResult& r) {
  double worst = deviation(m, r.initial_state.x, r.initial_state.y);
  for (const auto& s : r.steps) worst = std::max(worst, deviation(m, s.state.x, s.state.y));
  return worst;
}

Move walked_arc(std::int64_t xs, std::int64_t ys, Sense s, int n) {
  Circular<24> walk(xs, ys, xs, ys, s);
  for (int i = 0; i < n; ++i) walk.step();
  auto near = [](const State& st) { return std::llabs(st.d) <= std::llabs(st.x) + std::llabs(st.y); };
  while (!near(walk.state())) walk.step();
  return Move::arc(xs, ys, walk.state().x, walk.state().y, s);
}

}  // namespace contour
