// A move (line or arc), the result of running it, and the Engine seam that
// the golden model, the Verilated core and the 8085 program all implement.
#pragma once

#include <cstdint>
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

// Runs a move to its end, one command pulse at a time.
class Engine {
 public:
  virtual ~Engine() = default;
  virtual std::string name() const = 0;
  // Throws InputError if the move is outside the accepted domain.
  virtual RunResult run(const Move& m) = 0;
};

// Throws InputError unless `m` is accepted at width W.
template <unsigned W = 24>
void validate(const Move& m) {
  if (m.is_arc()) Circular<W>::validate(m.xs, m.ys, m.xe, m.ye, m.sense);
  else Linear<W>::validate(m.xe, m.ye);
}

// The golden model as an engine at width W.
template <unsigned W = 24>
RunResult run_model(const Move& m) {
  RunResult r;
  auto drive = [&r](auto& interp) {
    r.initial_state = interp.state();
    while (auto p = interp.step()) r.steps.push_back({*p, interp.state()});
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
};

// Distance in pulses of (x, y) from the ideal contour: for a line the
// perpendicular distance from the segment's supporting line, for an arc
// | sqrt(x^2 + y^2) - R |.
double deviation(const Move& m, std::int64_t x, std::int64_t y);

// The largest deviation over a run, start point included.
double max_deviation(const Move& m, const RunResult& r);

}  // namespace contour
