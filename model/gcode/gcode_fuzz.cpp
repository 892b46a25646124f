// libFuzzer target: any byte string either parses or throws gcode::Error;
// nothing else (no crash, no other exception, no non-finite coordinate).
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "gcode/gcode.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    for (const auto& b : contour::gcode::parse(text)) {
      for (int a = 0; a < 3; ++a)
        if (!std::isfinite(b.start[a]) || !std::isfinite(b.end[a]) || !std::isfinite(b.centre[a])) std::abort();
      if (b.is_arc() && !(b.r_start > 0)) std::abort();
    }
  } catch (const contour::gcode::Error& e) {
    if (e.line() < 1 || e.column() < 1) std::abort();
  }
  return 0;
}
