// Test support: an independent oracle for arcs, written from the text of
// docs/algorithm.md ("Circular") and sharing no code with what it checks:
// it includes nothing of the model (no Circular, no validate, no helpers).
// Used by the tests of every engine (model/interp, tb/interp, sw8085/interp).
//
// What it knows, by geometry and exact integer reasoning:
//  - q and k from table Q and the set-up rule (its own code);
//  - the pulse count of every quadrant travelled, in closed form. A crossing
//    leaves a quadrant on its axis with the other magnitude exactly
//    C = ceil(sqrt(R^2 - 1)): the last outward pulse there was taken with
//    D < 0 at |in| >= 1, so (C - 1)^2 < R^2 - 1, and the pulse onto the
//    axis with D >= 0 from |in| = 1, so 1 + C^2 >= R^2. Hence a quadrant is
//    entered at (|in|, |out|) = (C, 0) and, unless it is the end quadrant,
//    left at (0, C): the start quadrant takes |in_S| + (C - |out_S|) pulses,
//    each middle one 2C, the end quadrant (C - |in_E|) + |out_E|; with
//    k = 0 the one quadrant takes (|in_S| - |in_E|) + (|out_E| - |out_S|).
//    A full circle of integer radius R is 8R.
//  - a walk check (check_walk): every pulse is the inward or outward pulse
//    of the quadrant the oracle expects (table P), chosen by the sign of
//    D = x^2 + y^2 - R^2 computed from the position itself (not updated
//    incrementally) and by the end-point rule; every position belongs to
//    that quadrant (table Q); the per-quadrant counts are the closed form;
//    the position rebuilt from the pulses ends at the end point.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace contour::oracle {

struct Run {
  int q = 0;                    // quadrant 0..3 (Q1..Q4)
  std::int64_t in = 0, out = 0; // inward and outward pulses taken in it
};

struct ArcExpect {
  bool accepted = false;
  std::string why;              // the broken rule when not accepted
  std::int64_t r2 = 0, c = 0;   // R^2 and C = ceil(sqrt(R^2 - 1))
  int q_start = 0, q_end = 0, k = 0;
  std::vector<Run> runs;        // k + 1 quadrants in order of travel
  std::int64_t pulses = 0, x_pulses = 0, y_pulses = 0;
};

inline std::int64_t mag(std::int64_t v) { return v < 0 ? -v : v; }

// Table Q, row by row.
inline int quadrant(std::int64_t x, std::int64_t y, bool cw) {
  if (!cw) {
    if (x > 0 && y >= 0) return 0;
    if (x <= 0 && y > 0) return 1;
    if (x < 0 && y <= 0) return 2;
    return 3;  // x >= 0, y < 0 (the origin is never asked)
  }
  if (x >= 0 && y > 0) return 0;
  if (x < 0 && y >= 0) return 1;
  if (x <= 0 && y < 0) return 2;
  return 3;
}

// Table Q's inward axis column: true for X.
inline bool inward_x(int q, bool cw) {
  static const bool ccw_col[4] = {true, false, true, false};
  return cw ? !ccw_col[q] : ccw_col[q];
}

// Table Q's sign columns.
inline int sign_x(int q) { return (q == 0 || q == 3) ? +1 : -1; }
inline int sign_y(int q) { return q <= 1 ? +1 : -1; }

// Smallest c >= 0 with c^2 >= v.
inline std::int64_t ceil_sqrt(std::int64_t v) {
  std::int64_t c = 0;
  for (std::int64_t step = std::int64_t{1} << 31; step > 0; step >>= 1)
    if ((c + step) * (c + step) < v) c += step;
  return v <= 0 ? 0 : c + 1;
}

// The set-up of q and k, then rules 2 to 4 of "Accepted arcs" (rule 1, the
// width, is the caller's: the sweeps stay far inside it), then the runs.
inline ArcExpect expect_arc(std::int64_t xs, std::int64_t ys, std::int64_t xe, std::int64_t ye, bool cw) {
  ArcExpect a;
  a.r2 = xs * xs + ys * ys;
  if (a.r2 < 2) return a.why = "R^2 < 2", a;
  const std::int64_t de = xe * xe + ye * ye - a.r2;
  if (mag(de) > mag(xe) + mag(ye)) return a.why = "end not on the circle", a;
  a.q_start = quadrant(xs, ys, cw);
  a.q_end = quadrant(xe, ye, cw);
  const int steps = ((cw ? a.q_start - a.q_end : a.q_end - a.q_start) % 4 + 4) % 4;
  const bool ix = inward_x(a.q_end, cw);
  const std::int64_t in_s = mag(ix ? xs : ys), out_s = mag(ix ? ys : xs);
  const std::int64_t in_e = mag(ix ? xe : ye), out_e = mag(ix ? ye : xe);
  const bool ahead = !(xs == xe && ys == ye) && in_e <= in_s && out_e >= out_s;
  a.k = steps != 0 ? steps : (ahead ? 0 : 4);
  a.c = ceil_sqrt(a.r2 - 1);
  if (a.k > 0 && in_e > a.c) return a.why = "end not reachable", a;
  a.accepted = true;
  for (int i = 0; i <= a.k; ++i) {
    Run r;
    r.q = ((cw ? a.q_start - i : a.q_start + i) % 4 + 4) % 4;
    const bool first = i == 0, last = i == a.k;
    const bool rx = inward_x(r.q, cw);
    const std::int64_t in0 = first ? mag(rx ? xs : ys) : a.c, out0 = first ? mag(rx ? ys : xs) : 0;
    const std::int64_t in1 = last ? mag(rx ? xe : ye) : 0, out1 = last ? mag(rx ? ye : xe) : a.c;
    r.in = in0 - in1;
    r.out = out1 - out0;
    a.runs.push_back(r);
    a.pulses += r.in + r.out;
    (rx ? a.x_pulses : a.y_pulses) += r.in;
    (rx ? a.y_pulses : a.x_pulses) += r.out;
  }
  return a;
}

// One pulse of an engine, and (if the engine reports it) the state after.
struct Step {
  int axis = 0;  // 0: X, 1: Y
  int sign = +1;
  std::optional<int> q;                     // reported quadrant
  std::optional<std::int64_t> x, y;         // reported position
};

// Walks `steps` from the start as described above; "" if every check
// holds, otherwise the first failure.
inline std::string check_walk(const ArcExpect& a, std::int64_t xs, std::int64_t ys, std::int64_t xe,
                              std::int64_t ye, bool cw, const std::vector<Step>& steps);

namespace detail {
struct Walker {
  const ArcExpect& a;
  bool cw;
  std::int64_t xe, ye, x, y;
  std::size_t run = 0;
  std::vector<Run> seen{};

  // The pulse the rules choose at the current position: inward or not.
  bool rule_inward() const {
    const int q = a.runs[run].q;
    const bool ix = inward_x(q, cw);
    const std::int64_t d = x * x + y * y - a.r2;
    bool inward = d >= 0;
    if (run + 1 == a.runs.size()) {
      const std::int64_t in = mag(ix ? x : y), out = mag(ix ? y : x);
      const std::int64_t in_e = mag(ix ? xe : ye), out_e = mag(ix ? ye : xe);
      if (inward && in == in_e) inward = false;
      else if (!inward && out == out_e) inward = true;
    }
    return inward;
  }

  std::string step(const Step& s, std::size_t n) {
    const std::string at = "pulse " + std::to_string(n + 1) + ": ";
    if (run >= a.runs.size()) return at + "after the last quadrant";
    const int q = a.runs[run].q;
    const bool ix = inward_x(q, cw);
    const bool want_in = rule_inward();
    const int want_axis = (want_in == ix) ? 0 : 1;
    const int qs = want_axis == 0 ? sign_x(q) : sign_y(q);
    const int want_sign = want_in ? -qs : qs;
    if (s.axis != want_axis || s.sign != want_sign)
      return at + "got " + (s.sign < 0 ? "-" : "+") + (s.axis ? "Y" : "X") + ", the rules give " +
             (want_sign < 0 ? "-" : "+") + (want_axis ? "Y" : "X") + " in Q" + std::to_string(q + 1);
    (s.axis == 0 ? x : y) += s.sign;
    (want_in ? seen[run].in : seen[run].out) += 1;
    if (want_in && mag(ix ? x : y) == 0) ++run;  // onto the next quadrant
    const int now = run < a.runs.size() ? a.runs[run].q : -1;
    if (run < a.runs.size() && quadrant(x, y, cw) != now)
      return at + "position (" + std::to_string(x) + ", " + std::to_string(y) + ") is not in Q" +
             std::to_string(now + 1);
    if (s.q && *s.q != now) return at + "reported Q" + std::to_string(*s.q + 1) + ", want Q" + std::to_string(now + 1);
    if ((s.x && *s.x != x) || (s.y && *s.y != y)) return at + "reported position differs from the pulses'";
    return "";
  }
};
}  // namespace detail

inline std::string check_walk(const ArcExpect& a, std::int64_t xs, std::int64_t ys, std::int64_t xe,
                              std::int64_t ye, bool cw, const std::vector<Step>& steps) {
  if (!a.accepted) return "the oracle rejects the arc: " + a.why;
  if (static_cast<std::int64_t>(steps.size()) != a.pulses)
    return std::to_string(steps.size()) + " pulses, the geometry gives " + std::to_string(a.pulses);
  detail::Walker w{a, cw, xe, ye, xs, ys, 0, {}};
  w.seen.resize(a.runs.size());
  for (auto& r : w.seen) r.q = -1;
  for (std::size_t n = 0; n < steps.size(); ++n)
    if (std::string e = w.step(steps[n], n); !e.empty()) return e;
  if (w.x != xe || w.y != ye) return "ends at (" + std::to_string(w.x) + ", " + std::to_string(w.y) + ")";
  for (std::size_t i = 0; i < a.runs.size(); ++i)
    if (w.seen[i].in != a.runs[i].in || w.seen[i].out != a.runs[i].out)
      return "Q" + std::to_string(a.runs[i].q + 1) + " (quadrant " + std::to_string(i + 1) + " of the arc): " +
             std::to_string(w.seen[i].in) + " inward + " + std::to_string(w.seen[i].out) + " outward, want " +
             std::to_string(a.runs[i].in) + " + " + std::to_string(a.runs[i].out);
  return "";
}

// The sweep of the small-arc tests: every arc between lattice points with
// |xs|, |ys| <= n and |xe|, |ye| <= n + 1, both senses, that the oracle
// accepts, through `check` (xs, ys, xe, ye, cw -> "" or what is wrong);
// `seen` (optional) is told of every arc and the oracle's acceptance.
struct Sweep {
  int runs = 0, failed = 0;
  std::string first;  // the first three failures
};

struct NoSeen {
  void operator()(int, int, int, int, bool, bool) const {}
};

template <class Check, class Seen = NoSeen>
Sweep check_small_arcs(int n, Check&& check, Seen&& seen = {}) {
  Sweep s;
  for (int xs = -n; xs <= n; ++xs)
    for (int ys = -n; ys <= n; ++ys)
      for (int xe = -n - 1; xe <= n + 1; ++xe)
        for (int ye = -n - 1; ye <= n + 1; ++ye)
          for (bool cw : {false, true}) {
            const bool accepted = expect_arc(xs, ys, xe, ye, cw).accepted;
            seen(xs, ys, xe, ye, cw, accepted);
            if (!accepted) continue;
            ++s.runs;
            if (std::string e = check(xs, ys, xe, ye, cw); !e.empty() && s.failed++ < 3) s.first += e + "\n";
          }
  return s;
}

}  // namespace contour::oracle
