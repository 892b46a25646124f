// libFuzzer target: any byte string either parses or throws gcode::Error;
// the whole language: words, parameters, expressions, O-word control flow,
// canned cycles (seeds in corpus/), with small runaway bounds;
// nothing else (no crash, no other exception, no non-finite coordinate).
// When built with the planner (CONTOUR_FUZZ_PLANNER), a parsed program of
// modest size is also planned, and the plan must be finite and respect its
// own caps and junction limits.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <stdexcept>
#include <string_view>

#include "gcode/gcode.hpp"
#ifdef CONTOUR_FUZZ_PLANNER
#include "planner/planner.hpp"
#endif

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  std::vector<contour::gcode::Block> blocks;
  try {
    contour::gcode::Options o;
    o.tools = {{1, 10.0}, {2, -5.5}};  // so that G43 H1 / H2 are read
    o.max_lines_run = 20000;           // endless loops stop in milliseconds
    o.max_blocks = 5000;
    blocks = contour::gcode::parse(text, o);
  } catch (const contour::gcode::Error& e) {
    if (e.line() < 1 || e.column() < 1) std::abort();
    return 0;
  }
  bool modest = true;
  for (const auto& b : blocks) {
    for (int a = 0; a < 3; ++a) {
      if (!std::isfinite(b.start[a]) || !std::isfinite(b.end[a]) || !std::isfinite(b.centre[a])) std::abort();
      modest = modest && std::fabs(b.end[a]) < 1e4 && std::fabs(b.centre[a]) < 1e4;
    }
    if (b.is_arc() && !(b.r_start > 0)) std::abort();
    if (b.is_dwell()) {
      if (!(b.dwell_s >= 0) || !(b.start == b.end)) std::abort();
      modest = modest && b.dwell_s < 100;
      continue;
    }
    modest = modest && (b.motion == contour::gcode::Motion::Rapid || b.feed_mm_s > 1e-3);
  }
#ifdef CONTOUR_FUZZ_PLANNER
  if (!modest) return 0;
  try {
    const auto p = contour::planner::plan(blocks, contour::planner::Config{});
    for (const auto& s : p.segs) {
      if (s.geom.kind == contour::planner::Segment::Kind::Dwell) {
        if (!(s.duration >= 0) || s.v_start != 0 || s.v_end != 0) std::abort();
        continue;
      }
      if (!std::isfinite(s.duration) || s.duration < 0 || !(s.geom.length > 0)) std::abort();
      if (s.v_cruise > s.v_cap * (1 + 1e-9) || s.v_start > s.v_cruise * (1 + 1e-9) + 1e-12) std::abort();
      if (!(s.a_t > 0) || !std::isfinite(s.a_t)) std::abort();
    }
    if (!std::isfinite(p.total_time)) std::abort();
  } catch (const std::invalid_argument&) {
    // A block the planner refuses names itself; that is an answer, not a crash.
  }
#else
  (void)modest;
#endif
  return 0;
}
