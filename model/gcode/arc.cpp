#include "gcode/arc.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace contour::gcode {

namespace {

constexpr const char* kAxisNames = "XYZ";
constexpr const char* kOffsetNames = "IJK";

std::string fmt(double v, int prec = 4) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", prec, v);
  return buf;
}

double inplane_dist(Vec3 a, Vec3 b, Plane p) {
  const int i = first_axis(p), j = second_axis(p);
  return std::hypot(a[i] - b[i], a[j] - b[j]);
}

class ArcMaker {
 public:
  ArcMaker(Block& b, bool inches, int line) : b_(b), inches_(inches), unit_(inches ? 25.4 : 1.0), line_(line) {}

  void make(const ArcWords& w) {
    const std::string gname = b_.motion == Motion::ArcCW ? "G2" : "G3";
    const bool any_offset = w.off[0] || w.off[1] || w.off[2];
    if (w.r && any_offset) fail(w.r_column, "an arc takes R or I/J/K offsets, not both");
    if (!w.r && !any_offset) fail(b_.column, gname + " needs the centre offsets (I J K) or a radius R");
    if (w.r) return r_arc(*w.r, w.r_column);
    const int n = normal_axis(b_.plane);
    Vec3 off;
    for (int a = 0; a < 3; ++a) off[a] = w.off[a].value_or(0.0);
    const bool all3 = w.off[0] && w.off[1] && w.off[2];
    b_.centre = b_.start + off;
    if (all3 && (b_.end[n] != b_.start[n] || off[n] != 0)) return arc3d(gname);
    plane_arc(w, off, gname);
  }

 private:
  [[noreturn]] void fail(int col, const std::string& problem) const { throw Error(line_, col, problem); }

  // Paper B's 3D arc: start, end and centre in space.
  void arc3d(const std::string& gname) {
    const int n = normal_axis(b_.plane), col = b_.column;
    b_.arc3d = true;
    b_.r_start = norm(b_.start - b_.centre);
    b_.r_end = norm(b_.end - b_.centre);
    if (b_.r_start == 0) fail(col, "arc radius is zero (the centre is the start point)");
    radii();
    const Vec3 nv = cross(b_.start - b_.centre, b_.end - b_.centre);
    if (norm(nv) <= 1e-12 * b_.r_start * b_.r_end)
      fail(col, "3D arc: start, centre and end are in one line (a half or full circle), so they do not fix the "
                "arc's plane");
    if (std::fabs(nv[n]) <= 1e-9 * norm(nv))
      fail(col, std::string("3D arc: its plane contains the ") + kAxisNames[n] + " axis, the normal of the " +
                    plane_name(b_.plane) + " plane, so " + gname + " has no sense of rotation; use " +
                    (n == 2 ? "G18 or G19" : (n == 1 ? "G17 or G19" : "G17 or G18")));
  }

  // A plane arc (or helix): only the plane's two offsets count.
  void plane_arc(const ArcWords& w, const Vec3& off, const std::string& gname) {
    const Plane p = b_.plane;
    const int i = first_axis(p), j = second_axis(p), n = normal_axis(p), col = b_.column;
    if (w.off[n] && off[n] != 0)
      fail(w.off_column[n], std::string(1, kOffsetNames[n]) + " offset is off the " + plane_name(p) +
                                " plane: a 3D arc needs all of I, J and K");
    if (!w.off[i] && !w.off[j])
      fail(col, gname + " in the " + plane_name(p) + " plane needs " + kOffsetNames[i] + " or " + kOffsetNames[j] +
                    " (or R)");
    b_.centre[n] = b_.start[n];
    b_.r_start = inplane_dist(b_.start, b_.centre, p);
    b_.r_end = inplane_dist(b_.end, b_.centre, p);
    if (b_.r_start == 0) fail(col, "arc radius is zero (the centre is the start point)");
    radii();
    b_.full_circle = inplane_dist(b_.start, b_.end, p) <= 1e-9 * std::max(1.0, b_.r_start);
  }

  // R-format arc, by LinuxCNC's rule: refused when |R| is shorter than half
  // the chord by more than kArcRTolIn; otherwise, when |R| is at most half
  // the chord, the half circle on the chord (radius half the chord, centre
  // its midpoint), so the path never jumps.
  void r_arc(double r, int r_col) {
    const Plane p = b_.plane;
    const int i = first_axis(p), j = second_axis(p);
    const double d = inplane_dist(b_.start, b_.end, p);
    if (r == 0) fail(r_col, "arc radius R is zero");
    if (d == 0)
      fail(r_col, "an R arc cannot be a full circle (its end equals its start in the " + std::string(plane_name(p)) +
                      " plane): use I J K");
    const double half = d / 2, tol = kArcRTolIn * 25.4;  // mm
    if (half - std::fabs(r) > tol)
      fail(r_col, "arc radius too small to reach the end point: |R|=" + fmt(std::fabs(r) / unit_) +
                      ", half the chord " + fmt(half / unit_) + " (tolerance " + fmt(tol / unit_, 5) + ")");
    const double radius = std::max(std::fabs(r), half);
    const double h2 = std::max(0.0, radius * radius - half * half);
    // Centre on the left of start->end for CCW with R > 0 (arc <= 180 deg).
    const double ux = (b_.end[i] - b_.start[i]) / d, uy = (b_.end[j] - b_.start[j]) / d;
    const double side = (b_.motion == Motion::ArcCCW ? 1.0 : -1.0) * (r > 0 ? 1.0 : -1.0);
    const double h = std::sqrt(h2) * side;
    b_.centre = b_.start;
    b_.centre[i] = (b_.start[i] + b_.end[i]) / 2 - uy * h;
    b_.centre[j] = (b_.start[j] + b_.end[j]) / 2 + ux * h;
    b_.r_start = inplane_dist(b_.start, b_.centre, p);
    b_.r_end = inplane_dist(b_.end, b_.centre, p);
    b_.full_circle = false;
  }

  void radii() const {
    const std::string why = check_radii(b_.r_start / unit_, b_.r_end / unit_, inches_);
    if (!why.empty()) fail(b_.column, why);
  }

  Block& b_;
  bool inches_;
  double unit_;
  int line_;
};

}  // namespace

void make_arc(Block& b, const ArcWords& w, bool inches, int line) { ArcMaker(b, inches, line).make(w); }

}  // namespace contour::gcode
