// G-code reader: the RS274/NGC subset that paper B's planner runs.
//
// Grammar (case-insensitive; blanks and tabs may stand between any two
// tokens, including between a letter and its number):
//
//   program := line*                       lines end at '\n' (a '\r' before it is ignored)
//   line    := '%' | [ 'N' uint ] word* [ ';' any* ]
//   word    := letter real | comment       comments may stand between words
//   comment := '(' any-but-parens-and-newline* ')'
//   letter  := G | X | Y | Z | I | J | K | R | F
//   real    := [ '+' | '-' ] ( digits [ '.' digits? ] | '.' digits )
//
// Words:
//   G0 G1 G2 G3       motion (modal): rapid, line, arc CW, arc CCW
//   G17 G18 G19       arc plane XY / ZX / YZ (modal; normal axis Z / Y / X)
//   G20 G21           inches / millimetres (modal)
//   G90 G91           absolute / incremental X Y Z (modal); I J K are
//                     always offsets from the start point
//   X Y Z             end point; I J K arc centre offsets; R arc radius
//                     (negative: the arc of more than 180 degrees); F feed
//                     in units per minute (modal)
//
// Arcs (G2/G3):
//   - with the active plane's two offsets (G17: I J; G18: I K; G19: J K),
//     or R, the arc lies in the plane; it is a helix if the normal axis moves;
//     an end equal to the start in the plane is a full circle (offsets only);
//   - with all three of I J K, when the end or the centre is off the plane
//     through the start, it is a 3D arc as in paper B: start, end and centre
//     in space. Its sense (G2 CW, G3 CCW) is judged looking down the active
//     plane's normal axis, so its plane must not contain that axis;
//   - the radii to the start and to the end must agree by LinuxCNC's rule:
//     error if |r2 - r1| > 100 * tol, or if |r2 - r1| > tol and
//     |r2 - r1| > 0.1 % of max(r1, r2); tol = 0.0283 mm (G21) or 0.00283 in
//     (G20). The message gives both radii.
//
// Every error is a gcode::Error naming the line, the column (1-based) and the
// problem; nothing is skipped or clamped silently.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "gcode/vec3.hpp"

namespace contour::gcode {

enum class Motion : std::uint8_t { Rapid, Line, ArcCW, ArcCCW };
enum class Plane : std::uint8_t { XY, ZX, YZ };  // G17, G18, G19

// The plane's normal axis index (0 X, 1 Y, 2 Z) and its two in-plane axes,
// in the order that makes (first, second, normal) right-handed.
int normal_axis(Plane p);
int first_axis(Plane p);
int second_axis(Plane p);
const char* plane_name(Plane p);  // "G17" ...

// One motion block, in millimetres, absolute.
struct Block {
  Motion motion = Motion::Rapid;
  Vec3 start, end;
  double feed_mm_s = 0;  // programmed feed (G1/G2/G3); rapid: 0 (the machine's rapid)
  // Arcs only.
  Plane plane = Plane::XY;
  Vec3 centre;             // as programmed (start + I J K, or from R)
  bool arc3d = false;      // paper B's 3D arc (I J K all given, off the plane)
  bool full_circle = false;
  double r_start = 0, r_end = 0;  // radii (in-plane for plane arcs), mm
  // Source position of the block: its line and the column of its first word.
  int line = 0;
  int column = 0;

  bool is_arc() const { return motion == Motion::ArcCW || motion == Motion::ArcCCW; }
};

class Error : public std::runtime_error {
 public:
  Error(int line, int column, const std::string& problem);
  int line() const { return line_; }
  int column() const { return column_; }
  const std::string& problem() const { return problem_; }

 private:
  int line_, column_;
  std::string problem_;
};

struct Options {
  Vec3 start;  // machine position before the first block, mm
};

// Reads a whole program. Throws Error on the first problem.
std::vector<Block> parse(std::string_view text, const Options& options = {});

// LinuxCNC's arc radius tolerance in the program's units.
constexpr double kRadiusTolMm = 0.0283;
constexpr double kRadiusTolIn = 0.00283;
// LinuxCNC's tolerance for an R arc whose |R| is shorter than half its chord
// (0.00005 in = 0.00127 mm, measured against rs274: half chord 10 mm, R
// 9.99875 is taken, R 9.9987 refused).
constexpr double kArcRTolIn = 0.00005;

// Empty when r1 and r2 (program units) agree by LinuxCNC's rule, else the
// problem, giving both radii, e.g. "radius to end of arc differs from radius
// to start: r1=50.0000 r2=50.1000 (difference 0.1000 > ...)".
std::string check_radii(double r1, double r2, bool inches);

}  // namespace contour::gcode
