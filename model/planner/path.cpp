#include "planner/path.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace contour::planner {

namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;

Vec3 axis_unit(int a) {
  Vec3 v;
  v[a] = 1;
  return v;
}

// Angle in [0, 2 pi).
double wrap(double a) {
  a = std::fmod(a, kTwoPi);
  return a < 0 ? a + kTwoPi : a;
}

}  // namespace

double distance_to_segment(Vec3 p, Vec3 a, Vec3 b) {
  const Vec3 ab = b - a;
  const double l2 = dot(ab, ab);
  double t = l2 == 0 ? 0 : dot(p - a, ab) / l2;
  t = std::clamp(t, 0.0, 1.0);
  return norm(p - (a + t * ab));
}

Segment make_segment(const gcode::Block& b) {
  Segment g;
  g.start = b.start;
  g.end = b.end;
  g.line = b.line;
  g.rapid = b.motion == gcode::Motion::Rapid;
  g.exact_stop = b.path == gcode::PathMode::ExactStop;
  g.blend_tol = b.blend_tol_mm;
  if (b.is_dwell()) {
    g.kind = Segment::Kind::Dwell;
    g.dwell_s = b.dwell_s;
    g.exact_stop = true;
    return g;
  }
  if (!b.is_arc()) {
    g.kind = Segment::Kind::Line;
    g.length = norm(b.end - b.start);
    if (g.length == 0) throw std::invalid_argument("line " + std::to_string(b.line) + ": zero-length move");
    g.dir = (1.0 / g.length) * (b.end - b.start);
    return g;
  }
  g.kind = Segment::Kind::Arc;
  g.arc3d = b.arc3d;
  g.full_circle = b.full_circle;
  const bool ccw = b.motion == gcode::Motion::ArcCCW;
  const int nax = gcode::normal_axis(b.plane);
  const Vec3 ps = b.start, pc = b.centre;
  Vec3 pe = b.end;
  Vec3 n;
  if (b.arc3d) {
    n = cross(ps - pc, pe - pc);
    if (norm(n) == 0 || n[nax] == 0)
      throw std::invalid_argument("line " + std::to_string(b.line) + ": 3D arc plane undefined");
    n = unit(n);
    if (n[nax] < 0) n = -1.0 * n;
  } else {
    n = axis_unit(nax);
    g.rise = dot(b.end - b.start, n) * n;
    pe = b.end - g.rise;  // the end projected onto the plane of the start
  }
  const double R = 0.5 * (b.r_start + b.r_end);
  g.radius = R;
  if (b.full_circle) {
    const Vec3 v = unit(pc - ps);
    g.v_hat = v;
    g.u_hat = ccw ? cross(v, n) : cross(n, v);  // U = V turned -90 (CCW) / +90 (CW) degrees about n
    g.origin = ps;
    g.qs = {0, 0};
    g.qe = {0, 0};
    g.qc = {0, R};
    g.sigma = +1;  // U is the direction of travel at Ps, V points to the centre
    g.alpha_s = -std::numbers::pi / 2;
    g.sweep = kTwoPi;
  } else {
    // Swept angle of the programmed arc, in the sense of travel about n.
    const Vec3 a = ps - pc, c = pe - pc;
    double theta = std::atan2(dot(cross(a, c), n), dot(a, c));
    if (!ccw) theta = -theta;
    if (theta <= 0) theta += kTwoPi;
    const double d = norm(ps - pe);
    if (ccw) {
      g.origin = pe;
      g.u_hat = unit(ps - pe);
      g.qs = {d, 0};
      g.qe = {0, 0};
    } else {
      g.origin = ps;
      g.u_hat = unit(pe - ps);
      g.qs = {0, 0};
      g.qe = {d, 0};
    }
    g.v_hat = cross(n, g.u_hat);
    const double h = std::sqrt(std::max(0.0, R * R - d * d / 4));
    g.qc = {d / 2, theta < std::numbers::pi ? -h : h};
    g.sigma = ccw ? +1 : -1;
    g.alpha_s = std::atan2(g.qs.v - g.qc.v, g.qs.u - g.qc.u);
    const double alpha_e = std::atan2(g.qe.v - g.qc.v, g.qe.u - g.qc.u);
    g.sweep = wrap(g.sigma * (alpha_e - g.alpha_s));
    if (g.sweep == 0) g.sweep = kTwoPi;
  }
  g.normal = n;
  const double rise = norm(g.rise);
  g.length = std::hypot(R * g.sweep, rise);
  const Vec3 pc_used = g.origin + g.qc.u * g.u_hat + g.qc.v * g.v_hat;
  g.centre_shift = norm(pc_used - pc);
  return g;
}

UV Segment::uv_at(double s, double radial_offset) const {
  const double phi = sweep * (s / length);
  const double a = alpha_s + sigma * phi;
  const double r = radius + radial_offset;
  return {qc.u + r * std::cos(a), qc.v + r * std::sin(a)};
}

Vec3 Segment::point(double s, double radial_offset) const {
  if (s <= 0 && radial_offset == 0) return start;
  if (s >= length && radial_offset == 0) return end;
  s = std::clamp(s, 0.0, length);
  if (kind != Kind::Arc) return start + s * dir;
  const UV q = uv_at(s, radial_offset);
  return origin + q.u * u_hat + q.v * v_hat + (s / length) * rise;
}

Vec3 Segment::tangent(double s) const {
  if (kind != Kind::Arc) return dir;
  const double a = alpha_s + sigma * sweep * (s / length);
  const double k = sigma * radius * sweep / length;
  const Vec3 t = (-k * std::sin(a)) * u_hat + (k * std::cos(a)) * v_hat + (1.0 / length) * rise;
  return unit(t);
}

double Segment::curvature_radius() const {
  if (kind != Kind::Arc) return 0;
  const double c = norm(rise) / sweep;
  return (radius * radius + c * c) / radius;
}

double Segment::distance(const Vec3& p) const {
  if (kind != Kind::Arc) return distance_to_segment(p, start, end);
  if (!helix()) {
    const Vec3 w = p - origin;
    const Vec3 nn = cross(u_hat, v_hat);
    const double u = dot(w, u_hat) - qc.u, v = dot(w, v_hat) - qc.v, h = dot(w, nn);
    const double rel = wrap(sigma * (std::atan2(v, u) - alpha_s));
    if (rel <= sweep || sweep >= kTwoPi) return std::hypot(std::hypot(u, v) - radius, h);
    return std::min(norm(p - start), norm(p - end));
  }
  return nearest_on_helix(p, 0, length, 64);
}

double Segment::distance_near(const Vec3& p, double s_lo, double s_hi) const {
  if (kind != Kind::Arc || !helix()) return distance(p);
  return nearest_on_helix(p, s_lo, s_hi, 8);
}

// Coarse scan of kScan steps over [s_lo, s_hi], then golden-section
// refinement around the best.
double Segment::nearest_on_helix(const Vec3& p, double s_lo, double s_hi, int kScan) const {
  s_lo = std::clamp(s_lo, 0.0, length);
  s_hi = std::clamp(s_hi, s_lo, length);
  const double span = s_hi - s_lo;
  double best_s = s_lo, best = norm(p - point(s_lo));
  for (int i = 1; i <= kScan; ++i) {
    const double s = s_lo + span * i / kScan;
    const double d = norm(p - point(s));
    if (d < best) best = d, best_s = s;
  }
  double lo = std::max(s_lo, best_s - span / kScan), hi = std::min(s_hi, best_s + span / kScan);
  const double gr = (std::sqrt(5.0) - 1) / 2;
  const int iterations = kScan >= 64 ? 60 : 36;  // a chord's stretch is short: 0.618^36 of it is below 1e-7
  for (int i = 0; i < iterations; ++i) {
    const double m1 = hi - gr * (hi - lo), m2 = lo + gr * (hi - lo);
    if (norm(p - point(m1)) < norm(p - point(m2))) hi = m2;
    else lo = m1;
  }
  return std::min(best, norm(p - point((lo + hi) / 2)));
}

}  // namespace contour::planner
