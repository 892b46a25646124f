#include "gcode/gcode.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <optional>

namespace contour::gcode {

int normal_axis(Plane p) { return p == Plane::XY ? 2 : (p == Plane::ZX ? 1 : 0); }
int first_axis(Plane p) { return p == Plane::XY ? 0 : (p == Plane::ZX ? 2 : 1); }
int second_axis(Plane p) { return p == Plane::XY ? 1 : (p == Plane::ZX ? 0 : 2); }
const char* plane_name(Plane p) { return p == Plane::XY ? "G17" : (p == Plane::ZX ? "G18" : "G19"); }

Error::Error(int line, int column, const std::string& problem)
    : std::runtime_error("line " + std::to_string(line) + ", column " + std::to_string(column) + ": " + problem),
      line_(line),
      column_(column),
      problem_(problem) {}

namespace {

std::string fmt(double v, int prec = 4) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", prec, v);
  return buf;
}

constexpr const char* kAxisNames = "XYZ";
constexpr const char* kOffsetNames = "IJK";

struct Word {
  double value = 0;
  int column = 0;
};

// The words of one line, as read.
struct LineWords {
  std::vector<Word> g;
  std::array<std::optional<Word>, 3> axis;    // X Y Z
  std::array<std::optional<Word>, 3> offset;  // I J K
  std::optional<Word> r, f;
  int first_column = 0;  // column of the first word (0: none)
};

class LineReader {
 public:
  LineReader(std::string_view text, int line) : s_(text), line_(line) {}

  LineWords read() {
    LineWords w;
    skip_blank();
    if (pos_ < s_.size() && s_[pos_] == '%') {
      ++pos_;
      skip_blank();
      if (pos_ < s_.size() && s_[pos_] != ';') fail("text after '%' (a '%' line holds nothing else)");
      return w;
    }
    bool first = true;
    while (true) {
      skip_blank_and_comments();
      if (pos_ >= s_.size() || s_[pos_] == ';') break;
      const int col = column();
      const char raw = s_[pos_];
      const char c = static_cast<char>(std::toupper(static_cast<unsigned char>(raw)));
      if (!std::isalpha(static_cast<unsigned char>(raw))) {
        if (raw == ')') fail("')' without a matching '('");
        fail(std::string("unexpected character '") + printable(raw) + "' (a word starts with a letter)");
      }
      ++pos_;
      const double v = number(c, col);
      if (c == 'N') {
        if (!first) fail_at(col, "line number N must be the first word of the line");
        if (v < 0 || v != std::floor(v)) fail_at(col, "line number N must be a whole number >= 0");
        first = false;
        continue;
      }
      first = false;
      if (w.first_column == 0) w.first_column = col;
      const Word word{v, col};
      auto put = [&](std::optional<Word>& slot, char letter) {
        if (slot) fail_at(col, std::string("two ") + letter + " words in one line");
        slot = word;
      };
      switch (c) {
        case 'G': w.g.push_back(word); break;
        case 'X': case 'Y': case 'Z': put(w.axis[c - 'X'], c); break;
        case 'I': case 'J': case 'K': put(w.offset[c - 'I'], c); break;
        case 'R': put(w.r, c); break;
        case 'F': put(w.f, c); break;
        default:
          fail_at(col, std::string("unsupported word '") + c + "' (this reader takes G X Y Z I J K R F N)");
      }
    }
    return w;
  }

  [[noreturn]] void fail(const std::string& problem) const { throw Error(line_, column(), problem); }
  [[noreturn]] void fail_at(int col, const std::string& problem) const { throw Error(line_, col, problem); }

 private:
  static std::string printable(char c) {
    if (std::isprint(static_cast<unsigned char>(c))) return std::string(1, c);
    char buf[8];
    std::snprintf(buf, sizeof buf, "\\x%02x", static_cast<unsigned>(static_cast<unsigned char>(c)));
    return buf;
  }
  int column() const { return static_cast<int>(pos_) + 1; }
  void skip_blank() {
    while (pos_ < s_.size() && (s_[pos_] == ' ' || s_[pos_] == '\t')) ++pos_;
  }
  void skip_blank_and_comments() {
    while (true) {
      skip_blank();
      if (pos_ < s_.size() && s_[pos_] == '(') {
        const int col = column();
        const auto close = s_.find_first_of("()", pos_ + 1);
        if (close == std::string_view::npos) fail_at(col, "comment '(' is not closed on its line");
        if (s_[close] == '(') fail_at(static_cast<int>(close) + 1, "'(' inside a comment (comments do not nest)");
        pos_ = close + 1;
        continue;
      }
      return;
    }
  }
  double number(char letter, int letter_col) {
    skip_blank();
    const std::size_t start = pos_;
    std::string digits;
    if (pos_ < s_.size() && (s_[pos_] == '+' || s_[pos_] == '-')) digits += s_[pos_++];
    skip_blank();
    std::size_t n_int = 0, n_frac = 0;
    while (pos_ < s_.size() && std::isdigit(static_cast<unsigned char>(s_[pos_]))) digits += s_[pos_++], ++n_int;
    if (pos_ < s_.size() && s_[pos_] == '.') {
      digits += s_[pos_++];
      while (pos_ < s_.size() && std::isdigit(static_cast<unsigned char>(s_[pos_]))) digits += s_[pos_++], ++n_frac;
    }
    if (n_int + n_frac == 0) {
      fail_at(letter_col, std::string("word '") + letter + "' has no number");
    }
    if (n_int + n_frac > 30) fail_at(static_cast<int>(start) + 1, std::string("number of '") + letter + "' is too long");
    const double v = std::strtod(digits.c_str(), nullptr);
    if (!std::isfinite(v)) fail_at(static_cast<int>(start) + 1, std::string("number of '") + letter + "' is out of range");
    return v;
  }

  std::string_view s_;
  int line_;
  std::size_t pos_ = 0;
};

struct Modal {
  std::optional<Motion> motion;
  Plane plane = Plane::XY;
  bool inches = false;
  bool incremental = false;
  double feed_mm_s = 0;  // 0: not set
};

double inplane_dist(Vec3 a, Vec3 b, Plane p) {
  const int i = first_axis(p), j = second_axis(p);
  return std::hypot(a[i] - b[i], a[j] - b[j]);
}

class Reader {
 public:
  explicit Reader(const Options& o) : pos_(o.start) {}

  void line(std::string_view text, int lineno, std::vector<Block>& out) {
    LineReader lr(text, lineno);
    LineWords w = lr.read();
    line_ = lineno;
    // G words: at most one per modal group.
    std::optional<Word> g_motion, g_plane, g_units, g_dist;
    for (const Word& g : w.g) {
      if (g.value != std::floor(g.value) || g.value < 0 || g.value > 99)
        fail(g.column, "unsupported G code G" + fmt(g.value, 3) + " (this reader takes G0-G3 G17-G21 G90 G91)");
      const int code = static_cast<int>(g.value);
      std::optional<Word>* slot = nullptr;
      const char* group = "";
      if (code <= 3) slot = &g_motion, group = "motion";
      else if (code >= 17 && code <= 19) slot = &g_plane, group = "plane";
      else if (code == 20 || code == 21) slot = &g_units, group = "units";
      else if (code == 90 || code == 91) slot = &g_dist, group = "distance mode";
      else fail(g.column, "unsupported G code G" + std::to_string(code) + " (this reader takes G0-G3 G17-G21 G90 G91)");
      if (*slot)
        fail(g.column, "G" + std::to_string(code) + " and G" + std::to_string(static_cast<int>((*slot)->value)) +
                           " in one line are both " + group + " words");
      *slot = g;
    }
    // LinuxCNC's order of execution: the feed (step 3) before the units
    // (step 12), so F is read in the units in effect before this line's
    // G20/G21; the feed then stays the same speed across a change of units.
    if (w.f) {
      if (!(w.f->value > 0)) fail(w.f->column, "feed F must be > 0 (got " + fmt(w.f->value) + ")");
      modal_.feed_mm_s = w.f->value * (modal_.inches ? 25.4 : 1.0) / 60.0;
    }
    if (g_units) modal_.inches = g_units->value == 20;
    if (g_plane) modal_.plane = g_plane->value == 17 ? Plane::XY : (g_plane->value == 18 ? Plane::ZX : Plane::YZ);
    if (g_dist) modal_.incremental = g_dist->value == 91;
    const double unit = modal_.inches ? 25.4 : 1.0;
    if (g_motion) modal_.motion = static_cast<Motion>(static_cast<int>(g_motion->value));

    const bool has_axis = w.axis[0] || w.axis[1] || w.axis[2];
    const bool has_arc_word = w.offset[0] || w.offset[1] || w.offset[2] || w.r;
    if (!has_axis && !has_arc_word) return;  // modal settings only
    const int col = g_motion ? g_motion->column : w.first_column;
    if (!modal_.motion) fail(col, "axis word with no motion mode in effect (give G0, G1, G2 or G3)");
    const Motion m = *modal_.motion;
    if ((m == Motion::Rapid || m == Motion::Line) && has_arc_word) {
      const Word& bad = w.r ? *w.r : (w.offset[0] ? *w.offset[0] : (w.offset[1] ? *w.offset[1] : *w.offset[2]));
      fail(bad.column, std::string(w.r ? "R" : "I/J/K") + " word is only allowed with G2/G3 (motion is G" +
                           std::to_string(static_cast<int>(m)) + ")");
    }

    Block b;
    b.motion = m;
    b.start = pos_;
    b.end = pos_;
    b.line = lineno;
    b.column = col;
    b.plane = modal_.plane;
    for (int a = 0; a < 3; ++a) {
      if (!w.axis[a]) continue;
      const double v = w.axis[a]->value * unit;
      b.end[a] = modal_.incremental ? pos_[a] + v : v;
    }
    if (m != Motion::Rapid) {
      if (modal_.feed_mm_s <= 0) fail(col, "G" + std::to_string(static_cast<int>(m)) + " with no feed rate: set F");
      b.feed_mm_s = modal_.feed_mm_s;
    }
    if (b.is_arc()) arc(b, w, unit);
    else if (b.end == b.start) return;  // a line of length zero moves nothing
    pos_ = b.end;
    out.push_back(b);
  }

 private:
  [[noreturn]] void fail(int col, const std::string& problem) const { throw Error(line_, col, problem); }

  void arc(Block& b, const LineWords& w, double unit) {
    const Plane p = b.plane;
    const int i = first_axis(p), j = second_axis(p), n = normal_axis(p);
    const int col = b.column;
    const std::string gname = b.motion == Motion::ArcCW ? "G2" : "G3";
    const bool any_offset = w.offset[0] || w.offset[1] || w.offset[2];
    if (w.r && any_offset) fail(w.r->column, "an arc takes R or I/J/K offsets, not both");
    if (!w.r && !any_offset) fail(col, gname + " needs the centre offsets (I J K) or a radius R");
    Vec3 off;
    for (int a = 0; a < 3; ++a)
      if (w.offset[a]) off[a] = w.offset[a]->value * unit;

    if (w.r) {
      r_arc(b, *w.r, unit);
      return;
    }

    const bool all3 = w.offset[0] && w.offset[1] && w.offset[2];
    b.centre = b.start + off;
    if (all3 && (b.end[n] != b.start[n] || off[n] != 0)) {
      // Paper B's 3D arc.
      b.arc3d = true;
      b.r_start = norm(b.start - b.centre);
      b.r_end = norm(b.end - b.centre);
      if (b.r_start == 0) fail(col, "arc radius is zero (the centre is the start point)");
      radii(b, col, unit);
      const Vec3 nv = cross(b.start - b.centre, b.end - b.centre);
      if (norm(nv) <= 1e-12 * b.r_start * b.r_end)
        fail(col, "3D arc: start, centre and end are in one line (a half or full circle), so they do not fix the "
                  "arc's plane");
      if (std::fabs(nv[n]) <= 1e-9 * norm(nv))
        fail(col, std::string("3D arc: its plane contains the ") + kAxisNames[n] + " axis, the normal of the " +
                      plane_name(p) + " plane, so " + gname + " has no sense of rotation; use " +
                      (n == 2 ? "G18 or G19" : (n == 1 ? "G17 or G19" : "G17 or G18")));
      return;
    }
    // A plane arc (or helix): only the plane's two offsets count.
    if (w.offset[n] && off[n] != 0)
      fail(w.offset[n]->column, std::string(1, kOffsetNames[n]) + " offset is off the " + plane_name(p) +
                                    " plane: a 3D arc needs all of I, J and K");
    if (!w.offset[i] && !w.offset[j])
      fail(col, gname + " in the " + plane_name(p) + " plane needs " + kOffsetNames[i] + " or " + kOffsetNames[j] +
                    " (or R)");
    b.centre[n] = b.start[n];
    b.r_start = inplane_dist(b.start, b.centre, p);
    b.r_end = inplane_dist(b.end, b.centre, p);
    if (b.r_start == 0) fail(col, "arc radius is zero (the centre is the start point)");
    radii(b, col, unit);
    b.full_circle = inplane_dist(b.start, b.end, p) <= 1e-9 * std::max(1.0, b.r_start);
  }

  // R-format arc, by LinuxCNC's rule: refused when |R| is shorter than half
  // the chord by more than kArcRTol (program units); otherwise, when |R| is
  // at most half the chord, the arc is the half circle on the chord (radius
  // half the chord, centre its midpoint), so the path never jumps.
  void r_arc(Block& b, const Word& rw, double unit) const {
    const Plane p = b.plane;
    const int i = first_axis(p), j = second_axis(p);
    const double r = rw.value * unit;
    const double d = inplane_dist(b.start, b.end, p);
    if (r == 0) fail(rw.column, "arc radius R is zero");
    if (d == 0) fail(rw.column, "an R arc cannot be a full circle (its end equals its start in the " +
                                    std::string(plane_name(p)) + " plane): use I J K");
    const double half = d / 2, tol = kArcRTolIn * 25.4;  // mm
    if (half - std::fabs(r) > tol)
      fail(rw.column, "arc radius too small to reach the end point: |R|=" + fmt(std::fabs(r) / unit) +
                          ", half the chord " + fmt(half / unit) + " (tolerance " + fmt(tol / unit, 5) + ")");
    const double radius = std::max(std::fabs(r), half);
    const double h2 = std::max(0.0, radius * radius - half * half);
    // Centre on the left of start->end for CCW with R > 0 (arc <= 180 deg).
    const double ux = (b.end[i] - b.start[i]) / d, uy = (b.end[j] - b.start[j]) / d;
    const double side = (b.motion == Motion::ArcCCW ? 1.0 : -1.0) * (r > 0 ? 1.0 : -1.0);
    const double h = std::sqrt(h2) * side;
    b.centre = b.start;
    b.centre[i] = (b.start[i] + b.end[i]) / 2 - uy * h;
    b.centre[j] = (b.start[j] + b.end[j]) / 2 + ux * h;
    b.r_start = inplane_dist(b.start, b.centre, p);
    b.r_end = inplane_dist(b.end, b.centre, p);
    b.full_circle = false;
  }

  void radii(const Block& b, int col, double unit) const {
    const std::string why = check_radii(b.r_start / unit, b.r_end / unit, modal_.inches);
    if (!why.empty()) fail(col, why);
  }

  Modal modal_;
  Vec3 pos_;
  int line_ = 0;
};

}  // namespace

std::string check_radii(double r1, double r2, bool inches) {
  const double tol = inches ? kRadiusTolIn : kRadiusTolMm;
  const double abs_err = std::fabs(r2 - r1);
  const double rel_err = abs_err / std::max(r1, r2);
  std::string why;
  if (abs_err > 100 * tol) why = "more than 100 x " + fmt(tol, 5);
  else if (abs_err > tol && rel_err > 0.001) why = "more than " + fmt(tol, 5) + " and 0.1 % of the radius";
  if (why.empty()) return {};
  const char* u = inches ? " in" : " mm";
  return "radius to end of arc differs from radius to start: r1=" + fmt(r1) + u + " r2=" + fmt(r2) + u +
         " (difference " + fmt(abs_err, 5) + ", " + why + ")";
}

std::vector<Block> parse(std::string_view text, const Options& options) {
  std::vector<Block> out;
  Reader reader(options);
  int lineno = 0;
  std::size_t at = 0;
  while (at <= text.size()) {
    const auto nl = text.find('\n', at);
    std::string_view line = text.substr(at, nl == std::string_view::npos ? std::string_view::npos : nl - at);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    ++lineno;
    reader.line(line, lineno, out);
    if (nl == std::string_view::npos) break;
    at = nl + 1;
  }
  return out;
}

}  // namespace contour::gcode
