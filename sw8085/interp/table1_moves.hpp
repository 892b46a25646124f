// The standard set of `contour table1` (paper A's Table 1 measured on our
// 8085 program, docs/sw8085.md): 9 lines and 8 arcs, full circles and
// 24-bit ones among them. Shared by the CLI and sw8085_routines.
#pragma once

#include <vector>

#include "interp/engine.hpp"

namespace contour::sw8085 {

std::vector<Move> table1_lines();
std::vector<Move> table1_arcs();

}  // namespace contour::sw8085
