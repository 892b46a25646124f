// The geometry of one G2/G3 block from its words: plane arcs and helices
// (offsets or R), paper B's 3D arcs, and LinuxCNC's radius rules
// (gcode.hpp, "Arcs").
#pragma once

#include <array>
#include <optional>

#include "gcode/gcode.hpp"

namespace contour::gcode {

// The arc words of a line, converted to mm. off: the centre offset from the
// start (I J K, already relative even in G90.1); r: the R word.
struct ArcWords {
  std::array<std::optional<double>, 3> off;
  std::array<int, 3> off_column{};
  std::optional<double> r;
  int r_column = 0;
};

// Fills b.centre, r_start, r_end, arc3d, full_circle from the words, for a
// block whose motion, plane, start, end and column are set. `inches`: the
// program's units (for the tolerances and messages). Throws Error.
void make_arc(Block& b, const ArcWords& w, bool inches, int line);

}  // namespace contour::gcode
