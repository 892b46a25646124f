// Path geometry of paper B's planner: lines and arcs parameterised by path
// length, arcs through paper B's UV plane.
//
// Every arc, 2D or 3D, is interpolated in a UV plane built as in paper B,
// Section 3.2 (docs/paper-b.md):
//   - the plane normal n: for a plane arc the active plane's normal axis
//     (+Z for G17, +Y for G18, +X for G19); for a 3D arc
//     (Ps - Pc) x (Pe - Pc), turned so that its component on that axis is
//     positive (G2/G3 are judged looking down the normal axis);
//   - CCW (G3): origin Pe, U = unit(Ps - Pe); CW (G2): origin Ps,
//     U = unit(Pe - Ps); V = n x U (U turned +90 degrees in the plane);
//     Qe = (0,0), Qs = (|PePs|, 0) for CCW (Qs = (0,0), Qe = (|PePs|, 0) for
//     CW), Qc = (|PePs|/2, H), |H| = sqrt(R^2 - (|PePs|/2)^2), H < 0 when
//     the swept angle is < pi, H >= 0 otherwise;
//   - full circle: CCW V = unit(Pc - Ps), U = V turned -90 degrees about n;
//     CW U = V turned +90 degrees; origin Ps, Qs = (0,0), Qc = (0, R);
//   - a point of the arc in UV maps back as P = O + u*U + v*V (+ the helix
//     rise along n).
// R is the mean of the programmed start and end radii (they agree within
// LinuxCNC's tolerance), so the arc ends exactly at the programmed end point;
// the centre moves onto the bisector of PsPe by at most half their difference.
#pragma once

#include <string>

#include "gcode/gcode.hpp"
#include "gcode/vec3.hpp"

namespace contour::planner {

struct UV {
  double u = 0, v = 0;
};

struct Segment {
  enum class Kind { Line, Arc, Dwell };  // Dwell: at rest at start for dwell_s (0: a stop)
  Kind kind = Kind::Line;
  bool rapid = false;
  Vec3 start, end;
  double length = 0;  // path length, mm
  int line = 0;       // source line of the block
  double dwell_s = 0;       // Dwell
  bool exact_stop = false;  // G61/G61.1 (and dwells): at rest at the end
  double blend_tol = -1;    // G64 P, mm (< 0: the configured default)

  // Line.
  Vec3 dir;  // unit

  // Arc (and helix).
  Vec3 origin, u_hat, v_hat, normal;  // UV frame; normal = u_hat x v_hat for CCW frames
  UV qs, qe, qc;                       // start, end, centre in UV
  double radius = 0;                   // R in the UV plane
  double alpha_s = 0;                  // angle of Qs about Qc
  double sweep = 0;                    // swept angle, > 0, up to 2 pi
  double sigma = 1;                    // +1: counter-clockwise in UV, -1: clockwise
  Vec3 rise;                           // helix: total displacement along the normal axis
  bool full_circle = false;
  bool arc3d = false;
  double centre_shift = 0;             // |Pc (programmed) - Pc (used)|, mm

  // Point at path length s in [0, length]. For an arc, `radial_offset` moves
  // the point off the arc along the radius (paper B's chord placements).
  Vec3 point(double s, double radial_offset = 0) const;
  Vec3 tangent(double s) const;       // unit tangent at s
  double curvature_radius() const;    // R for arcs, R (1 + (rise/(R*sweep))^2) for helices; 0 for lines
  bool helix() const { return rise.x != 0 || rise.y != 0 || rise.z != 0; }
  // UV coordinates of the arc point at path length s (radial offset 0).
  UV uv_at(double s, double radial_offset = 0) const;
  // Distance from p to the path (the segment or the arc portion, clamped to
  // its ends). Exact for lines and plane arcs; helices by Newton iteration.
  double distance(const Vec3& p) const;
  // The same over the part of the path between path lengths s_lo and s_hi
  // (helices; lines and plane arcs: distance()). Never less than distance().
  double distance_near(const Vec3& p, double s_lo, double s_hi) const;

 private:
  double nearest_on_helix(const Vec3& p, double s_lo, double s_hi, int scan) const;

 public:
};

// Distance from p to the straight segment a-b.
double distance_to_segment(Vec3 p, Vec3 a, Vec3 b);

// Builds the geometry of one block. Throws std::invalid_argument for a block
// the reader should have rejected (the reader checks every case first).
Segment make_segment(const gcode::Block& b);

}  // namespace contour::planner
