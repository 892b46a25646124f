// Paper B's planner: pre-interpolation linear acc/dec on the path length,
// and real-time chord interpolation, one chord per control cycle.
//
// Planning (docs/paper-b.md, "Planner"):
//   - each block is a Segment (path.hpp) with a cruise cap v_cap and a
//     constant tangential acceleration a_t (trapezoidal velocity, "linear
//     acc/dec"), chosen so that no axis exceeds its velocity or
//     acceleration limit anywhere on the block:
//       line:  v_cap = min(F, min_i V_i/|d_i|),  a_t = min_i A_i/|d_i|;
//       arc:   p_i = |projection of axis i on the arc plane|,
//              A_plane = (1 - margin) min_i A_i/p_i,
//              v_cap = min(F, min_i V_i/p_i, chord/T, sqrt(k_n A_plane rho)),
//              a_t = sqrt(A_plane^2 - (v_cap^2/rho)^2)
//       (chord: the longest chord of the selected placement (a), (b) or (c)
//       for the tolerance; k_n = sqrt(3)/2 bounds the centripetal share so
//       that a_t >= A_plane/2; helices use a per-axis sum instead of the
//       plane bound);
//   - junction speeds by look-ahead over the whole program: a limit per
//     junction (below), then a backward and a forward pass so that every
//     block can reach its end speed: v_start^2 <= v_end^2 + 2 a_t L;
//   - junction limit (this project's "cycle corner" rule, for a controller
//     that samples the path every cycle T): with unit tangents T1, T2 and
//     the angle delta between them,
//       tolerance: the chord that cuts the corner within one cycle stays
//         within eps:  (v + a T) T <= 2 eps / sin(delta/2);
//       per axis: the one-cycle velocity step at the corner, v |T2_i - T1_i|
//         / T, plus the blocks' own acceleration on that axis stays within
//         A_i;
//       into or out of an arc: the first chord is an inside chord ((a)), and
//         the radial vertex offset appears smoothly (<= 0.5 % of A).
// Blending (path control, G61 / G64): a corner between two feed moves
// (G1 G2 G3) whose first block is in G64 is passed at the junction limit
// computed with the blend tolerance P (G64 P, else Config::blend_tol_mm)
// in place of eps: the chord that cuts the corner stays within P of it
// (the tolerance rule), each axis' velocity step within its acceleration
// (the per-axis rule), for which feed lines with such a corner keep
// kCornerShare = 1/2 of their axes' acceleration. A corner after a G61 /
// G61.1 block, at a rapid (G0) or at a dwell or stop is an exact stop (as is
// any corner whose tolerance rule gives 0).
// Look-ahead: a block's end speed is planned from a window of the blocks
// after it, ending in a stop, that grows until the stop's pure deceleration
// distance is more than the speed found (so nothing past it can matter: the
// plan is the whole program's, bit for bit), at most kMaxLookAhead = 65536
// blocks (past that, the stop at the window's end is kept: slower, never
// over a limit). The window is bounded; the Plan still holds every block
// (the reader and the plan are not streamed yet).
// Interpolation: the profile is sampled every cycle on one global clock
// (blocks are not forced onto cycle boundaries, except that after an exact
// stop the next block waits at rest for the next cycle, so that a sample
// lands on the corner); sample points on arcs are
// moved off the arc radially by the offset e that balances the chord error
// for a chord of path length L, L the longer of the two chords meeting at the
// point (so that the offset is never short for either): (a) e = 0 (ends on the arc),
// (b) (R + e)^2 - (L/2)^2 = R^2 (middle on the arc), (c) (R + e)^2 - (L/2)^2
// = (R - e)^2, e = L^2 / (16 R) (error e at the ends and in the middle); at
// the longest chord this is paper B's placement (R + eps / R - eps for (c)).
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "gcode/gcode.hpp"
#include "gcode/vec3.hpp"
#include "planner/path.hpp"

namespace contour::planner {

// Paper B, Fig. 1.
enum class ChordMethod { Inside, Outside, InsideOutside };  // (a), (b), (c)

double chord_length(ChordMethod m, double R, double eps);  // longest chord within eps
double chord_angle(ChordMethod m, double R, double eps);   // its angle
// Radial offset of the chord ends for a chord of length L on radius R with
// the placement m: 0 for (a); (b) middle on the arc; (c) L^2 / (16 R).
double vertex_offset(ChordMethod m, double R, double L);
const char* chord_name(ChordMethod m);  // "a", "b", "c"

struct Machine {
  Vec3 vmax{10000.0 / 60, 10000.0 / 60, 10000.0 / 60};  // mm/s per axis
  Vec3 amax{980, 980, 980};                              // mm/s^2 per axis (0.1 g = 3,528,000 mm/min^2)
  double rapid = 10000.0 / 60;                           // G0 path speed, mm/s
};

struct Config {
  Machine machine;
  double cycle_s = 1e-3;                       // control cycle T
  double tol_mm = 2e-5;                        // chord tolerance eps (0.02 um)
  double blend_tol_mm = 0.01;                  // G64 without P: corner tolerance (10 um)
  ChordMethod chord = ChordMethod::InsideOutside;
  // Throws std::invalid_argument naming the bad value.
  void validate() const;
};

// Why a block's cruise speed is what it is.
enum class Cap { Feed, AxisVelocity, Chord, Centripetal, Rapid };
const char* cap_name(Cap c);

struct PlannedSegment {
  Segment geom;
  double v_cap = 0;  // cruise cap, mm/s
  Cap cap = Cap::Feed;
  double a_t = 0;     // tangential acceleration, mm/s^2
  double rho = 0;     // curvature radius (arcs)
  Vec3 accel_use;     // bound on each axis' acceleration inside the block
  double v_start = 0, v_end = 0, v_cruise = 0;
  double t_begin = 0, duration = 0;
  double t_acc = 0, t_cruise = 0, t_dec = 0;
  double s_acc = 0, s_cruise = 0;

  double s_at(double t) const;  // path length after t seconds in the block
  double v_at(double t) const;  // path speed
};

struct Plan {
  Config config;
  std::vector<PlannedSegment> segs;
  std::vector<double> junction_limit;  // per junction k (between segs k-1 and k), before the passes
  std::vector<double> junction_tol;    // per junction k: the path tolerance there (chord or blend), mm
  double total_time = 0;
  std::size_t lookahead_blocks = 0;  // the widest look-ahead window used (Look-ahead, above)
};

// Plans a program. Throws std::invalid_argument for a bad configuration.
Plan plan(const std::vector<gcode::Block>& blocks, const Config& config);

// One control cycle's end point: the cycle's chord runs from the previous
// sample to this one.
struct Sample {
  double t = 0;
  Vec3 p;
  int seg = 0;     // segment index the sample lies on
  double s = 0;    // path length within that segment
  double v = 0;    // planned path speed at t
};

// Real-time interpolator: one sample per call, O(1) per cycle.
class Interpolator {
 public:
  explicit Interpolator(const Plan& plan);
  // Fills the next sample (the first is the start at t = 0); false when done.
  bool next(Sample& out);
  std::size_t cycles() const { return cycles_; }  // number of chords

 private:
  Sample at(std::size_t n);
  const Plan* plan_;
  std::size_t n_ = 0, cycles_ = 0, seg_ = 0;
};

std::vector<Sample> interpolate(const Plan& plan);

// Largest distance between the chord a->b and the programmed path between
// the two samples (both ways: chord points to the path, path points to the
// chord). Exact for a chord inside one plane arc or one line.
double chord_error(const Plan& plan, const Sample& a, const Sample& b);

struct AxisReport {
  double peak_v = 0, vmax = 0;  // mm/s
  double peak_a = 0, amax = 0;  // mm/s^2
  bool v_ok = true, a_ok = true;
};

struct Report {
  double total_time_s = 0;
  std::size_t cycles = 0;
  double peak_feed = 0;        // mm/s, largest chord / T
  double max_chord_error = 0;  // mm, chords inside one block
  bool tol_ok = true;
  double max_blend_error = 0;  // mm, chords across a corner
  bool blend_ok = true;        // each within its corner's tolerance
  std::array<AxisReport, 3> axes;
};

// A limit (axis velocity, axis acceleration, chord tolerance) counts as
// exceeded only when the measured peak is above it by more than this
// relative tolerance. The planner plans under every limit; what the samples
// show above a limit by less than this is floating-point rounding of the
// second differences (measured up to 4e-8 on real programs), not an excess.
constexpr double kLimitRelTol = 1e-6;

// Measures the samples: per-axis velocity (chord / T) and acceleration
// (second difference / T^2), chord errors, against the configured limits,
// each within kLimitRelTol.
Report analyse(const Plan& plan, const std::vector<Sample>& samples);

// The same measurement one sample at a time, so that the samples need not
// be kept: add() each sample in order, then report(). analyse() is this.
class Analyser {
 public:
  explicit Analyser(const Plan& plan);
  void add(const Sample& s);
  Report report() const;  // at rest after the last sample

 private:
  void step(const Vec3& v);  // one chord velocity (or rest)
  const Plan* plan_;
  Report r_;
  Sample prev_;
  Vec3 v_prev_;
  std::size_t count_ = 0;
};

}  // namespace contour::planner
