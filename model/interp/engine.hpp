// A move (line or arc), the result of running it, and the Engine seam that
// the golden model, the Verilated core and the 8085 program all implement.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "interp/circular.hpp"
#include "interp/linear.hpp"
#include "interp/types.hpp"

namespace contour {

struct Move {
  enum class Kind : std::uint8_t { Line, Arc };
  Kind kind = Kind::Line;
  std::int64_t xs = 0, ys = 0;  // arc: start, relative to the centre
  std::int64_t xe = 0, ye = 0;  // line: end relative to the start; arc: end relative to the centre
  Sense sense = Sense::CCW;     // arc only

  static Move line(std::int64_t xe, std::int64_t ye) { return Move{Kind::Line, 0, 0, xe, ye, Sense::CCW}; }
  static Move arc(std::int64_t xs, std::int64_t ys, std::int64_t xe, std::int64_t ye, Sense s) {
    return Move{Kind::Arc, xs, ys, xe, ye, s};
  }
  bool is_arc() const { return kind == Kind::Arc; }
};

// "line 6 5" / "arc 6 0 0 6 ccw": the CLI spelling, for messages and reports.
std::string describe(const Move& m);

// One command pulse that produced an output pulse, and the state after it.
struct StepRecord {
  Pulse pulse;
  State state;
};

struct RunResult {
  std::vector<StepRecord> steps;
  State final_state;  // also the initial state when there are no steps
  State initial_state;
};

// Receives each step of a streamed run as the engine makes it.
using StepFn = std::function<void(const StepRecord&)>;

// Runs a move to its end, one command pulse at a time.
class Engine {
 public:
  virtual ~Engine() = default;
  virtual std::string name() const = 0;
  // Throws InputError if the move is outside the accepted domain.
  virtual RunResult run(const Move& m) = 0;
  // The same run, each step handed to `on_step` and none kept: the result
  // has the initial and final states and no steps, so memory does not grow
  // with the move. This default runs run() and replays it; the engines
  // override it with a loop that keeps nothing.
  virtual RunResult stream(const Move& m, const StepFn& on_step) {
    RunResult r = run(m);
    for (const auto& s : r.steps) on_step(s);
    r.steps = {};
    return r;
  }
};

// Throws InputError unless `m` is accepted at width W.
template <unsigned W = 24>
void validate(const Move& m) {
  if (m.is_arc()) Circular<W>::validate(m.xs, m.ys, m.xe, m.ye, m.sense);
  else Linear<W>::validate(m.xe, m.ye);
}

// The golden model as an engine at width W. With `on_step` each step goes
// there and none is kept.
template <unsigned W = 24>
RunResult run_model(const Move& m, const StepFn& on_step = {}) {
  RunResult r;
  auto drive = [&r, &on_step](auto& interp) {
    r.initial_state = interp.state();
    while (auto p = interp.step()) {
      if (on_step) on_step({*p, interp.state()});
      else r.steps.push_back({*p, interp.state()});
    }
    r.final_state = interp.state();
  };
  if (m.is_arc()) {
    Circular<W> c(m.xs, m.ys, m.xe, m.ye, m.sense);
    drive(c);
  } else {
    Linear<W> l(m.xe, m.ye);
    drive(l);
  }
  return r;
}

class ModelEngine final : public Engine {
 public:
  std::string name() const override { return "model"; }
  RunResult run(const Move& m) override { return run_model<24>(m); }
  RunResult stream(const Move& m, const StepFn& on_step) override { return run_model<24>(m, on_step); }
};

// Distance in pulses of (x, y) from the ideal contour: for a line the
// perpendicular distance from the segment's supporting line, for an arc
// | sqrt(x^2 + y^2) - R |.
double deviation(const Move& m, std::int64_t x, std::int64_t y);

// The largest deviation over a run, start point included.
double max_deviation(const Move& m, const RunResult& r);

// An arc over about n pulses of the circle through (xs, ys), ending at an
// accepted end point: the walk's position once |D| <= |x| + |y| after n
// pulses (long 24-bit arcs for tables and tests without a multiplier).
Move walked_arc(std::int64_t xs, std::int64_t ys, Sense s, int n);

}  // namespace contour
