#include "interp/types.hpp"

#include <sstream>

namespace contour {

std::string to_string(const Pulse& p) {
  std::string s = p.sign > 0 ? "+" : "-";
  s += p.axis == Axis::X ? 'X' : p.axis == Axis::Y ? 'Y' : 'Z';
  return s;
}

std::string to_string(const State& s) {
  std::ostringstream o;
  o << "x=" << s.x << " y=" << s.y << " D=" << s.d << " q=Q" << int(s.quadrant) + 1
    << " k=" << int(s.crossings) << " n=" << s.pulses << (s.done ? " done" : "");
  return o.str();
}

void throw_overflow(const char* what, const State& s) {
  throw OverflowError(std::string(what) + " overflows its width: " + to_string(s));
}

void check_coord(std::int64_t v, const char* name, unsigned width) {
  const std::int64_t max = max_magnitude(width);
  if (v > max || v < -max)
    throw InputError(std::string(name) + " = " + std::to_string(v) + " is out of range: |" + name +
                     "| must be <= 2^" + std::to_string(width) + " - 1 = " + std::to_string(max));
}

}  // namespace contour
