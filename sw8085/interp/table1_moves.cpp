#include "sw8085/interp/table1_moves.hpp"

#include <cstdint>

#include "interp/engine.hpp"

namespace contour::sw8085 {

std::vector<Move> table1_lines() {
  return {Move::line(3000, 1234), Move::line(-2600, -2599), Move::line(1, 2000),   Move::line(-4000, 0),
          Move::line(0, -300),    Move::line(257, -65),     Move::line(12345, -6789), Move::line(65537, -3),
          Move::line(-7, 9)};
}

std::vector<Move> table1_arcs() {
  const std::int64_t big = (std::int64_t{1} << 24) - 1;
  return {Move::arc(100, 0, 100, 0, Sense::CCW),
          Move::arc(0, -100, 0, -100, Sense::CW),
          Move::arc(1000, 0, 0, 1000, Sense::CCW),
          Move::arc(-707, 707, 707, -707, Sense::CW),
          Move::arc(3, 4, -4, -3, Sense::CCW),
          walked_arc(big, 0, Sense::CCW, 3000),
          walked_arc(5, -16777200, Sense::CW, 3000),
          walked_arc(11863282, -11863282, Sense::CCW, 2000)};
}

}  // namespace contour::sw8085
