// G-code reader: RS274/NGC as LinuxCNC 2.9 reads it (its documentation and
// its `rs274` program are the reference), the part that real milling
// programs use; what it does not take it refuses with a one-line Error.
//
// Lexical (case-insensitive; blanks and tabs may stand between any two
// tokens, including between a letter and its number; lines end at '\n',
// any '\r' before it is ignored, so CR LF and CR CR LF both read):
//   line    := '%' | [ '/' ] [ 'N' uint ] word* [ ';' any* ]
//   word    := letter real | comment       comments may stand between words
//   comment := '(' any-but-parens-and-newline* ')'
//   real    := [ '+' | '-' ] ( digits [ '.' digits? ] | '.' digits )
//   '%' lines: when the first non-blank line is '%', the program ends at the
//   next '%' line; otherwise a '%' line is nothing. A line starting with '/'
//   is skipped (block delete on, as `rs274 -b`; Options::block_delete).
//
// Words (units: G20 inch, G21 mm; every position is kept in machine mm):
//   G0 G1 G2 G3 G80   motion: rapid, line, arc CW, arc CCW; G80: none
//   G4 P              dwell P seconds (the machine comes to rest and waits)
//   G10 L2 P X Y Z    work offset P (1..9 = G54..G59.3, 0 = the active one)
//   G10 L20 P X Y Z   work offset P such that the current point reads X Y Z
//   G17 G18 G19       arc plane XY / ZX / YZ (normal axis Z / Y / X)
//   G20 G21           inches / millimetres
//   G28 G30 [X Y Z]   rapid (through X Y Z if given, then) to the stored
//                     position of those axes (all three if none given);
//                     zero until G28.1 / G30.1 store the current point
//   G40               cutter compensation off (G41 G42 are refused)
//   G43 [H] G49       tool length offset of tool H from the tool table
//                     (Options::tools; without H the loaded tool), off
//   G53               this line's G0/G1 end point in machine coordinates
//   G54..G59 G59.1..G59.3  work coordinate system 1..9
//   G61 G61.1 G64 [P Q]  exact stop / exact path / blending within P
//   G90 G91           absolute / incremental X Y Z
//   G90.1 G91.1       arc centres I J K absolute / relative to the start
//   G94               feed per minute (G93 inverse time and G95 refused)
//   G73 G81 G82 G83 G85 G89  canned cycles (G17, absolute mode): X Y the
//                     hole, R the retract plane, Z the bottom, Q the peck,
//                     P the dwell (R Z P Q sticky), expanded into LinuxCNC's
//                     moves; G80 ends them
//   G98 G99           cycle retract to the initial level / to R
//   M0 M1             pause (the machine comes to rest)
//   M2 M30            program end: nothing after it is read
//   M3 M4 M5 S        spindle CW / CCW / stop (a stop), speed
//   M6 T              tool change (a stop) / tool select
//   M7 M8 M9          mist / flood / coolant off
//   X Y Z I J K R F   end point, arc centre, arc radius (negative: more than
//                     180 degrees), feed in units per minute (modal)
// Parameters and expressions (words.hpp): #1..#5399, #<name>, '[...]';
// O-words (program.cpp): sub/endsub/call/return, if/elseif/else/endif,
// while/endwhile, do/while, repeat/endrepeat, break, continue; runaway
// programs stop at Options::max_lines_run lines or max_blocks moves.
// Non-motion words are kept as Events in the program, in LinuxCNC's order
// of execution within a line: F, S, T, M6, M3-M5, M7-M9, G4, plane, units,
// G40, G43/G49, G54.., G61/G64, G90/G91, G90.1/G91.1, G98/G99, G10 G28 G30
// G53, motion, M0 M1 M2 M30. So F is read in the units before the line's
// G20/G21 (as LinuxCNC), and the feed keeps its speed across a change of
// units.
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
//     (G20). The message gives both radii;
//   - R arcs by LinuxCNC's rule: refused when |R| is shorter than half the
//     chord by more than 0.00005 in (0.00127 mm); otherwise, when |R| is at
//     most half the chord, the half circle on the chord.
//
// Every error is a gcode::Error naming the line, the column (1-based) and the
// problem; nothing is skipped or clamped silently.
#pragma once

#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "gcode/vec3.hpp"

namespace contour::gcode {

enum class Motion : std::uint8_t { Rapid, Line, ArcCW, ArcCCW, Dwell };
// Path control (G61, G61.1: exact stop at the end of the block; G64: blend).
enum class PathMode : std::uint8_t { Blend, ExactStop };
enum class Plane : std::uint8_t { XY, ZX, YZ };  // G17, G18, G19

// The plane's normal axis index (0 X, 1 Y, 2 Z) and its two in-plane axes,
// in the order that makes (first, second, normal) right-handed.
int normal_axis(Plane p);
int first_axis(Plane p);
int second_axis(Plane p);
const char* plane_name(Plane p);  // "G17" ...

// One motion block, in machine millimetres, absolute; or a dwell (the
// machine at rest at `start` for dwell_s; dwell_s 0: a stop, from M0 M1 M3
// M4 M5 M6).
struct Block {
  Motion motion = Motion::Rapid;
  Vec3 start, end;
  double feed_mm_s = 0;  // programmed feed (G1/G2/G3); rapid: 0 (the machine's rapid)
  double dwell_s = 0;    // Dwell only
  PathMode path = PathMode::Blend;
  double blend_tol_mm = -1;  // G64 P, mm; < 0: no P given (the planner's default)
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
  bool is_dwell() const { return motion == Motion::Dwell; }
};

// A non-motion word as executed, e.g. "M3", "S12000", "T2", "M6", "G43 H2",
// "G55", "G4 P0.5", "M30"; it happens before blocks[before].
struct Event {
  std::string code;
  int line = 0, column = 0;
  std::size_t before = 0;
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

// A tool table entry: tool number -> its length (Z offset), mm.
using ToolTable = std::map<int, double>;

struct Options {
  Vec3 start;  // machine position before the first block, mm
  ToolTable tools;
  bool block_delete = true;  // skip lines that start with '/'
  // Bounds against runaway programs (O-word loops, recursion): lines run
  // and moves made; beyond either the program stops with an Error.
  std::size_t max_lines_run = 10'000'000;
  std::size_t max_blocks = 2'000'000;
};

struct Program {
  std::vector<Block> blocks;
  std::vector<Event> events;
  bool ended = false;  // by M2 or M30 (or a closing '%')
};

// Reads a whole program. Throws Error on the first problem.
Program read(std::string_view text, const Options& options = {});
// The motion blocks (and dwells) of read(text, options).
std::vector<Block> parse(std::string_view text, const Options& options = {});

// Reads a tool table in LinuxCNC's format: one tool a line,
// 'T<n> P<pocket> [X Y Z A B C U V W D I J Q <value>] [; comment]'; only T
// and Z are used (Z: the tool length in mm, the machine's units). Errors
// name the line and column (Error).
ToolTable read_tool_table(std::string_view text);

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
