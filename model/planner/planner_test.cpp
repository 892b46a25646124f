// Paper B's planner: UV frames, the 2.46 s reproduction, chord tolerance,
// per-axis limits, junction speeds, chord caps and the two-stage pulses.
#include "planner/planner.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <numbers>
#include <random>
#include <string>

#include "planner/two_stage.hpp"

namespace contour::planner {
namespace {

constexpr double kPi = std::numbers::pi;
const char* kPaper3D = "G00X50.Y0.Z0.\nG03X0.Y-47.246Z-16.366I-50J0.K0.F6000\nG00X0.Y0.Z0.\n";
const char* kPaperArcOnly = "G03X0.Y-47.246Z-16.366I-50J0.K0.F6000\n";
const char* kPaperCircle = "G03X50.Y0.I-50.J0.F6000\n";

gcode::Options at(double x, double y, double z) {
  gcode::Options o;
  o.start = {x, y, z};
  return o;
}

Plan plan_text(const char* text, const Config& c = {}, gcode::Options o = {}) {
  return plan(gcode::parse(text, o), c);
}

// Distance from p to the circle (centre c, unit normal n, radius R).
double circle_distance(Vec3 p, Vec3 c, Vec3 n, double R) {
  const Vec3 w = p - c;
  const double h = dot(w, n);
  const double r = norm(w - h * n);
  return std::hypot(r - R, h);
}

// Largest distance of the chords a->b (sampled densely, ends included) from a circle.
double max_chord_distance(const std::vector<Sample>& s, Vec3 c, Vec3 n, double R) {
  double worst = 0;
  for (std::size_t k = 1; k < s.size(); ++k)
    for (int j = 0; j <= 40; ++j) {
      const Vec3 p = s[k - 1].p + (j / 40.0) * (s[k].p - s[k - 1].p);
      worst = std::max(worst, circle_distance(p, c, n, R));
    }
  return worst;
}

// Peak |second difference| / T^2 per axis, at rest before and after.
Vec3 peak_accel(const std::vector<Sample>& s, double T) {
  Vec3 peak, vprev;
  for (std::size_t k = 1; k <= s.size(); ++k) {
    Vec3 v;
    if (k < s.size()) v = (1 / T) * (s[k].p - s[k - 1].p);
    for (int i = 0; i < 3; ++i) peak[i] = std::max(peak[i], std::fabs(v[i] - vprev[i]) / T);
    vprev = v;
  }
  return peak;
}

TEST(ChordPlacement, PaperBFigure1Geometry) {
  const double R = 50, e = 2e-5;
  // (a) ends on the circle, middle at R - e.
  double th = chord_angle(ChordMethod::Inside, R, e);
  EXPECT_NEAR(R * std::cos(th / 2), R - e, 1e-12);
  EXPECT_NEAR(chord_length(ChordMethod::Inside, R, e), 2 * R * std::sin(th / 2), 1e-10);
  // (b) ends at R + e, middle tangent (at R).
  th = chord_angle(ChordMethod::Outside, R, e);
  EXPECT_NEAR((R + e) * std::cos(th / 2), R, 1e-12);
  EXPECT_NEAR(chord_length(ChordMethod::Outside, R, e), 2 * (R + e) * std::sin(th / 2), 1e-10);
  // (c) ends at R + e, middle at R - e: the longest, 4 sqrt(R e).
  th = chord_angle(ChordMethod::InsideOutside, R, e);
  EXPECT_NEAR((R + e) * std::cos(th / 2), R - e, 1e-12);
  EXPECT_NEAR(chord_length(ChordMethod::InsideOutside, R, e), 2 * (R + e) * std::sin(th / 2), 1e-10);
  EXPECT_NEAR(chord_length(ChordMethod::InsideOutside, R, e), 0.12649, 1e-5);  // paper B (docs/papers.md): 0.1265 mm
  EXPECT_GT(chord_length(ChordMethod::InsideOutside, R, e), chord_length(ChordMethod::Outside, R, e));
  EXPECT_GT(chord_length(ChordMethod::Outside, R, e), chord_length(ChordMethod::Inside, R, e));
  EXPECT_GT(chord_angle(ChordMethod::Inside, R, e), chord_angle(ChordMethod::Outside, R, e));
  // The balanced offset at the longest chord is paper B's placement.
  EXPECT_NEAR(vertex_offset(ChordMethod::InsideOutside, R, chord_length(ChordMethod::InsideOutside, R, e)), e, 1e-15);
  EXPECT_NEAR(vertex_offset(ChordMethod::Outside, R, chord_length(ChordMethod::Outside, R, e)), e, 1e-15);
  EXPECT_EQ(vertex_offset(ChordMethod::Inside, R, 0.1), 0);
}

TEST(UVFrame, PaperB3DArc) {
  const auto blocks = gcode::parse(kPaperArcOnly, at(50, 0, 0));
  const Segment g = make_segment(blocks[0]);
  const Vec3 ps{50, 0, 0}, pe{0, -47.246, -16.366};
  // CCW: origin Pe, U from Pe towards Ps, V = n x U, n towards +Z.
  EXPECT_EQ(g.origin, pe);
  const Vec3 u = unit(ps - pe);
  EXPECT_NEAR(norm(g.u_hat - u), 0, 1e-15);
  EXPECT_GT(g.normal.z, 0);
  EXPECT_NEAR(norm(g.v_hat - cross(g.normal, g.u_hat)), 0, 1e-15);
  EXPECT_NEAR(dot(g.normal, ps - pe), 0, 1e-12);
  // Qs = (|PePs|, 0), Qc = (|PePs|/2, H), H >= 0 since the arc is 3 pi / 2.
  const double d = norm(ps - pe);
  EXPECT_NEAR(g.qs.u, d, 1e-12);
  EXPECT_EQ(g.qs.v, 0);
  EXPECT_NEAR(g.qc.u, d / 2, 1e-12);
  EXPECT_NEAR(g.qc.v, std::sqrt(g.radius * g.radius - d * d / 4), 1e-12);
  EXPECT_GT(g.qc.v, 0);
  EXPECT_NEAR(g.sweep, 3 * kPi / 2, 1e-5);
  EXPECT_NEAR(g.length, 50 * 3 * kPi / 2, 0.01);
  // The centre maps back next to the programmed (0,0,0); the end radius of
  // the block is 50.0003 (its end point is rounded), so it moves by ~0.0002.
  EXPECT_LT(g.centre_shift, 3e-4);
  // Ends exact; a quarter of the way the point is where rotating Ps by
  // +90 degrees about n puts it (independent construction).
  EXPECT_EQ(g.point(0), ps);
  EXPECT_EQ(g.point(g.length), pe);
  const Vec3 e1{1, 0, 0}, e2 = cross(g.normal, e1);
  for (double phi : {kPi / 6, kPi / 2, kPi, 4 * kPi / 3}) {
    const Vec3 want = 50 * std::cos(phi) * e1 + 50 * std::sin(phi) * e2;
    EXPECT_LT(norm(g.point(g.length * phi / g.sweep) - want), 5e-4) << phi;
  }
}

TEST(UVFrame, CwArcsAndFullCircles) {
  // G2 from (10,0) to (0,-10) about the origin: a quarter, CW, origin Ps.
  auto g = make_segment(gcode::parse("G2 X0 Y-10 I-10 J0 F60\n", at(10, 0, 0))[0]);
  EXPECT_EQ(g.origin, (Vec3{10, 0, 0}));
  EXPECT_NEAR(g.sweep, kPi / 2, 1e-12);
  EXPECT_LT(g.qc.v, 0);  // theta < pi
  EXPECT_LT(g.tangent(0).y, -0.999);
  EXPECT_LT(norm(g.point(g.length / 2) - Vec3{10 * std::cos(kPi / 4), -10 * std::sin(kPi / 4), 0}), 1e-12);
  // G2 the long way, 3 pi / 2: H >= 0.
  g = make_segment(gcode::parse("G2 X0 Y10 I-10 J0 F60\n", at(10, 0, 0))[0]);
  EXPECT_NEAR(g.sweep, 3 * kPi / 2, 1e-12);
  EXPECT_GT(g.qc.v, 0);
  // Full circles: G3 starts towards +Y, G2 towards -Y, V points to the centre.
  for (bool ccw : {true, false}) {
    g = make_segment(gcode::parse(ccw ? kPaperCircle : "G02X50.Y0.I-50.J0.F6000\n", at(50, 0, 0))[0]);
    EXPECT_TRUE(g.full_circle);
    EXPECT_NEAR(g.sweep, 2 * kPi, 0);
    EXPECT_NEAR(g.length, 100 * kPi, 1e-9);
    EXPECT_NEAR(norm(g.v_hat - Vec3{-1, 0, 0}), 0, 1e-15);
    EXPECT_NEAR(g.tangent(0).y, ccw ? 1 : -1, 1e-12);
    EXPECT_LT(norm(g.point(g.length / 4) - Vec3{0, ccw ? 50.0 : -50.0, 0}), 1e-9);
    EXPECT_EQ(g.point(g.length), (Vec3{50, 0, 0}));
  }
  // Helix: the normal axis rises linearly with the path.
  g = make_segment(gcode::parse("G3 X-10 Y0 Z5 I-10 J0 F60\n", at(10, 0, 0))[0]);
  EXPECT_TRUE(g.helix());
  EXPECT_NEAR(g.length, std::hypot(10 * kPi, 5), 1e-12);
  EXPECT_NEAR(g.point(g.length / 2).z, 2.5, 1e-12);
  EXPECT_NEAR(g.point(g.length / 2).y, 10, 1e-12);
}

TEST(PaperB, ThreeDArcTakes2_46Seconds) {
  Config c;  // paper B's conditions are the defaults
  EXPECT_EQ(c.cycle_s, 1e-3);
  EXPECT_EQ(c.tol_mm, 2e-5);
  EXPECT_NEAR(c.machine.amax.x * 3600, 3528000, 1e-6);
  const Plan p = plan_text(kPaperArcOnly, c, at(50, 0, 0));
  ASSERT_EQ(p.segs.size(), 1u);
  EXPECT_NEAR(p.total_time, 2.46, 0.01);
  EXPECT_EQ(p.segs[0].cap, Cap::Feed);  // 6000 mm/min is not capped by the chord
  const auto samples = interpolate(p);
  EXPECT_EQ(samples.size() - 1, static_cast<std::size_t>(std::ceil(p.total_time / 1e-3)));
  EXPECT_NEAR((samples.size() - 1) * 1e-3, 2.46, 0.01);
  // In the whole program (rapid in, arc, rapid out) the arc block is the same.
  const Plan full = plan_text(kPaper3D, c);
  ASSERT_EQ(full.segs.size(), 3u);
  EXPECT_NEAR(full.segs[1].duration, 2.46, 0.01);
  EXPECT_EQ(full.segs[1].v_start, 0);  // 90 degree corners: exact stops
  EXPECT_EQ(full.segs[1].v_end, 0);
  // After a stop the next block starts on a cycle: a sample sits exactly on
  // each corner, so no chord cuts it.
  const auto fs = interpolate(full);
  int corners = 0;
  for (const auto& x : fs) corners += x.p == Vec3{50, 0, 0} || x.p == Vec3{0, -47.246, -16.366};
  EXPECT_GE(corners, 2);
  EXPECT_NEAR(std::remainder(full.segs[1].t_begin / 1e-3, 1.0), 0.0, 1e-9);
  EXPECT_NEAR(std::remainder(full.segs[2].t_begin / 1e-3, 1.0), 0.0, 1e-9);
}

TEST(PaperB, EveryChordWithinToleranceOfTheTrueArc) {
  // 3D arc. The true arc passes through Ps and Pe with the mean radius and
  // its centre on their bisector in the plane of (Ps, Pc, Pe), next to Pc.
  {
    const Plan p = plan_text(kPaperArcOnly, {}, at(50, 0, 0));
    const auto s = interpolate(p);
    const Vec3 ps{50, 0, 0}, pe{0, -47.246, -16.366}, pc{0, 0, 0};
    const double R = (norm(ps - pc) + norm(pe - pc)) / 2;
    Vec3 n = unit(cross(ps - pc, pe - pc));
    if (n.z < 0) n = -1.0 * n;
    const Vec3 m = 0.5 * (ps + pe), along = unit(pe - ps);
    Vec3 w = (pc - m) - dot(pc - m, along) * along;
    w = unit(w);
    const Vec3 c = m + std::sqrt(R * R - dot(pe - ps, pe - ps) / 4) * w;
    EXPECT_LT(norm(c - pc), 3e-4);
    const double worst = max_chord_distance(s, c, n, R);
    // At 100 mm/s the chord is 0.1 mm, under the longest (0.1265 mm): with
    // the ends at R + e and the middle at R - e, e = 0.1^2 / (16 R).
    EXPECT_LE(worst, 2e-5);
    EXPECT_NEAR(worst, 0.01 / (16 * 50), 0.01 * 0.01 / (16 * 50));
    const Report r = analyse(p, s);
    EXPECT_TRUE(r.tol_ok);
    EXPECT_NEAR(r.max_chord_error, worst, 1e-9);
  }
  // The R 50 full circle from (50, 0), CCW.
  {
    const Plan p = plan_text(kPaperCircle, {}, at(50, 0, 0));
    const auto s = interpolate(p);
    EXPECT_NEAR(p.total_time, 100 * kPi / 100 + 100 / 980.0, 0.01);
    const double worst = max_chord_distance(s, {0, 0, 0}, {0, 0, 1}, 50);
    EXPECT_LE(worst, 2e-5);
    EXPECT_NEAR(worst, 0.01 / (16 * 50), 0.01 * 0.01 / (16 * 50));
    EXPECT_EQ(s.back().p, (Vec3{50, 0, 0}));
  }
}

TEST(PaperB, ThreeDArcsInEveryPlaneAndSense) {
  // A circle of R 30 about (1, 2, 3) on a plane with normal (1, 2, 3)/|.|,
  // from angle 0 to angle 2 rad. G3 (CCW about the normal, which points
  // along +X, +Y and +Z alike) sweeps 2 rad; G2 sweeps 2 pi - 2.
  const Vec3 c{1, 2, 3}, n = unit(Vec3{1, 2, 3});
  const Vec3 e1 = unit(cross(n, Vec3{0, 0, 1})), e2 = cross(n, e1);
  const double R = 30, phi = 2;
  const Vec3 ps = c + R * e1, pe = c + R * std::cos(phi) * e1 + R * std::sin(phi) * e2;
  for (const char* plane : {"G17", "G18", "G19"})
    for (int g : {2, 3}) {
      char prog[256];
      std::snprintf(prog, sizeof prog, "%s G%d X%.9f Y%.9f Z%.9f I%.9f J%.9f K%.9f F3000\n", plane, g, pe.x, pe.y,
                    pe.z, c.x - ps.x, c.y - ps.y, c.z - ps.z);
      Config cfg;
      cfg.tol_mm = 1e-3;
      const Plan p = plan_text(prog, cfg, at(ps.x, ps.y, ps.z));
      ASSERT_EQ(p.segs.size(), 1u);
      const Segment& seg = p.segs[0].geom;
      EXPECT_TRUE(seg.arc3d);
      EXPECT_NEAR(seg.length, R * (g == 3 ? phi : 2 * kPi - phi), 1e-6) << prog;
      const auto s = interpolate(p);
      EXPECT_LE(max_chord_distance(s, c, n, R), 1e-3 + 1e-6) << prog;
      // The sense: a quarter of the way along, the point is at angle
      // +-(sweep / 4) from Ps about n.
      const double q = (g == 3 ? 1 : -1) * seg.sweep / 4;
      const Vec3 want = c + R * std::cos(q) * e1 + R * std::sin(q) * e2;
      EXPECT_LT(norm(seg.point(seg.length / 4) - want), 1e-6) << prog;
      const Report r = analyse(p, s);
      EXPECT_TRUE(r.tol_ok && r.axes[0].a_ok && r.axes[1].a_ok && r.axes[2].a_ok) << prog;
    }
}

TEST(PaperB, PerAxisLimitsNeverExceeded) {
  const char* programs[] = {
      kPaper3D,
      kPaperCircle,
      // Lines, corners, a tangent line-arc-line, a helix, a G18 arc, rapids.
      "G0 X10 Y5\nG1 X40 Y5 F9000\nG3 X50 Y15 I0 J10\nG1 X50 Y40\nG1 X30 Y60 Z-3\n"
      "G2 X10 Y60 Z-8 I-10 J0\nG18 G3 X0 Z-18 I-10 K0\nG0 X0 Y0 Z0\n",
      // A gentle polyline (small corners keep speed) at a loose tolerance.
      "G1 X10 Y1 F6000\nX20 Y0\nX30 Y1\nX40 Y0\nX50 Y1\n",
  };
  for (double tol : {2e-5, 0.01}) {
    for (const char* prog : programs) {
      Config c;
      c.tol_mm = tol;
      c.machine.vmax = {120, 80, 50};
      c.machine.amax = {980, 700, 500};
      const Plan p = plan_text(prog, c, at(50, 0, 0));
      const auto s = interpolate(p);
      const Vec3 a = peak_accel(s, c.cycle_s);
      const Report r = analyse(p, s);
      for (int i = 0; i < 3; ++i) {
        EXPECT_LE(a[i], c.machine.amax[i] * (1 + 1e-9)) << "axis " << i << " tol " << tol << "\n" << prog;
        EXPECT_LE(r.axes[i].peak_v, c.machine.vmax[i] * (1 + 1e-9)) << "axis " << i << "\n" << prog;
        EXPECT_TRUE(r.axes[i].a_ok && r.axes[i].v_ok);
      }
      EXPECT_TRUE(r.tol_ok) << "max chord error " << r.max_chord_error << " tol " << tol << "\n" << prog;
    }
  }
}

// Random chains of short lines with small and large turns, tangent arcs
// (CW and CCW) and Z moves: tolerance and every axis limit hold.
TEST(PaperB, RandomProgramsRespectEveryLimit) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> U(-1, 1);
  int runs = 0;
  for (int trial = 0; trial < 60; ++trial) {
    std::string prog = "G1 F" + std::to_string(1000 + 9000 * (U(rng) + 1) / 2) + "\n";
    double x = 0, y = 0, z = 0, ang = 0;
    const int n = 5 + trial % 40;
    const double seglen = trial % 3 == 0 ? 0.05 : (trial % 3 == 1 ? 0.5 : 5);
    char b[200];
    for (int i = 0; i < n; ++i) {
      ang += U(rng) * (trial % 2 ? 0.05 : 0.6);
      if (i % 7 == 3) {  // an arc tangent to the previous line
        const double R = 1 + 10 * (U(rng) + 1), sweep = 0.3 + (U(rng) + 1);
        const int sg = U(rng) > 0 ? 1 : -1;
        const double cx = x - sg * R * std::sin(ang), cy = y + sg * R * std::cos(ang);
        const double a1 = std::atan2(y - cy, x - cx) + sg * sweep;
        const double ex = cx + R * std::cos(a1), ey = cy + R * std::sin(a1);
        std::snprintf(b, sizeof b, "G%d X%.6f Y%.6f I%.6f J%.6f\n", sg > 0 ? 3 : 2, ex, ey, cx - x, cy - y);
        prog += b;
        x = ex, y = ey, ang += sg * sweep;
        continue;
      }
      const double L = seglen * (0.2 + (U(rng) + 1));
      x += L * std::cos(ang), y += L * std::sin(ang), z += 0.1 * U(rng) * L;
      std::snprintf(b, sizeof b, "G1 X%.6f Y%.6f Z%.6f\n", x, y, z);
      prog += b;
    }
    for (double tol : {2e-5, 1e-3, 0.01}) {
      Config c;
      c.tol_mm = tol;
      c.machine.vmax = {120, 80, 50};
      c.machine.amax = {980, 700, 500};
      const Plan p = plan_text(prog.c_str(), c);
      const auto s = interpolate(p);
      const Vec3 a = peak_accel(s, c.cycle_s);
      const Report r = analyse(p, s);
      for (int i = 0; i < 3; ++i) {
        ASSERT_LE(a[i], c.machine.amax[i] * (1 + 1e-9)) << "trial " << trial << " axis " << i << "\n" << prog;
        ASSERT_TRUE(r.axes[i].v_ok) << "trial " << trial << " axis " << i << "\n" << prog;
      }
      ASSERT_TRUE(r.tol_ok) << "trial " << trial << " error " << r.max_chord_error << " tol " << tol << "\n" << prog;
      ASSERT_TRUE(r.blend_ok) << "trial " << trial << " blend error " << r.max_blend_error << "\n" << prog;
      ++runs;
    }
  }
  EXPECT_EQ(runs, 180);
}

// A limit counts as exceeded only beyond kLimitRelTol (1e-6) relative: an
// acceleration above the limit by 1e-8 relative (rounding, as measured on
// real programs) is within it; 1e-5 above is an excess.
TEST(Verdict, LimitExceededOnlyBeyondTheStatedTolerance) {
  Config c;
  const Plan p = plan_text("G1 X10 F600\n", c);
  const double T = c.cycle_s, A = c.machine.amax.x;
  auto report_for = [&](double rel) {
    std::vector<Sample> s(4);
    for (int n = 0; n < 4; ++n) s[n].t = n * T, s[n].seg = 0;
    // At rest, one cycle at acceleration A (1 + rel), then back at rest.
    s[2].p = {A * (1 + rel) * T * T, 0, 0};
    s[3].p = s[2].p;
    s[2].s = s[3].s = s[2].p.x;
    return analyse(p, s);
  };
  EXPECT_TRUE(report_for(1e-8).axes[0].a_ok);
  EXPECT_TRUE(report_for(0.9e-6).axes[0].a_ok);
  EXPECT_FALSE(report_for(1e-5).axes[0].a_ok);
  EXPECT_GT(kLimitRelTol, 4e-8);
  EXPECT_LE(kLimitRelTol, 1e-6);
}

// G4 P: the planner comes to rest, waits P seconds at the point, goes on.
TEST(Dwell, ComesToRestAndWaits) {
  const Plan with = plan_text("G1 X10 F600\nG4 P0.5\nG1 X20\n");
  const Plan without = plan_text("G1 X10 F600\nG1 X20\n");
  ASSERT_EQ(with.segs.size(), 3u);
  EXPECT_EQ(with.segs[0].v_end, 0);
  EXPECT_EQ(with.segs[2].v_start, 0);
  EXPECT_DOUBLE_EQ(with.segs[1].duration, 0.5);
  EXPECT_GT(without.segs[0].v_end, 0);  // collinear: no stop without the dwell
  EXPECT_GE(with.total_time, without.total_time + 0.5);
  // The samples stand at X10 for the whole dwell.
  int at_rest = 0;
  for (const Sample& s : interpolate(with))
    if (std::fabs(s.p.x - 10) < 1e-12) ++at_rest;
  EXPECT_GE(at_rest, 500);
  EXPECT_LE(at_rest, 502);
}

// G61: exact stop at the end of every block, even between collinear lines.
TEST(PathControl, ExactStopStopsAtEveryCorner) {
  const Plan p = plan_text("G61 G1 X10 F6000\nX20\nX30\n");
  for (const auto& s : p.segs) EXPECT_EQ(s.v_end, 0);
  const Plan b = plan_text("G64 G1 X10 F6000\nX20\nX30\n");
  EXPECT_GT(b.segs[0].v_end, 0);
}

// The figure: 1000 G1 segments on a circle of R 50 mm at F3000,
// 0.1 g, G64 P0.01 plan within 1.1 x the time of the same circle as one G2
// block; every limit holds and every corner chord is within 0.01 mm. In G61
// every corner is a stop.
std::string polyline_circle(const char* mode, int n) {
  std::string prog = std::string(mode) + " G0 X50 Y0\nG1 F3000\n";
  char b[80];
  for (int k = 1; k <= n; ++k) {
    const double a = 2 * kPi * k / n;
    std::snprintf(b, sizeof b, "X%.4f Y%.4f\n", 50 * std::cos(a), 50 * std::sin(a));
    prog += b;
  }
  return prog;
}

TEST(Blending, PolylineCircleRunsAtTheFeed) {
  const Plan arc = plan_text("G0 X50 Y0\nG2 X50 Y0 I-50 J0 F3000\n");
  const Plan blended = plan_text(polyline_circle("G64 P0.01", 1000).c_str());
  const double t_arc = arc.segs[1].duration;
  double t_lines = 0;
  for (std::size_t k = 1; k < blended.segs.size(); ++k) t_lines += blended.segs[k].duration;
  EXPECT_LE(t_lines, 1.1 * t_arc) << t_lines << " s against " << t_arc << " s";
  const Report r = analyse(blended, interpolate(blended));
  EXPECT_TRUE(r.blend_ok) << r.max_blend_error;
  EXPECT_LE(r.max_blend_error, 0.01);
  EXPECT_TRUE(r.tol_ok);
  for (const auto& ax : r.axes) EXPECT_TRUE(ax.v_ok && ax.a_ok) << ax.peak_a;
  int stops = 0;
  for (std::size_t k = 2; k < blended.segs.size(); ++k) stops += blended.segs[k].v_start == 0;
  EXPECT_EQ(stops, 0);
  // G61: the same program stops at every corner, and takes far longer.
  const Plan exact = plan_text(polyline_circle("G61", 1000).c_str());
  for (std::size_t k = 1; k < exact.segs.size(); ++k) ASSERT_EQ(exact.segs[k].v_end, 0) << k;
  EXPECT_GT(exact.total_time, 5 * blended.total_time);
}

// The blend tolerance bounds the corner chord: a 1 degree corner at 6000
// mm/min cuts at most P (measured), and with a smaller P it goes slower (at
// P 1e-3 the per-axis rule decides, ~28 mm/s; below, the tolerance rule).
// Sharp corners are decided by the per-axis rule: 90 degrees at 0.49 mm/s.
TEST(Blending, CornerChordWithinP) {
  double v_prev = 1e9;
  for (double P : {1e-3, 1e-4, 1e-5}) {
    Config c;
    c.blend_tol_mm = P;
    const Plan p = plan_text("G1 X20 F6000\nG1 X40 Y0.3491\n", c);
    const Report r = analyse(p, interpolate(p));
    EXPECT_TRUE(r.blend_ok) << P << " " << r.max_blend_error;
    EXPECT_LE(r.max_blend_error, P);
    EXPECT_LT(p.segs[0].v_end, v_prev);
    EXPECT_GT(p.segs[0].v_end, 0);
    v_prev = p.segs[0].v_end;
    for (const auto& ax : r.axes) EXPECT_TRUE(ax.a_ok) << P << " " << ax.peak_a;
  }
}

TEST(Junctions, CollinearLinesKeepTheFeed) {
  const Plan p = plan_text("G1 X10 F6000\nX20\nX30\n");
  ASSERT_EQ(p.segs.size(), 3u);
  EXPECT_DOUBLE_EQ(p.segs[0].v_end, 100);
  EXPECT_DOUBLE_EQ(p.segs[1].v_start, 100);
  EXPECT_DOUBLE_EQ(p.segs[1].v_end, 100);
}

TEST(Junctions, PerAxisAndToleranceRules) {
  // Directions (1, 0.1) then (1, -0.1): X's component does not change, Y's
  // changes by 2 * 0.1/sqrt(1.01). Lines with a blended corner use a_t =
  // A / 0.995... / 2 (half kept for the corner), Y's share of it is a_t * 0.0995...
  const double dy = 0.1 / std::sqrt(1.01), dx = 1 / std::sqrt(1.01);
  const double at = 0.5 * 980 / dx, use_y = at * dy;
  const double per_axis = (980 - use_y) * 1e-3 / (2 * dy);  // ~4.43 mm/s
  const double delta = 2 * std::atan(0.1);
  const char* prog = "G1 X10 Y1 F6000\nX20 Y0\n";
  {
    Config c;
    c.blend_tol_mm = 0.01;  // tolerance rule ~200 mm/s: the per-axis rule decides
    const Plan p = plan_text(prog, c);
    EXPECT_NEAR(p.junction_limit[1], per_axis, 1e-9);
    EXPECT_NEAR(p.segs[0].v_end, per_axis, 1e-9);
    EXPECT_NEAR(p.segs[1].v_start, per_axis, 1e-9);
  }
  {
    Config c;
    c.blend_tol_mm = 1e-4;  // tolerance rule ~1.02 mm/s decides
    const double eps = 1e-4 * (1 - 1e-3);
    const double tol_rule = 2 * eps / std::sin(delta / 2) / 1e-3 - at * 1e-3;
    EXPECT_LT(tol_rule, per_axis);
    const Plan p = plan_text(prog, c);
    EXPECT_NEAR(p.junction_limit[1], tol_rule, 1e-9);
    EXPECT_NEAR(p.segs[1].v_start, tol_rule, 1e-9);
  }
  {
    // With a blend tolerance of paper B's 0.02 um, or in G61, the corner is an exact stop.
    Config c;
    c.blend_tol_mm = 2e-5;
    EXPECT_EQ(plan_text(prog, c).segs[0].v_end, 0);
    EXPECT_EQ(plan_text((std::string("G61 ") + prog).c_str()).segs[0].v_end, 0);
  }
}

TEST(Junctions, LookAheadLimitsByDistance) {
  // A 0.1 mm block between two corners (stops): it cannot reach 100 mm/s.
  const Plan p = plan_text("G1 X10 F6000\nY0.1\nX20\n");
  const double a = 980;
  EXPECT_LE(p.segs[1].v_cruise, std::sqrt(a * 0.1) + 1e-9);  // triangle from 0 to 0 over 0.1 mm
  // Look-ahead across blocks: collinear short blocks reach full speed.
  const Plan q = plan_text("G1 X1 F6000\nX2\nX3\nX4\nX5\nX6\nX7\nX8\nX9\nX30\n");
  double vmax = 0;
  for (const auto& s : q.segs) {
    vmax = std::max(vmax, s.v_cruise);
    EXPECT_LE(s.v_start * s.v_start, s.v_end * s.v_end + 2 * s.a_t * s.geom.length + 1e-9);
    EXPECT_LE(s.v_end * s.v_end, s.v_start * s.v_start + 2 * s.a_t * s.geom.length + 1e-9);
  }
  EXPECT_DOUBLE_EQ(vmax, 100);
  EXPECT_NEAR(q.segs[6].v_start, 100, 1e-9);  // 100^2 / (2 * 980) = 5.1 mm to reach it
}

// A long program: CAM polylines of short G1 segments (straight runs of 10 um
// ones, so that the stopping distance spans a hundred blocks and more), long
// fast lines, rapids, arcs and G61 stretches.
std::string long_mixed_program(int blocks) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  std::string t = "G21 G90 G17 G64 P0.01\nG1 F3000\n";
  double x = 0, y = 0, h = 0;
  char b[128];
  for (int k = 0; k < blocks; ++k) {
    const int what = static_cast<int>(rng() % 100);
    if (what < 2) {  // a long fast line
      x += 100 * u(rng);
      std::snprintf(b, sizeof b, "G1 X%.4f Y%.4f F9000\nF3000\n", x, y);
    } else if (what < 3) {
      x += 20 * u(rng), y += 20 * u(rng);
      std::snprintf(b, sizeof b, "G0 X%.4f Y%.4f\nG1\n", x, y);
    } else if (what < 4) {
      std::snprintf(b, sizeof b, "G2 X%.4f Y%.4f I1 J0\nG1\n", x + 2, y);
      x += 2;
    } else if (what < 5) {
      std::snprintf(b, sizeof b, "G%d\n", rng() % 2 ? 61 : 64);
    } else if (what < 7) {  // 300 blocks straight on, 10 um each: a stop spans ~130
      b[0] = 0;
      for (int j = 0; j < 300; ++j, ++k) {
        char l[64];
        x += 0.01 * std::cos(h), y += 0.01 * std::sin(h);
        std::snprintf(l, sizeof l, "X%.4f Y%.4f\n", x, y);
        t += l;
      }
    } else {
      h += 0.05 * u(rng);
      x += 0.2 * std::cos(h), y += 0.2 * std::sin(h);
      std::snprintf(b, sizeof b, "X%.4f Y%.4f\n", x, y);
    }
    t += b;
  }
  t += "G64 P0.01\n";  // the end: blended blocks up to the final stop
  for (int j = 0; j < 50; ++j) {
    char l[64];
    x += 0.2, y += 0.002 * (j % 2);
    std::snprintf(l, sizeof l, "X%.4f Y%.4f\n", x, y);
    t += l;
  }
  return t;
}

// The oracle: the whole program's backward and forward passes over the
// junction limits (written here, apart from the planner's windowed ones).
// Returns the number of blocks whose planned speeds differ from it.
std::size_t speeds_unlike_whole_program(const Plan& p) {
  const std::size_t n = p.segs.size();
  std::vector<double> J = p.junction_limit;  // J[n] = 0
  for (std::size_t k = n; k-- > 0;) {
    const auto& s = p.segs[k];
    J[k] = std::min(std::min(J[k], s.v_cap), std::sqrt(J[k + 1] * J[k + 1] + 2 * s.a_t * s.geom.length));
  }
  for (std::size_t k = 0; k < n; ++k) {
    const auto& s = p.segs[k];
    J[k + 1] = std::min(J[k + 1], std::sqrt(J[k] * J[k] + 2 * s.a_t * s.geom.length));
  }
  std::size_t differ = 0;
  for (std::size_t k = 0; k < n; ++k) differ += p.segs[k].v_start != J[k] || p.segs[k].v_end != J[k + 1];
  return differ;
}

TEST(LookAhead, WindowedPlanEqualsWholeProgram) {
  const std::string text = long_mixed_program(40000);
  const Plan p = plan_text(text.c_str());
  const std::size_t n = p.segs.size();
  ASSERT_GT(n, 30000u);
  EXPECT_EQ(speeds_unlike_whole_program(p), 0u) << "blocks whose windowed speeds are not the whole program's";
  // The window did look ahead (stopping distances over many 10 um blocks),
  // and stayed far short of the program.
  EXPECT_GT(p.lookahead_blocks, 100u);
  EXPECT_LT(p.lookahead_blocks, n / 4);
}

// 1 um lines straight on at F9000: a stop spans ~11,500 blocks; the window
// grows that far (by doubling) and the plan is still the whole program's.
TEST(LookAhead, LongWindowOverTinyBlocks) {
  std::string text = "G21 G90 G64 P0.01\nG1 F9000\n";
  char l[64];
  for (int k = 1; k <= 30000; ++k) {
    std::snprintf(l, sizeof l, "X%.4f\n", k * 0.001);
    text += l;
  }
  const Plan p = plan_text(text.c_str());
  EXPECT_EQ(speeds_unlike_whole_program(p), 0u);
  EXPECT_GT(p.lookahead_blocks, 11000u);
  EXPECT_NEAR(p.segs[15000].v_end, 150.0, 1e-3);  // cruising at F9000 in the middle
}

TEST(ChordCap, FeedCappedByEachPlacement) {
  for (ChordMethod m : {ChordMethod::Inside, ChordMethod::Outside, ChordMethod::InsideOutside}) {
    Config c;
    c.chord = m;
    const Plan p = plan_text("G03X50.Y0.I-50.J0.F12000\n", c, at(50, 0, 0));
    const double cap = chord_length(m, 50, 2e-5 * (1 - 1e-3)) / 1e-3;
    EXPECT_EQ(p.segs[0].cap, Cap::Chord) << chord_name(m);
    EXPECT_NEAR(p.segs[0].v_cap, cap, 1e-9);
    const auto s = interpolate(p);
    const double worst = max_chord_distance(s, {0, 0, 0}, {0, 0, 1}, 50);
    EXPECT_LE(worst, 2e-5) << chord_name(m);
    EXPECT_GT(worst, 0.9 * 2e-5) << chord_name(m);
  }
}

TEST(ChordCap, CentripetalCap) {
  // R 1 mm at 6000 mm/min: v^2/R = 10000 > sqrt(3)/2 * A_plane.
  Config c;
  c.tol_mm = 0.001;
  const Plan p = plan_text("G3 X1 Y0 I-1 J0 F6000\n", c, at(1, 0, 0));
  EXPECT_EQ(p.segs[0].cap, Cap::Centripetal);
  EXPECT_NEAR(p.segs[0].v_cap * p.segs[0].v_cap / 1.0, std::sqrt(3.0) / 2 * 980 * 0.99, 1e-6);
}

// --pulses follows the blended path: the pulses of a blended polyline (a
// 200-gon, G64 P0.01) stay within P + sqrt(3) steps of the path and end on
// the end, and no cycle between the first and the last pulse is idle (the
// axes never stop at a corner; in G61 they stop at every one).
struct PulseWalk {
  std::int64_t x = 0, y = 0, z = 0;
  double worst = 0;        // largest distance of a pulse position from the path, mm
  std::size_t idle = 0;    // cycles without a step between the first and the last moving one
};

PulseWalk walk_pulses(const Plan& p) {
  const double spm = 1000, T = 1e-3;
  const auto samples = interpolate(p);
  const auto chords = chords_in_steps(samples, spm);
  PulseWalk w;
  w.x = std::llround(samples[0].p.x * spm), w.y = std::llround(samples[0].p.y * spm);
  w.z = std::llround(samples[0].p.z * spm);
  std::size_t first = chords.size(), last = 0;
  for (std::size_t n = 0; n < chords.size(); ++n)
    if (chords[n].dx || chords[n].dy || chords[n].dz) first = std::min(first, n), last = n;
  for (std::size_t n = first; n <= last && n < chords.size(); ++n)
    w.idle += !(chords[n].dx || chords[n].dy || chords[n].dz);
  for (const auto& tp : two_stage_model(chords, T)) {
    (tp.pulse.axis == Axis::X ? w.x : tp.pulse.axis == Axis::Y ? w.y : w.z) += tp.pulse.sign;
    const std::size_t n = std::min(chords.size() - 1, static_cast<std::size_t>(std::ceil(tp.t / T - 1e-9)) - 1);
    const Vec3 pos{w.x / spm, w.y / spm, w.z / spm};
    double d = 1e9;
    for (int k = samples[n].seg; k <= samples[n + 1].seg; ++k) d = std::min(d, p.segs[k].geom.distance(pos));
    w.worst = std::max(w.worst, d);
  }
  return w;
}

TEST(TwoStage, PulsePathFollowsTheBlendedPath) {
  // Start on the circle, at rest: the first block is the first chord.
  const std::string blended = polyline_circle("G64 P0.01", 200).substr(std::strlen("G64 P0.01 G0 X50 Y0\n"));
  const std::string exact = polyline_circle("G61", 200).substr(std::strlen("G61 G0 X50 Y0\n"));
  const Plan p = plan_text(("G64 P0.01" + blended).c_str(), {}, at(50, 0, 0));
  const Plan e = plan_text(("G61" + exact).c_str(), {}, at(50, 0, 0));
  for (std::size_t k = 1; k < p.segs.size(); ++k) EXPECT_GT(p.segs[k].v_start, 0);
  const PulseWalk w = walk_pulses(p);
  EXPECT_EQ(w.x, 50000);
  EXPECT_LE(std::llabs(w.y), 1);
  EXPECT_LE(w.worst, 0.01 + std::sqrt(3.0) / 1000);
  EXPECT_EQ(w.idle, 0u);
  EXPECT_GE(walk_pulses(e).idle, 199u);  // G61: at rest at every corner
}

TEST(TwoStage, PulsePathWithinToleranceAndOnePulse) {
  const Plan p = plan_text(kPaperArcOnly, {}, at(50, 0, 0));
  const auto s = interpolate(p);
  const double spm = 1000;  // 1 um per step
  const auto chords = chords_in_steps(s, spm);
  ASSERT_EQ(chords.size(), s.size() - 1);
  const auto pulses = two_stage_model(chords, 1e-3);
  // Every chord's pulses, in order and time, and the end point exact.
  std::int64_t x = std::llround(50 * spm), y = 0, z = 0;
  std::size_t k = 0;
  double worst = 0, t_prev = 0;
  const Segment& g = p.segs[0].geom;
  std::int64_t cx = x, cy = y, cz = z;  // start of the current chord
  for (std::size_t n = 0; n < chords.size(); ++n) {
    const auto& c = chords[n];
    const std::size_t count = std::llabs(c.dx) + std::llabs(c.dy) + std::llabs(c.dz);
    for (std::size_t j = 0; j < count; ++j, ++k) {
      ASSERT_LT(k, pulses.size());
      const auto& tp = pulses[k];
      ASSERT_GT(tp.t, n * 1e-3 - 1e-12);
      ASSERT_LE(tp.t, (n + 1) * 1e-3 + 1e-12);
      ASSERT_GE(tp.t, t_prev);
      t_prev = tp.t;
      (tp.pulse.axis == Axis::X ? x : tp.pulse.axis == Axis::Y ? y : z) += tp.pulse.sign;
      const Vec3 pos{x / spm, y / spm, z / spm};
      worst = std::max(worst, g.distance(pos));
      // Within sqrt(3)/2 step of the chord in steps (Linear3's bound).
      const Vec3 a{double(cx), double(cy), double(cz)}, d{double(c.dx), double(c.dy), double(c.dz)};
      const Vec3 q{double(x), double(y), double(z)};
      const double l2 = dot(d, d);
      const double t = std::clamp(dot(q - a, d) / l2, 0.0, 1.0);
      ASSERT_LE(norm(q - (a + t * d)), std::sqrt(3.0) / 2 + 1e-9);
    }
    cx += c.dx, cy += c.dy, cz += c.dz;
    ASSERT_EQ(x, cx);
    ASSERT_EQ(y, cy);
    ASSERT_EQ(z, cz);
  }
  EXPECT_EQ(k, pulses.size());
  EXPECT_EQ(x, 0);
  EXPECT_EQ(y, std::llround(-47.246 * spm));
  EXPECT_EQ(z, std::llround(-16.366 * spm));
  // Ideal path to pulse path: tolerance + rounding of the chord ends
  // (sqrt(3)/2 step) + Linear3 (sqrt(3)/2 step).
  EXPECT_LE(worst, 2e-5 + std::sqrt(3.0) / spm);
  EXPECT_GT(worst, 0.3 / spm);  // the bound is not vacuous
  EXPECT_EQ(pulse_stages().count("model"), 1u);
}

}  // namespace
}  // namespace contour::planner
