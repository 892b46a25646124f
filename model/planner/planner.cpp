#include "planner/planner.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace contour::planner {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// Planning margins (docs/paper-b.md): velocities are planned 1e-6 under the
// limits, arc accelerations 1 % under (the radial chord offset uses the
// rest), chords for eps * (1 - 1e-3).
constexpr double kVelMargin = 1e-6;
constexpr double kArcAccelMargin = 0.01;
constexpr double kTolMargin = 1e-3;
constexpr double kNormalShare = 0.8660254037844386;  // sqrt(3)/2: a_t >= A/2
constexpr double kOffsetAccelShare = 0.005;          // radial offset jump at a junction
// A feed line with a blended corner at either end plans its tangential
// acceleration at (1 - kCornerShare) of what its axes allow, leaving the
// rest for the velocity step of passing the corner (planner.hpp, "Blending").
constexpr double kCornerShare = 0.5;
// The look-ahead window's bound, in blocks (planner.hpp, "Look-ahead").
constexpr std::size_t kMaxLookAhead = std::size_t{1} << 16;

void require(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument(what);
}

}  // namespace

double chord_length(ChordMethod m, double R, double eps) {
  switch (m) {
    case ChordMethod::Inside: return eps >= R ? 2 * R : 2 * std::sqrt(2 * R * eps - eps * eps);
    case ChordMethod::Outside: return 2 * std::sqrt(2 * R * eps + eps * eps);
    case ChordMethod::InsideOutside: return 4 * std::sqrt(R * eps);
  }
  return 0;
}

double chord_angle(ChordMethod m, double R, double eps) {
  switch (m) {
    case ChordMethod::Inside: return 2 * std::acos(std::max(-1.0, (R - eps) / R));
    case ChordMethod::Outside: return 2 * std::acos(R / (R + eps));
    case ChordMethod::InsideOutside: return 2 * std::acos(std::max(-1.0, (R - eps) / (R + eps)));
  }
  return 0;
}

double vertex_offset(ChordMethod m, double R, double L) {
  if (m == ChordMethod::Inside || R <= 0 || L <= 0) return 0;
  const double h2 = L * L / 4;  // (half chord)^2
  // (b): ends at R + e, middle on the circle: (R + e)^2 - h^2 = R^2.
  if (m == ChordMethod::Outside) return h2 / (std::sqrt(R * R + h2) + R);
  // (c): ends at R + e, middle at R - e: (R + e)^2 - h^2 = (R - e)^2.
  return h2 / (4 * R);
}

const char* chord_name(ChordMethod m) {
  return m == ChordMethod::Inside ? "a" : (m == ChordMethod::Outside ? "b" : "c");
}

const char* cap_name(Cap c) {
  switch (c) {
    case Cap::Feed: return "feed";
    case Cap::AxisVelocity: return "axis velocity";
    case Cap::Chord: return "chord tolerance";
    case Cap::Centripetal: return "centripetal acceleration";
    case Cap::Rapid: return "rapid";
  }
  return "";
}

void Config::validate() const {
  auto pos = [](double v) { return std::isfinite(v) && v > 0; };
  require(pos(cycle_s), "cycle must be > 0 s (got " + std::to_string(cycle_s) + ")");
  require(pos(tol_mm), "tolerance must be > 0 mm (got " + std::to_string(tol_mm) + ")");
  require(std::isfinite(blend_tol_mm) && blend_tol_mm >= 0,
          "blend tolerance must be >= 0 mm (got " + std::to_string(blend_tol_mm) + ")");
  const char* names = "XYZ";
  for (int i = 0; i < 3; ++i) {
    require(pos(machine.vmax[i]), std::string("velocity limit of ") + names[i] + " must be > 0");
    require(pos(machine.amax[i]), std::string("acceleration limit of ") + names[i] + " must be > 0");
  }
  require(pos(machine.rapid), "rapid speed must be > 0");
}

double PlannedSegment::s_at(double t) const {
  if (t <= 0) return 0;
  if (t < t_acc) return std::min(geom.length, v_start * t + 0.5 * a_t * t * t);
  if (t < t_acc + t_cruise) return std::min(geom.length, s_acc + v_cruise * (t - t_acc));
  const double tau = std::min(t - t_acc - t_cruise, t_dec);
  return std::min(geom.length, s_acc + s_cruise + v_cruise * tau - 0.5 * a_t * tau * tau);
}

double PlannedSegment::v_at(double t) const {
  if (t <= 0) return v_start;
  if (t < t_acc) return v_start + a_t * t;
  if (t < t_acc + t_cruise) return v_cruise;
  const double tau = std::min(t - t_acc - t_cruise, t_dec);
  return std::max(0.0, v_cruise - a_t * tau);
}

namespace {

// Lowers a block's cruise cap to v, naming the reason, if v is lower.
void lower_cap(PlannedSegment& ps, double v, Cap why) {
  if (v < ps.v_cap) ps.v_cap = v, ps.cap = why;
}

// Line: each axis' velocity and acceleration limit over its direction share.
void limit_line(PlannedSegment& ps, const Machine& mc) {
  const Segment& g = ps.geom;
  double a = kInf;
  for (int i = 0; i < 3; ++i) {
    const double d = std::fabs(g.dir[i]);
    if (d < 1e-15) continue;
    lower_cap(ps, mc.vmax[i] * (1 - kVelMargin) / d, Cap::AxisVelocity);
    a = std::min(a, mc.amax[i] / d);
  }
  ps.a_t = a;
  for (int i = 0; i < 3; ++i) ps.accel_use[i] = a * std::fabs(g.dir[i]);
}

// Planar arc: the plane acceleration bound A_plane, the centripetal cap, and
// a_t = what A_plane leaves beside the centripetal acceleration. pr: each
// axis' projection on the arc plane.
void limit_planar_arc(PlannedSegment& ps, const Machine& mc, const Vec3& pr) {
  double a_plane = kInf;
  for (int i = 0; i < 3; ++i) {
    if (pr[i] < 1e-15) continue;
    a_plane = std::min(a_plane, mc.amax[i] / pr[i]);
    lower_cap(ps, mc.vmax[i] * (1 - kVelMargin) / pr[i], Cap::AxisVelocity);
  }
  a_plane *= 1 - kArcAccelMargin;
  lower_cap(ps, std::sqrt(kNormalShare * a_plane * ps.rho), Cap::Centripetal);
  const double an = ps.v_cap * ps.v_cap / ps.rho;
  ps.a_t = std::sqrt(std::max(0.0, a_plane * a_plane - an * an));
  for (int i = 0; i < 3; ++i) ps.accel_use[i] = a_plane * pr[i];
}

// Helix: per axis, the tangential share c_i (bound on |tangent_i|) plus the
// centripetal share on the plane projection.
void limit_helix(PlannedSegment& ps, const Machine& mc, const Vec3& pr) {
  const Segment& g = ps.geom;
  const double rise = norm(g.rise);
  const double beta = std::atan2(rise, g.radius * g.sweep);
  const Vec3 rh = (1.0 / rise) * g.rise;
  Vec3 c;  // bound on |tangent_i|
  double a_plane = kInf;
  for (int i = 0; i < 3; ++i) {
    c[i] = std::cos(beta) * pr[i] + std::sin(beta) * std::fabs(rh[i]);
    if (c[i] > 1e-15) lower_cap(ps, mc.vmax[i] * (1 - kVelMargin) / c[i], Cap::AxisVelocity);
    if (pr[i] > 1e-15) a_plane = std::min(a_plane, mc.amax[i] * (1 - kArcAccelMargin) / pr[i]);
  }
  lower_cap(ps, std::sqrt(kNormalShare * a_plane * ps.rho), Cap::Centripetal);
  const double an = ps.v_cap * ps.v_cap / ps.rho;
  double at = kInf;
  for (int i = 0; i < 3; ++i)
    if (c[i] > 1e-15) at = std::min(at, (mc.amax[i] * (1 - kArcAccelMargin) - an * pr[i]) / c[i]);
  ps.a_t = std::max(0.0, at);
  for (int i = 0; i < 3; ++i) ps.accel_use[i] = ps.a_t * c[i] + an * pr[i];
}

// A block's geometry, cruise cap and tangential acceleration.
PlannedSegment plan_segment(const gcode::Block& b, const Config& config, double eps) {
  const Machine& mc = config.machine;
  PlannedSegment ps;
  ps.geom = make_segment(b);
  const Segment& g = ps.geom;
  if (g.kind == Segment::Kind::Dwell) return ps;  // at rest: v_cap 0, a_t 0
  ps.v_cap = g.rapid ? mc.rapid : b.feed_mm_s;
  ps.cap = g.rapid ? Cap::Rapid : Cap::Feed;
  if (g.kind == Segment::Kind::Line) {
    limit_line(ps, mc);
  } else {
    ps.rho = g.curvature_radius();
    Vec3 pr;  // projection of each axis on the arc plane
    for (int i = 0; i < 3; ++i) pr[i] = std::hypot(g.u_hat[i], g.v_hat[i]);
    lower_cap(ps, chord_length(config.chord, ps.rho, eps) / config.cycle_s, Cap::Chord);
    if (!g.helix()) limit_planar_arc(ps, mc, pr);
    else limit_helix(ps, mc, pr);
  }
  require(ps.a_t > 0 && ps.v_cap > 0, "line " + std::to_string(b.line) + ": no feasible speed");
  return ps;
}

// Whether the corner s1 -> s2 may be blended: two feed moves (G1 G2 G3),
// s1 in G64.
bool blendable(const PlannedSegment& s1, const PlannedSegment& s2) {
  auto feed = [](const Segment& g) { return g.kind != Segment::Kind::Dwell && !g.rapid; };
  return feed(s1.geom) && feed(s2.geom) && !s1.geom.exact_stop;
}

// The path tolerance at the junction s1 -> s2: the blend tolerance (G64 P of
// either block, else the configured one) where it may be blended, else eps.
double junction_tol(const PlannedSegment& s1, const PlannedSegment& s2, const Config& config, double eps) {
  if (!blendable(s1, s2)) return eps;
  auto p = [&](const Segment& g) { return g.blend_tol >= 0 ? g.blend_tol : config.blend_tol_mm; };
  return std::max(eps, std::min(p(s1.geom), p(s2.geom)) * (1 - kTolMargin));
}

// Feed lines with a blended corner at either end keep kCornerShare of their
// axes' acceleration for the corner.
void reserve_corner_acceleration(std::vector<PlannedSegment>& segs) {
  for (std::size_t k = 0; k < segs.size(); ++k) {
    PlannedSegment& s = segs[k];
    if (s.geom.kind != Segment::Kind::Line || s.geom.rapid) continue;
    auto bent = [](const PlannedSegment& a, const PlannedSegment& b) {
      return blendable(a, b) && dot(a.geom.tangent(a.geom.length), b.geom.tangent(0)) < 1 - 1e-12;
    };
    const bool corner = (k > 0 && bent(segs[k - 1], s)) || (k + 1 < segs.size() && bent(s, segs[k + 1]));
    if (!corner) continue;
    s.a_t *= 1 - kCornerShare;
    s.accel_use = (1 - kCornerShare) * s.accel_use;
  }
}

// The speed limit at the junction s1 -> s2 (planner.hpp, "junction limit");
// eps: the junction's path tolerance (junction_tol).
double junction_limit(const PlannedSegment& s1, const PlannedSegment& s2, const Config& config, double eps,
                      double amin) {
  const Machine& mc = config.machine;
  const double T = config.cycle_s;
  if (s1.geom.exact_stop || s2.geom.kind == Segment::Kind::Dwell) return 0;
  double lim = std::min(s1.v_cap, s2.v_cap);
  const double amx = std::max(s1.a_t, s2.a_t);
  const Vec3 t1 = s1.geom.tangent(s1.geom.length), t2 = s2.geom.tangent(0);
  const double delta = std::acos(std::clamp(dot(t1, t2), -1.0, 1.0));
  if (delta > 1e-9) {
    lim = std::min(lim, std::max(0.0, 2 * eps / std::sin(delta / 2) / T - amx * T));
    for (int i = 0; i < 3; ++i) {
      const double dt = std::fabs(t2[i] - t1[i]);
      if (dt < 1e-12) continue;
      const double rem = mc.amax[i] - std::max(s1.accel_use[i], s2.accel_use[i]);
      lim = std::min(lim, std::max(0.0, rem) * T / dt);
    }
  }
  for (const PlannedSegment* s : {&s1, &s2}) {
    if (s->geom.kind != Segment::Kind::Arc) continue;
    lim = std::min(lim, std::max(0.0, chord_length(ChordMethod::Inside, s->rho, eps) / T - amx * T));
    // vertex_offset ~ k L^2 / rho: keep its jump under kOffsetAccelShare of A.
    const double x = kOffsetAccelShare * amin * T * T;
    const double k = config.chord == ChordMethod::InsideOutside ? 1.0 / 16 : 1.0 / 8;
    if (config.chord != ChordMethod::Inside)
      lim = std::min(lim, std::max(0.0, std::sqrt(x * s->rho / k) / T - amx * T));
  }
  return lim;
}

// Junction speeds by look-ahead over a bounded window (planner.hpp,
// "Look-ahead"). J[k]: the limit at the start of segment k on entry, the
// planned speed on return (J[n] = 0). The speed at the end of block k is the
// backward pass over segments k+1 .. e-1 from a stop at junction e (the
// window's end), then the forward pass from J[k]. The window is long enough
// when the pure deceleration from the stop at e (no limit on the way) is more
// than the backward pass found at k+1: then nothing beyond e can lower
// J[k+1], and the speed is the whole program's, bit for bit (min and
// sqrt(x^2 + c) commute, both rounded monotonically). When it is not, the
// window doubles (so the pass is recomputed about once per window's length
// of blocks, not every block), up to kMaxLookAhead blocks; a window of
// kMaxLookAhead / 2 or more that is still short keeps its stop (slower,
// never over a limit). Returns the largest window used, in blocks.
std::size_t windowed_junction_speeds(const std::vector<PlannedSegment>& segs, std::vector<double>& J) {
  const std::size_t n = segs.size();
  auto reach = [&](std::size_t k, double v) {  // from v at the end of segment k to its start
    return std::sqrt(v * v + 2 * segs[k].a_t * segs[k].geom.length);
  };
  // The backward pass from a stop at e, with and without the limits on the
  // way, at junctions base .. e (index j - base).
  std::vector<double> vb, free_stop;
  std::size_t base = 0, e = 0, widest = 0;
  auto pass = [&](std::size_t from, std::size_t to) {
    base = from, e = to;
    vb.assign(e - base + 1, 0.0);
    free_stop.assign(e - base + 1, 0.0);
    for (std::size_t j = e; j-- > base;) {
      vb[j - base] = std::min({J[j], segs[j].v_cap, reach(j, vb[j + 1 - base])});
      free_stop[j - base] = reach(j, free_stop[j + 1 - base]);
    }
  };
  for (std::size_t k = 0; k < n; ++k) {
    if (e < k + 1) pass(k + 1, k + 1);
    for (;;) {
      const std::size_t i = k + 1 - base;
      if (e == n || free_stop[i] > vb[i] || e - k >= kMaxLookAhead / 2) break;
      pass(k + 1, std::min({n, k + 1 + 2 * std::max<std::size_t>(e - k, 8), k + kMaxLookAhead}));
    }
    widest = std::max(widest, e - k);
    J[k + 1] = vb[k + 1 - base];
    J[k] = std::min({J[k], segs[k].v_cap, reach(k, J[k + 1])});
    J[k + 1] = std::min(J[k + 1], reach(k, J[k]));
  }
  return widest;
}

// The trapezoid of a block between its start and end speeds.
void shape_trapezoid(PlannedSegment& s, double v_start, double v_end) {
  const double L = s.geom.length, a = s.a_t;
  s.v_start = v_start;
  s.v_end = v_end;
  if (s.geom.kind == Segment::Kind::Dwell) {
    s.duration = s.geom.dwell_s;
    return;
  }
  const double v_peak = std::sqrt((2 * a * L + s.v_start * s.v_start + s.v_end * s.v_end) / 2);
  s.v_cruise = std::max({std::min(s.v_cap, v_peak), s.v_start, s.v_end});
  s.s_acc = (s.v_cruise * s.v_cruise - s.v_start * s.v_start) / (2 * a);
  const double s_dec = (s.v_cruise * s.v_cruise - s.v_end * s.v_end) / (2 * a);
  s.s_cruise = std::max(0.0, L - s.s_acc - s_dec);
  s.t_acc = (s.v_cruise - s.v_start) / a;
  s.t_dec = (s.v_cruise - s.v_end) / a;
  s.t_cruise = s.v_cruise > 0 ? s.s_cruise / s.v_cruise : 0;
  s.duration = s.t_acc + s.t_cruise + s.t_dec;
}

// Places the blocks on the time axis; returns the total time.
double schedule(std::vector<PlannedSegment>& segs, double T) {
  double t = 0;
  for (std::size_t k = 0; k < segs.size(); ++k) {
    PlannedSegment& s = segs[k];
    // After an exact stop the next block starts on a cycle boundary (the
    // axes wait at rest for the rest of the cycle), so that a sample lands
    // on the corner and no chord cuts it.
    if (k > 0 && s.v_start == 0) t = std::ceil(t / T - 1e-9) * T;
    s.t_begin = t;
    t += s.duration;
  }
  return t;
}

}  // namespace

Plan plan(const std::vector<gcode::Block>& blocks, const Config& config) {
  config.validate();
  Plan p;
  p.config = config;
  const Machine& mc = config.machine;
  const double T = config.cycle_s;
  const double eps = config.tol_mm * (1 - kTolMargin);
  const double amin = std::min({mc.amax.x, mc.amax.y, mc.amax.z});
  p.segs.reserve(blocks.size());  // no growth slack: ~470 bytes a block
  for (const auto& b : blocks) p.segs.push_back(plan_segment(b, config, eps));
  reserve_corner_acceleration(p.segs);

  // Junction limits. J[k] is the speed at the start of segment k; J[n] = 0.
  const std::size_t n = p.segs.size();
  std::vector<double> J(n + 1, 0.0);
  p.junction_tol.assign(n + 1, config.tol_mm);
  for (std::size_t k = 1; k < n; ++k) {
    const double tol = junction_tol(p.segs[k - 1], p.segs[k], config, eps);
    p.junction_tol[k] = std::max(config.tol_mm, tol / (1 - kTolMargin));
    J[k] = junction_limit(p.segs[k - 1], p.segs[k], config, tol, amin);
  }
  p.junction_limit = J;
  p.lookahead_blocks = windowed_junction_speeds(p.segs, J);
  for (std::size_t k = 0; k < n; ++k) shape_trapezoid(p.segs[k], J[k], J[k + 1]);
  const double t = schedule(p.segs, T);
  p.total_time = t;
  require(std::isfinite(t) && t / T < 1e12,
          "the program takes " + std::to_string(t) + " s, more than 10^12 cycles of " + std::to_string(T) + " s");
  return p;
}

Interpolator::Interpolator(const Plan& plan) : plan_(&plan) {
  const double T = plan.config.cycle_s;
  cycles_ = plan.segs.empty() ? 0 : static_cast<std::size_t>(std::ceil(plan.total_time / T - 1e-9));
  if (!plan.segs.empty() && cycles_ == 0) cycles_ = 1;
}

Sample Interpolator::at(std::size_t n) {
  Sample out;
  const double T = plan_->config.cycle_s;
  out.t = static_cast<double>(n) * T;
  if (n >= cycles_) {
    out.seg = static_cast<int>(plan_->segs.size()) - 1;
    const auto& last = plan_->segs.back();
    out.s = last.geom.length;
    out.p = last.geom.end;
    return out;
  }
  while (seg_ + 1 < plan_->segs.size() && out.t >= plan_->segs[seg_ + 1].t_begin) ++seg_;
  const PlannedSegment& s = plan_->segs[seg_];
  const double tl = out.t - s.t_begin;
  out.seg = static_cast<int>(seg_);
  out.s = s.s_at(tl);
  out.v = s.v_at(tl);
  // The offset suits the longer of the two chords that meet here, so that
  // each chord's ends are at least its own balanced offset out (the chord
  // error is then at most the offset, itself at most eps).
  double e = 0;
  if (s.geom.kind == Segment::Kind::Arc && out.s > 0 && out.s < s.geom.length) {  // block ends stay exact
    const double l = std::max(out.s - s.s_at(tl - T), s.s_at(tl + T) - out.s);
    e = vertex_offset(plan_->config.chord, s.rho, l);
  }
  out.p = s.geom.point(out.s, e);
  return out;
}

bool Interpolator::next(Sample& out) {
  if (plan_->segs.empty() || n_ > cycles_) return false;
  out = at(n_++);
  return true;
}

std::vector<Sample> interpolate(const Plan& plan) {
  std::vector<Sample> out;
  Interpolator it(plan);
  out.reserve(it.cycles() + 1);
  Sample s;
  while (it.next(s)) out.push_back(s);
  return out;
}

double chord_error(const Plan& plan, const Sample& a, const Sample& b) {
  if (a.seg == b.seg) {
    const Segment& g = plan.segs[a.seg].geom;
    if (g.kind != Segment::Kind::Arc) return std::max(g.distance(a.p), g.distance(b.p));
    if (!g.helix()) {
      const Vec3 nn = cross(g.u_hat, g.v_hat);
      auto uv = [&](Vec3 p) {
        const Vec3 w = p - g.origin;
        return std::array<double, 3>{dot(w, g.u_hat) - g.qc.u, dot(w, g.v_hat) - g.qc.v, dot(w, nn)};
      };
      const auto qa = uv(a.p), qb = uv(b.p);
      const double ra = std::hypot(qa[0], qa[1]), rb = std::hypot(qb[0], qb[1]);
      // Nearest approach of the chord to the centre, in the plane.
      const double du = qb[0] - qa[0], dv = qb[1] - qa[1];
      const double l2 = du * du + dv * dv;
      double t = l2 == 0 ? 0 : -(qa[0] * du + qa[1] * dv) / l2;
      t = std::clamp(t, 0.0, 1.0);
      const double rmin = std::hypot(qa[0] + t * du, qa[1] + t * dv);
      const double R = g.radius;
      const double err = std::max({std::fabs(ra - R), std::fabs(rb - R), R - rmin});
      return std::max({err, std::fabs(qa[2]), std::fabs(qb[2])});
    }
  }
  // Sampled, both ways, over every segment the chord spans. On a helix the
  // search for the nearest point is kept to the chord's own stretch of the
  // path and as much again on each side: another turn is a pitch away, so
  // the distance found is the true one (and never less).
  constexpr int kN = 16;
  double err = 0;
  for (int j = 0; j <= kN; ++j) {
    const Vec3 p = a.p + (static_cast<double>(j) / kN) * (b.p - a.p);
    double d = kInf;
    for (int k = a.seg; k <= b.seg; ++k) {
      const Segment& g = plan.segs[k].geom;
      const double s0 = k == a.seg ? a.s : 0, s1 = k == b.seg ? b.s : g.length;
      d = std::min(d, g.distance_near(p, 2 * s0 - s1 - 1e-3, 2 * s1 - s0 + 1e-3));
    }
    err = std::max(err, d);
  }
  for (int k = a.seg; k <= b.seg; ++k) {
    const Segment& g = plan.segs[k].geom;
    const double s0 = k == a.seg ? a.s : 0, s1 = k == b.seg ? b.s : g.length;
    for (int j = 0; j <= kN; ++j) {
      const Vec3 q = g.point(s0 + (s1 - s0) * j / kN);
      err = std::max(err, distance_to_segment(q, a.p, b.p));
    }
  }
  return err;
}

Analyser::Analyser(const Plan& plan) : plan_(&plan) {
  const Config& c = plan.config;
  r_.total_time_s = plan.total_time;
  for (int i = 0; i < 3; ++i) {
    r_.axes[i].vmax = c.machine.vmax[i];
    r_.axes[i].amax = c.machine.amax[i];
  }
}

void Analyser::step(const Vec3& v) {
  const double T = plan_->config.cycle_s;
  for (int i = 0; i < 3; ++i) {
    r_.axes[i].peak_v = std::max(r_.axes[i].peak_v, std::fabs(v[i]));
    r_.axes[i].peak_a = std::max(r_.axes[i].peak_a, std::fabs(v[i] - v_prev_[i]) / T);
  }
  v_prev_ = v;
}

void Analyser::add(const Sample& b) {
  if (count_++ == 0) {  // the start: no chord yet
    prev_ = b;
    return;
  }
  const Plan& plan = *plan_;
  const double T = plan.config.cycle_s;
  const Sample& a = prev_;
  const Vec3 d = b.p - a.p;
  r_.peak_feed = std::max(r_.peak_feed, norm(d) / T);
  const double err = chord_error(plan, a, b);
  if (a.seg == b.seg || plan.junction_tol.empty()) {
    r_.max_chord_error = std::max(r_.max_chord_error, err);
  } else {  // a chord across one or more corners: within their blend tolerance
    double lim = 0;
    for (int k = a.seg + 1; k <= b.seg; ++k) lim = std::max(lim, plan.junction_tol[k]);
    r_.max_blend_error = std::max(r_.max_blend_error, err);
    r_.blend_ok = r_.blend_ok && err <= lim * (1 + kLimitRelTol);
  }
  step((1.0 / T) * d);
  prev_ = b;
}

Report Analyser::report() const {
  Analyser last = *this;
  if (count_ > 0) last.step(Vec3{});  // at rest after the last chord
  Report r = last.r_;
  r.cycles = count_ == 0 ? 0 : count_ - 1;
  constexpr double kSlack = 1 + kLimitRelTol;
  r.tol_ok = r.max_chord_error <= plan_->config.tol_mm * kSlack;
  for (auto& ax : r.axes) {
    ax.v_ok = ax.peak_v <= ax.vmax * kSlack;
    ax.a_ok = ax.peak_a <= ax.amax * kSlack;
  }
  return r;
}

Report analyse(const Plan& plan, const std::vector<Sample>& samples) {
  Analyser an(plan);
  for (const Sample& s : samples) an.add(s);
  return an.report();
}

}  // namespace contour::planner
