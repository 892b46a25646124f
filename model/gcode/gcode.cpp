#include "gcode/gcode.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <optional>

#include "gcode/words.hpp"

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

// One tool table line: T and Z are kept, the other LinuxCNC words are
// checked and ignored.
void tool_line(const LineWords& w, int lineno, ToolTable& out) {
  for (char c = 'A'; c <= 'Z'; ++c) {
    if (c == 'G' || c == 'M' || !w[c]) continue;
    if (std::string("TPXYZABCUVWDIJQ").find(c) == std::string::npos)
      throw Error(lineno, w[c]->column, std::string("tool table: unknown word '") + c + "'");
  }
  if (!w.g.empty() || !w.m.empty()) {
    const Word& x = w.g.empty() ? w.m[0] : w.g[0];
    throw Error(lineno, x.column, std::string("tool table: unknown word '") + (w.g.empty() ? 'M' : 'G') + "'");
  }
  if (!w['T']) {
    if (w.first_column) throw Error(lineno, w.first_column, "tool table: a line needs its tool number T");
    return;
  }
  const Word t = *w['T'];
  if (t.value < 0 || t.value != std::floor(t.value) || t.value > 99999)
    throw Error(lineno, t.column, "tool table: T must be a whole number 0..99999");
  const int n = static_cast<int>(t.value);
  if (out.count(n)) throw Error(lineno, t.column, "tool table: tool " + std::to_string(n) + " is listed twice");
  out[n] = w['Z'] ? w['Z']->value : 0.0;
}

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

ToolTable read_tool_table(std::string_view text) {
  ToolTable out;
  int lineno = 0;
  std::size_t at = 0;
  while (at <= text.size()) {
    const auto nl = text.find('\n', at);
    std::string_view line = text.substr(at, nl == std::string_view::npos ? std::string_view::npos : nl - at);
    ++lineno;
    const LineWords w = read_words(line, lineno);
    if (w.block_delete || w.percent) throw Error(lineno, 1, "tool table: unexpected '/' or '%'");
    tool_line(w, lineno, out);
    if (nl == std::string_view::npos) break;
    at = nl + 1;
  }
  return out;
}

std::vector<Block> parse(std::string_view text, const Options& options) { return read(text, options).blocks; }

}  // namespace contour::gcode
