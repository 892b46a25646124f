// The interpreter of gcode.hpp: one line at a time, in LinuxCNC's order of
// execution, into motion blocks, dwells and events.
#include <array>
#include <memory>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>

#include "gcode/interpreter.hpp"

#include "gcode/arc.hpp"
#include "gcode/gcode.hpp"
#include "gcode/words.hpp"

namespace contour::gcode {

namespace {

std::string fmt(double v, int prec = 4) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", prec, v);
  return buf;
}

// G code number times ten (G59.1 -> 591), or -1 when it has more decimals.
int code10(double v) {
  const double t = std::round(v * 10);
  return std::fabs(v * 10 - t) < 1e-6 && t >= 0 && t < 10000 ? static_cast<int>(t) : -1;
}

std::string gname(int c10) { return "G" + std::to_string(c10 / 10) + (c10 % 10 ? "." + std::to_string(c10 % 10) : ""); }

// LinuxCNC's modal groups of the G codes this reader takes.
enum GroupId { kNonModal, kMotion, kPlane, kDistance, kArcDistance, kFeedMode, kUnits, kCutter, kToolLength,
               kRetract, kCoordSystem, kPathControl, kGroups };
const char* const kGroupNames[kGroups] = {"non-modal", "motion", "plane", "distance mode", "arc distance mode",
                                          "feed mode", "units", "cutter compensation", "tool length offset",
                                          "retract mode", "coordinate system", "path control"};

// The group of G code c10, or the reason it is refused.
int g_group(int c10, std::string& refused) {
  switch (c10) {
    case 0: case 10: case 20: case 30: case 800: return kMotion;
    case 730: case 810: case 820: case 830: case 850: case 890: return kMotion;  // canned cycles
    case 40: case 100: case 280: case 281: case 300: case 301: case 530: return kNonModal;
    case 170: case 180: case 190: return kPlane;
    case 200: case 210: return kUnits;
    case 400: return kCutter;
    case 430: case 490: return kToolLength;
    case 540: case 550: case 560: case 570: case 580: case 590: case 591: case 592: case 593: return kCoordSystem;
    case 610: case 611: case 640: return kPathControl;
    case 900: case 910: return kDistance;
    case 901: case 911: return kArcDistance;
    case 940: return kFeedMode;
    case 980: case 990: return kRetract;
    case 410: case 420: case 411: case 421: refused = "cutter radius compensation (G41/G42) is not supported"; break;
    case 930: refused = "inverse time feed (G93) is not supported: use G94 (units per minute)"; break;
    case 950: refused = "feed per revolution (G95) is not supported: use G94 (units per minute)"; break;
    case 740: case 760: case 840: case 860: case 870: case 880: case 331: case 330:
      refused = "cycle " + gname(c10) + " is not supported (G73 G81 G82 G83 G85 G89 are)";
      break;
    case 920: case 921: case 922: case 923: refused = "G92 offsets are not supported (use G10 L2/L20)"; break;
    default:
      refused = "unsupported G code " + gname(c10) + " (gcode.hpp lists the G codes this reader takes)";
  }
  return -1;
}

// M groups: 4 stop, 6 tool change, 7 spindle, 8 coolant.
int m_group(int m) {
  switch (m) {
    case 0: case 1: case 2: case 30: return 0;
    case 6: return 1;
    case 3: case 4: case 5: return 2;
    case 7: case 8: case 9: return 3;
    default: return -1;
  }
}

struct LineCodes {
  std::array<std::optional<Word>, kGroups> g;
  std::array<int, kGroups> g10{};  // the code (x10) of each group's word
  std::array<std::optional<Word>, 4> m;
  std::array<int, 4> mcode{};
};

struct State {
  std::optional<Motion> motion;
  Plane plane = Plane::XY;
  bool inches = false, incremental = false, arc_absolute = false;
  double feed_mm_s = 0;
  int cs = 0;                      // G54 .. G59.3 = 0 .. 8
  std::array<Vec3, 9> offsets{};   // work offsets, mm
  double tlo = 0;                  // tool length offset, mm (Z)
  int tool = 0, selected = 0;      // loaded tool, selected tool
  Vec3 g28, g30;                   // stored positions, machine mm
  PathMode path = PathMode::Blend;
  double blend_tol = -1;           // mm; < 0: no P
  int cycle = 0;                   // the canned cycle in effect (81 ...), 0: none
  bool retract_to_r = false;       // G99 (else G98: the Z before the cycle block)
  double cycle_r = 0, cycle_z = 0; // sticky R and Z, machine mm
  double cycle_q = 0, cycle_p = 0; // sticky Q (mm) and P (s)
  bool cycle_seen = false;         // a cycle block since the mode was entered
  std::optional<double> cycle_il;  // the initial level: Z when the series of cycles began
};

}  // namespace

class Interpreter {
 public:
  explicit Interpreter(const Options& o) : opt_(o), pos_(o.start) {}

  // Runs one line; false after M2/M30.
  bool line(std::string_view text, int lineno) {
    line_ = lineno;
    if (block_deleted(text)) return true;
    const LineWords w = read_words(text, lineno, &params_);
    for (const Assignment& a : w.assignments) {  // after the whole line is read
      if (a.number) params_.numbered[a.number] = a.value;
      else params_.named[a.name] = a.value;
    }
    const LineCodes c = classify(w);
    check_letters(w, c);
    settings_before_motion(w, c);
    motion_and_nonmodal(w, c);
    return stop_words(c);
  }

  Program take() { return std::move(prog_); }
  Params& params() { return params_; }
  std::size_t blocks() const { return prog_.blocks.size(); }

  // A '/' line is skipped unread when block delete is on (its words may
  // use parameters that are not set).
  bool block_deleted(std::string_view text) const {
    const auto first = text.find_first_not_of(" \t\r");
    return opt_.block_delete && first != std::string_view::npos && text[first] == '/';
  }

 private:
  [[noreturn]] void fail(int col, const std::string& problem) const { throw Error(line_, col, problem); }
  double unit() const { return st_.inches ? 25.4 : 1.0; }
  const char* units_name() const { return st_.inches ? "in" : "mm"; }

  void event(int col, const std::string& code) { prog_.events.push_back({code, line_, col, prog_.blocks.size()}); }

  // A dwell of t seconds (0: a stop), the machine at rest.
  void dwell(int col, double t) {
    Block b;
    b.motion = Motion::Dwell;
    b.start = b.end = b.centre = pos_;
    b.dwell_s = t;
    b.line = line_;
    b.column = col;
    b.path = PathMode::ExactStop;
    prog_.blocks.push_back(b);
  }

  LineCodes classify(const LineWords& w) const {
    LineCodes c;
    for (const Word& g : w.g) {
      const int c10 = code10(g.value);
      std::string refused;
      const int grp = c10 < 0 ? -1 : g_group(c10, refused);
      if (grp < 0) fail(g.column, c10 < 0 ? "unsupported G code G" + fmt(g.value, 4) : refused);
      if (c.g[grp])
        fail(g.column, gname(c10) + " and " + gname(c.g10[grp]) + " in one line are both " + kGroupNames[grp] +
                           " words");
      c.g[grp] = g;
      c.g10[grp] = c10;
    }
    for (const Word& m : w.m) {
      const int code = m.value == std::floor(m.value) && m.value >= 0 && m.value < 1000 ? static_cast<int>(m.value) : -1;
      const int grp = code < 0 ? -1 : m_group(code);
      if (grp < 0) fail(m.column, "unsupported M code M" + (code < 0 ? fmt(m.value, 4) : std::to_string(code)));
      if (c.m[grp])
        fail(m.column, "M" + std::to_string(code) + " and M" + std::to_string(c.mcode[grp]) +
                           " in one line are in one modal group");
      c.m[grp] = m;
      c.mcode[grp] = code;
    }
    return c;
  }

  // Letters this reader does not take, and words without the code that uses them.
  void check_letters(const LineWords& w, const LineCodes& c) const {
    for (char l : std::string("ABCUVW"))
      if (w[l]) fail(w[l]->column, std::string("unsupported word '") + l + "' (this reader has the axes X Y Z)");
    for (char l : std::string("DE"))
      if (w[l]) fail(w[l]->column, std::string("unsupported word '") + l + "'");
    const int nm = c.g[kNonModal] ? c.g10[kNonModal] : -1;
    if (w['H'] && c.g10[kToolLength] != 430) fail(w['H']->column, "H word with no G43");
    const int cyc = c.g[kMotion] ? (c.g10[kMotion] > 30 && c.g10[kMotion] != 800 ? c.g10[kMotion] / 10 : 0) : st_.cycle;
    if (w['L'] && nm != 100 && !cyc) fail(w['L']->column, "L word with no G10 or canned cycle");
    if (w['Q'] && c.g10[kPathControl] != 640 && cyc != 73 && cyc != 83)
      fail(w['Q']->column, "Q word with no G64, G73 or G83");
    const bool arc_line = c.g[kMotion] ? (c.g10[kMotion] == 20 || c.g10[kMotion] == 30)
                                       : (st_.motion == Motion::ArcCW || st_.motion == Motion::ArcCCW);
    if (w['P'] && nm != 40 && nm != 100 && c.g10[kPathControl] != 640 && !arc_line && cyc != 82 && cyc != 89)
      fail(w['P']->column, "P word with no G4, G10, G64, G82, G89 or arc");
  }

  void settings_before_motion(const LineWords& w, const LineCodes& c) {
    if (w['F']) feed(*w['F']);
    if (w['S']) {
      if (w['S']->value < 0) fail(w['S']->column, "spindle speed S must be >= 0 (got " + fmt(w['S']->value) + ")");
      event(w['S']->column, "S" + fmt(w['S']->value, 0));
    }
    if (w['T']) tool_select(*w['T']);
    if (c.m[1]) {  // M6
      st_.tool = st_.selected;
      dwell(c.m[1]->column, 0);
      event(c.m[1]->column, "M6 T" + std::to_string(st_.tool));
    }
    if (c.m[2]) {  // M3 M4 M5
      dwell(c.m[2]->column, 0);
      event(c.m[2]->column, "M" + std::to_string(c.mcode[2]));
    }
    if (c.m[3]) event(c.m[3]->column, "M" + std::to_string(c.mcode[3]));
    if (c.g10[kNonModal] == 40 && c.g[kNonModal]) dwell_word(w, c.g[kNonModal]->column);
    modal_settings(w, c);
  }

  // F in the units before this line's G20/G21 (LinuxCNC's order).
  void feed(const Word& f) {
    if (!(f.value > 0)) fail(f.column, "feed F must be > 0 (got " + fmt(f.value) + ")");
    st_.feed_mm_s = f.value * unit() / 60.0;
  }

  void tool_select(const Word& t) {
    if (t.value < 0 || t.value != std::floor(t.value) || t.value > 99999)
      fail(t.column, "tool T must be a whole number 0..99999 (got " + fmt(t.value) + ")");
    st_.selected = static_cast<int>(t.value);
    event(t.column, "T" + std::to_string(st_.selected));
  }

  void dwell_word(const LineWords& w, int col) {
    if (!w['P']) fail(col, "G4 needs P (the dwell in seconds)");
    const Word p = *w['P'];
    if (p.value < 0) fail(p.column, "dwell P must be >= 0 s (got " + fmt(p.value) + ")");
    dwell(col, p.value);
    event(col, "G4 P" + fmt(p.value));
  }

  void modal_settings(const LineWords& w, const LineCodes& c) {
    if (c.g[kPlane]) st_.plane = c.g10[kPlane] == 170 ? Plane::XY : (c.g10[kPlane] == 180 ? Plane::ZX : Plane::YZ);
    if (c.g[kUnits]) st_.inches = c.g10[kUnits] == 200;
    if (c.g[kToolLength]) tool_length(w, c);
    if (c.g[kCoordSystem]) {
      const int c10 = c.g10[kCoordSystem];
      st_.cs = c10 <= 590 ? (c10 - 540) / 10 : 6 + (c10 - 591);
      event(c.g[kCoordSystem]->column, gname(c10));
    }
    if (c.g[kPathControl]) path_control(w, c);
    if (c.g[kDistance]) st_.incremental = c.g10[kDistance] == 910;
    if (c.g[kArcDistance]) st_.arc_absolute = c.g10[kArcDistance] == 901;
    if (c.g[kRetract]) st_.retract_to_r = c.g10[kRetract] == 990;
  }

  void tool_length(const LineWords& w, const LineCodes& c) {
    const int col = c.g[kToolLength]->column;
    if (c.g10[kToolLength] == 490) {
      st_.tlo = 0;
      return event(col, "G49");
    }
    int tool = st_.tool;
    if (w['H']) {
      const Word h = *w['H'];
      if (h.value < 0 || h.value != std::floor(h.value) || h.value > 99999)
        fail(h.column, "H must be a whole number 0..99999 (got " + fmt(h.value) + ")");
      tool = static_cast<int>(h.value);
    }
    const auto it = opt_.tools.find(tool);
    if (tool != 0 && it == opt_.tools.end())
      fail(w['H'] ? w['H']->column : col, "tool " + std::to_string(tool) + " is not in the tool table" +
                                              (opt_.tools.empty() ? " (give one with --tool-table)" : ""));
    st_.tlo = tool == 0 ? 0 : it->second;
    event(col, "G43 H" + std::to_string(tool));
  }

  void path_control(const LineWords& w, const LineCodes& c) {
    const int c10 = c.g10[kPathControl];
    st_.path = c10 == 640 ? PathMode::Blend : PathMode::ExactStop;
    st_.blend_tol = -1;
    if (c10 == 640 && w['P']) {
      if (w['P']->value < 0) fail(w['P']->column, "G64 P must be >= 0 (got " + fmt(w['P']->value) + ")");
      st_.blend_tol = w['P']->value * unit();
    }
    if (w['Q'] && w['Q']->value < 0) fail(w['Q']->column, "G64 Q must be >= 0");
  }

  // Machine coordinate of program value v on axis a (absolute mode).
  double to_machine(int a, double v) const { return v * unit() + st_.offsets[st_.cs][a] + (a == 2 ? st_.tlo : 0.0); }

  bool has_axis(const LineWords& w) const { return w['X'] || w['Y'] || w['Z']; }

  void motion_and_nonmodal(const LineWords& w, const LineCodes& c);
  void g10(const LineWords& w, int col);
  void go_home(const LineWords& w, int c10, int col);
  void motion(const LineWords& w, const LineCodes& c, bool machine);
  Vec3 end_point(const LineWords& w, bool machine) const;
  void push_move(Block& b, const LineWords& w);
  bool stop_words(const LineCodes& c);
  void cycle(const LineWords& w, int col);
  void cycle_words(const LineWords& w, int col);
  void rapid_to(Vec3 p, int col);
  void feed_to(Vec3 p, int col);
  void cycle_holes(int col, double clear);
  void peck(int col, double clear);

  const Options& opt_;
  State st_;
  Vec3 pos_;
  int line_ = 0;
  Program prog_;
  Params params_;
};

void Interpreter::motion_and_nonmodal(const LineWords& w, const LineCodes& c) {
  const int nm = c.g[kNonModal] ? c.g10[kNonModal] : -1;
  const int ncol = nm >= 0 ? c.g[kNonModal]->column : 0;
  const bool motion_axes = nm != 100 && nm != 280 && nm != 300;
  if (!motion_axes && c.g[kMotion] && has_axis(w))
    fail(c.g[kMotion]->column, gname(c.g10[kMotion]) + " and " + gname(nm) + " in one line both use the axis words");
  if (c.g[kMotion]) {
    const int c10 = c.g10[kMotion];
    if (c10 / 10 != st_.cycle) st_.cycle_seen = false;
    if (c10 <= 30 || c10 == 800) st_.cycle_il.reset();
    st_.cycle = 0;
    if (c10 == 800 || c10 > 30) st_.motion.reset();
    else st_.motion = static_cast<Motion>(c10 / 10);
    if (c10 > 30 && c10 != 800) st_.cycle = c10 / 10;
  }
  if (nm == 100) g10(w, ncol);
  else if (nm == 280 || nm == 300) go_home(w, nm, ncol);
  else if (nm == 281 || nm == 301) {
    if (has_axis(w)) fail(ncol, gname(nm) + " takes no axis words");
    (nm == 281 ? st_.g28 : st_.g30) = pos_;
    event(ncol, gname(nm));
  }
  if (motion_axes) motion(w, c, nm == 530);
}

void Interpreter::g10(const LineWords& w, int col) {
  if (!w['L']) fail(col, "G10 needs L (L2 or L20)");
  const double l = w['L']->value;
  if (l != 2 && l != 20) fail(w['L']->column, "G10 L" + fmt(l, 0) + " is not supported (L2 and L20 are)");
  if (!w['P']) fail(col, "G10 needs P (the coordinate system, 0..9)");
  const double p = w['P']->value;
  if (p < 0 || p > 9 || p != std::floor(p)) fail(w['P']->column, "G10 P must be 0..9 (0: the active system)");
  if (w['R']) fail(w['R']->column, "G10 R (rotation) is not supported");
  const int cs = p == 0 ? st_.cs : static_cast<int>(p) - 1;
  for (int a = 0; a < 3; ++a) {
    const auto& v = w["XYZ"[a]];
    if (!v) continue;
    if (l == 2) st_.offsets[cs][a] = v->value * unit();
    else st_.offsets[cs][a] = pos_[a] - (a == 2 ? st_.tlo : 0.0) - v->value * unit();
  }
  event(col, "G10 L" + fmt(l, 0) + " P" + std::to_string(cs + 1));
}

// G28 / G30: through the given point (if any) to the stored position.
void Interpreter::go_home(const LineWords& w, int c10, int col) {
  const Vec3 home = c10 == 280 ? st_.g28 : st_.g30;
  Block via;
  via.motion = Motion::Rapid;
  via.column = col;
  via.start = pos_;
  via.end = end_point(w, false);
  push_move(via, w);
  Block b;
  b.motion = Motion::Rapid;
  b.column = col;
  b.start = pos_;
  b.end = pos_;
  for (int a = 0; a < 3; ++a)
    if (!has_axis(w) || w["XYZ"[a]]) b.end[a] = home[a];
  push_move(b, w);
}

// The end point of this line's move, machine mm.
Vec3 Interpreter::end_point(const LineWords& w, bool machine) const {
  Vec3 e = pos_;
  for (int a = 0; a < 3; ++a) {
    const auto& v = w["XYZ"[a]];
    if (!v) continue;
    if (machine) e[a] = v->value * unit();
    else e[a] = st_.incremental ? pos_[a] + v->value * unit() : to_machine(a, v->value);
  }
  return e;
}

void Interpreter::push_move(Block& b, const LineWords& w) {
  b.line = line_;
  if (b.column == 0) b.column = w.first_column;
  b.plane = st_.plane;
  b.path = st_.path;
  b.blend_tol_mm = st_.blend_tol;
  if (!b.is_arc() && b.end == b.start) return;  // a line of length zero moves nothing
  pos_ = b.end;
  prog_.blocks.push_back(b);
}

void Interpreter::motion(const LineWords& w, const LineCodes& c, bool machine) {
  const bool arc_word = w['I'] || w['J'] || w['K'] || w['R'];
  const int col = c.g[kMotion] ? c.g[kMotion]->column : w.first_column;
  if (!has_axis(w) && !arc_word) {
    if (machine) fail(c.g[kNonModal]->column, "G53 with no axis words");
    return;
  }
  if (st_.cycle) return cycle(w, col);
  if (!st_.motion) fail(col, "axis word with no motion mode in effect (give G0, G1, G2 or G3)");
  const Motion m = *st_.motion;
  if (machine && (m != Motion::Rapid && m != Motion::Line))
    fail(c.g[kNonModal]->column, "G53 needs G0 or G1");
  if (machine && st_.incremental) fail(c.g[kNonModal]->column, "G53 cannot be used in incremental mode (G91)");
  if ((m == Motion::Rapid || m == Motion::Line) && arc_word) {
    const Word& bad = w['R'] ? *w['R'] : (w['I'] ? *w['I'] : (w['J'] ? *w['J'] : *w['K']));
    fail(bad.column, std::string(w['R'] ? "R" : "I/J/K") + " word is only allowed with G2/G3 (motion is G" +
                         std::to_string(static_cast<int>(m)) + ")");
  }
  Block b;
  b.motion = m;
  b.start = pos_;
  b.end = end_point(w, machine);
  b.column = col;
  b.plane = st_.plane;
  if (m != Motion::Rapid) {
    if (st_.feed_mm_s <= 0) fail(col, "G" + std::to_string(static_cast<int>(m)) + " with no feed rate: set F");
    b.feed_mm_s = st_.feed_mm_s;
  }
  if (b.is_arc()) {
    if (w['P'] && w['P']->value != 1) fail(w['P']->column, "arc turns P other than 1 are not supported");
    ArcWords aw;
    for (int a = 0; a < 3; ++a) {
      const auto& v = w["IJK"[a]];
      if (!v) continue;
      aw.off[a] = st_.arc_absolute ? to_machine(a, v->value) - pos_[a] : v->value * unit();
      aw.off_column[a] = v->column;
    }
    if (w['R']) aw.r = w['R']->value * unit(), aw.r_column = w['R']->column;
    make_arc(b, aw, st_.inches, line_);
  }
  push_move(b, w);
}

void Interpreter::rapid_to(Vec3 p, int col) {
  Block b;
  b.motion = Motion::Rapid;
  b.start = pos_;
  b.end = p;
  b.column = col;
  push_move(b, LineWords{});
}

void Interpreter::feed_to(Vec3 p, int col) {
  Block b;
  b.motion = Motion::Line;
  b.start = pos_;
  b.end = p;
  b.column = col;
  b.feed_mm_s = st_.feed_mm_s;
  push_move(b, LineWords{});
}

// The sticky cycle words of a line (R and Z absolute, in machine mm).
void Interpreter::cycle_words(const LineWords& w, int col) {
  const std::string g = "G" + std::to_string(st_.cycle);
  if (st_.incremental) fail(col, "canned cycles in incremental mode (G91) are not supported");
  if (st_.plane != Plane::XY) fail(col, "canned cycles are supported in the G17 plane only");
  if (st_.feed_mm_s <= 0) fail(col, g + " with no feed rate: set F");
  if (w['L'] && w['L']->value != 1) fail(w['L']->column, "cycle repeats L other than 1 are not supported");
  if (w['R']) st_.cycle_r = to_machine(2, w['R']->value);
  if (w['Z']) st_.cycle_z = to_machine(2, w['Z']->value);
  if (w['Q']) {
    if (!(w['Q']->value > 0)) fail(w['Q']->column, g + " Q (the peck) must be > 0");
    st_.cycle_q = w['Q']->value * unit();
  }
  if (w['P']) {
    if (w['P']->value < 0) fail(w['P']->column, g + " P (the dwell) must be >= 0 s");
    st_.cycle_p = w['P']->value;
  }
  if (st_.cycle_z > st_.cycle_r) fail(col, g + ": the bottom Z is above the retract plane R");
  if ((st_.cycle == 73 || st_.cycle == 83) && !(st_.cycle_q > 0)) fail(col, g + " needs Q (the peck)");
}

// A canned cycle at the line's X Y, with LinuxCNC's moves (absolute mode):
// when the initial level (Z when the series of cycles began) is below R,
// first rapid straight up to R; then rapid to X Y at the current Z if it
// is above R (and down to R), else at the clear level (and down to R if it
// is above); the cycle; the clear level is R (G99) or the initial level
// (G98, raised to R if below).
void Interpreter::cycle(const LineWords& w, int col) {
  const std::string g = "G" + std::to_string(st_.cycle);
  if (!st_.cycle_seen) {
    if (!w['R']) fail(col, g + " needs R (the retract plane) when the cycle begins");
    if (!w['Z']) fail(col, g + " needs Z (the bottom) when the cycle begins");
    if ((st_.cycle == 82 || st_.cycle == 89) && !w['P']) fail(col, g + " needs P (the dwell) when the cycle begins");
    if ((st_.cycle == 73 || st_.cycle == 83) && !w['Q']) fail(col, g + " needs Q (the peck) when the cycle begins");
  }
  st_.cycle_seen = true;
  cycle_words(w, col);
  if (!st_.cycle_il) st_.cycle_il = pos_.z;
  double old = *st_.cycle_il, current = pos_.z;
  const double r = st_.cycle_r;
  if (old < r) {
    rapid_to({pos_.x, pos_.y, r}, col);
    old = current = r;
  }
  const double clear = st_.retract_to_r ? r : old;
  const Vec3 xy = end_point(w, false);
  if (current > r) {
    rapid_to({xy.x, xy.y, current}, col);
  } else {
    rapid_to({xy.x, xy.y, clear}, col);
  }
  rapid_to({xy.x, xy.y, r}, col);
  cycle_holes(col, clear);
}

void Interpreter::cycle_holes(int col, double clear) {
  const Vec3 top = pos_;
  const Vec3 bottom{top.x, top.y, st_.cycle_z};
  const Vec3 out{top.x, top.y, clear};
  switch (st_.cycle) {
    case 73: case 83: return peck(col, clear);
    case 81: feed_to(bottom, col); break;
    case 82: feed_to(bottom, col), dwell(col, st_.cycle_p); break;
    case 85: feed_to(bottom, col), feed_to(top, col); break;
    case 89: feed_to(bottom, col), dwell(col, st_.cycle_p), feed_to(out, col); break;
  }
  rapid_to(out, col);
}

// G83: each peck Q deeper, back to R between pecks, rapid down to the last
// depth + 0.010 in; G73: a 0.010 in retract between pecks.
void Interpreter::peck(int col, double clear) {
  constexpr double kDelta = 0.254;  // mm (LinuxCNC: 0.010 in)
  const double r = pos_.z, bottom = st_.cycle_z;
  double depth = r;
  while (depth > bottom) {
    if (depth != r && st_.cycle == 83) rapid_to({pos_.x, pos_.y, depth + kDelta}, col);
    depth -= st_.cycle_q;
    if (depth < bottom + 1e-9) depth = bottom;  // a peck that reaches the bottom up to rounding is the last
    feed_to({pos_.x, pos_.y, depth}, col);
    if (depth <= bottom) break;
    rapid_to({pos_.x, pos_.y, st_.cycle == 83 ? r : depth + kDelta}, col);
  }
  rapid_to({pos_.x, pos_.y, clear}, col);
}

bool Interpreter::stop_words(const LineCodes& c) {
  if (!c.m[0]) return true;
  const int code = c.mcode[0], col = c.m[0]->column;
  event(col, "M" + std::to_string(code));
  if (code == 0 || code == 1) {
    dwell(col, 0);
    return true;
  }
  prog_.ended = true;
  return false;
}

LineRunner::LineRunner(const Options& o) : impl_(std::make_unique<Interpreter>(o)) {}
LineRunner::~LineRunner() = default;
bool LineRunner::line(std::string_view text, int lineno) { return impl_->line(text, lineno); }
Params& LineRunner::params() { return impl_->params(); }
std::size_t LineRunner::blocks() const { return impl_->blocks(); }
Program LineRunner::take() { return impl_->take(); }

}  // namespace contour::gcode
