#include "coverage.hpp"

#include <cstdlib>

namespace contour::cosim {

namespace {

// Table Q of docs/algorithm.md: the quadrant a point belongs to for the
// sense (a point on an axis belongs to the quadrant being entered); -1 for
// the origin.
int quadrant(std::int64_t x, std::int64_t y, bool cw) {
  if (!cw) {
    if (x > 0 && y >= 0) return 0;
    if (x <= 0 && y > 0) return 1;
    if (x < 0 && y <= 0) return 2;
    if (x >= 0 && y < 0) return 3;
  } else {
    if (x >= 0 && y > 0) return 0;
    if (x < 0 && y >= 0) return 1;
    if (x <= 0 && y < 0) return 2;
    if (x > 0 && y <= 0) return 3;
  }
  return -1;
}

std::vector<CoverageBin> make_bins() {
  std::vector<CoverageBin> b(bin::kCount);
  const char* sense[2] = {"CCW", "CW"};
  for (int q = 0; q < 4; ++q)
    for (int cw = 0; cw < 2; ++cw)
      for (int out = 0; out < 2; ++out)
        b[bin::kArcDir + q * 4 + cw * 2 + out] = {
            "arc direction", "Q" + std::to_string(q + 1) + " " + sense[cw] + (out ? " outward" : " inward") + " pulse",
            {}};
  b[bin::kArcTie] = {"arc rules", "D = 0 tie: the pulse goes inward", {}};
  b[bin::kArcEndOut] = {"arc rules", "end-point rule: inward axis arrived (D >= 0), the pulse goes outward", {}};
  b[bin::kArcEndIn] = {"arc rules", "end-point rule: outward axis arrived (D < 0), the pulse goes inward", {}};
  for (int k = 0; k <= 4; ++k)
    b[bin::kArcK + k] = {"arc rules", "k = " + std::to_string(k) + " quadrant crossings from the load to the end", {}};
  b[bin::kArcCrossOntoEnd] = {"arc rules", "a crossing lands on the end point (the last pulse reaches an axis)", {}};
  b[bin::kLineTie] = {"line", "D = 0 tie: the pulse moves X", {}};
  b[bin::kLineEnd] = {"line", "end-point rule: X has no distance left (D >= 0), Y moves", {}};
  const char* signs[4] = {"X+ Y+", "X- Y+", "X+ Y-", "X- Y-"};
  for (int i = 0; i < 4; ++i) b[bin::kLineSigns + i] = {"line", std::string("direction ") + signs[i], {}};
  b[bin::kBackToBack] = {"sequence", "back-to-back loads: a move's first pulse on the command after the previous move's last", {}};
  b[bin::kOverrun] = {"host", "refused command pulses, every one flagged as an overrun", {}};
  b[bin::kQueueFull] = {"host", "queue full: a move waited for room (core: 16 blocks; 8085: both mailbox slots)", {}};
  b[bin::kPushRefused] = {"host", "a PUSH into the full queue refused (REJECT, nothing queued)", {}};
  b[bin::kAbort] = {"host", "ABORT drops the loaded and the queued move; the next moves exact", {}};
  return b;
}

}  // namespace

Coverage::Coverage() : bins_(make_bins()) {}

// Replays an arc's pulses from its start: before each pulse, the quadrant
// (table Q), D = x^2 + y^2 - R^2 and whether the pulse goes inward (its axis
// is the quadrant's inward one: X when (q even) XOR CW).
void Coverage::walk_arc(const Move& m, const std::vector<Pulse>& ps, bool complete, const std::string& engine) {
  const bool cw = m.sense == Sense::CW;
  std::int64_t x = m.xs, y = m.ys;
  const std::int64_t r2 = m.xs * m.xs + m.ys * m.ys;
  int crossings = 0;
  bool last_crossed = false;
  for (const Pulse& p : ps) {
    const int q = quadrant(x, y, cw);
    if (q < 0) return;  // cannot happen on a passed run: the origin is in no quadrant
    const Axis inward_axis = ((q % 2 == 0) != cw) ? Axis::X : Axis::Y;
    const bool inward = p.axis == inward_axis;
    const std::int64_t d = x * x + y * y - r2;
    count(bin::kArcDir + q * 4 + (cw ? 2 : 0) + (inward ? 0 : 1), engine);
    if (d == 0 && inward) count(bin::kArcTie, engine);
    if (d >= 0 && !inward) count(bin::kArcEndOut, engine);
    if (d < 0 && inward) count(bin::kArcEndIn, engine);
    (p.axis == Axis::X ? x : y) += p.sign;
    last_crossed = inward && (p.axis == Axis::X ? x : y) == 0;
    crossings += last_crossed;
  }
  if (!complete) return;
  if (crossings <= 4) count(bin::kArcK + crossings, engine);
  if (last_crossed) count(bin::kArcCrossOntoEnd, engine);
}

// Replays a line's pulses: D = A*y - B*x over the distances travelled.
void Coverage::walk_line(const Move& m, const std::vector<Pulse>& ps, const std::string& engine) {
  const std::int64_t a = std::llabs(m.xe), b = std::llabs(m.ye);
  std::int64_t x = 0, y = 0;
  for (const Pulse& p : ps) {
    const std::int64_t d = a * y - b * x;
    if (d == 0 && p.axis == Axis::X) count(bin::kLineTie, engine);
    if (d >= 0 && p.axis == Axis::Y) count(bin::kLineEnd, engine);
    (p.axis == Axis::X ? x : y) += 1;
  }
  if (!ps.empty()) count(bin::kLineSigns + (m.xe < 0 ? 1 : 0) + (m.ye < 0 ? 2 : 0), engine);
}

void Coverage::add(const Case& c, const Expected& exp, const EngineRun& run, const Row& row) {
  if (!row.acceptable()) return;
  const std::string& e = run.engine;
  // The engine's pulses, move by move: a passed run's pulses are the
  // model's (a prefix when FLAGGED), so the model's per-move counts split them.
  std::vector<std::size_t> per_move(c.moves.size(), 0);
  for (std::size_t i : exp.move_of) ++per_move[i];
  std::size_t at = 0;
  for (std::size_t i = 0; i < c.moves.size(); ++i) {
    const std::size_t n = std::min(per_move[i], run.out.size() - std::min(at, run.out.size()));
    std::vector<Pulse> ps;
    for (std::size_t j = at; j < at + n; ++j) ps.push_back(run.out[j].pulse);
    if (c.moves[i].is_arc()) walk_arc(c.moves[i], ps, n == per_move[i], e);
    else walk_line(c.moves[i], ps, e);
    // Back to back: this move ended with a pulse, the next one starts on the
    // next command (nothing lost: pulse j answered command j).
    if (i + 1 < c.moves.size() && n > 0 && n == per_move[i] && row.lost == 0 && at + n < run.out.size())
      count(bin::kBackToBack, e);
    at += n;
  }
  if (row.verdict == Verdict::Flagged && row.overruns > 0) count(bin::kOverrun, e);
  const auto ev = [&](const char* name) {
    const auto it = run.events.find(name);
    return it == run.events.end() ? 0 : it->second;
  };
  if (ev("queue_full")) count(bin::kQueueFull, e, ev("queue_full"));
  if (ev("push_refused")) count(bin::kPushRefused, e, ev("push_refused"));
  if (ev("abort")) count(bin::kAbort, e, ev("abort"));
}

std::size_t Coverage::hit() const {
  std::size_t n = 0;
  for (const auto& b : bins_) n += b.total() > 0;
  return n;
}

double Coverage::percent() const { return bins_.empty() ? 0 : 100.0 * double(hit()) / double(bins_.size()); }

}  // namespace contour::cosim
