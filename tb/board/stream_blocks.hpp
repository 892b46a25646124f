// Paper A mode of the host link (`contour stream --hw-arcs`, docs/board.md,
// "Paper A mode"): a planned G-code program's lines and arcs of the XY
// plane sent as interp_top blocks (window INTERP), and interp_top's feed
// register written every control cycle from the planner's velocity
// profile, so that paper B's pre-interpolation acc/dec drives paper A's
// exact hardware arcs.
//
// The conversion (to_blocks): every point is rounded to the nearest step
// on the program's grid; a line runs from where the hardware really is
// (the end of the block before) to the rounded end point; an arc runs from
// there to the rounded end point about the lattice point nearest the
// programmed centre (of the 5 x 5 around it) for which paper A accepts the
// arc with the program's sweep; if none does, to the rounded point of its
// own circle toward the programmed end; an arc too short for either
// becomes a line. So each block starts exactly where the last one ended:
// nothing accumulates.
//
// The feed (FeedSchedule): the plan's progress in hardware pulses,
// N(t) = the pulses of the blocks before + the block's pulses times the
// fraction of its L1 length (|dx| + |dy|, the length a pulse stands for
// along the path) planned done at t. Each cycle the host writes the rate
// (N(tau + T) - N(tau)) / T, tau the plan time, which advances with the
// host's clock but never past the time the plan gives the pulse after
// the one the board has reached, and never faster than the board can
// brake to rest within the blocks it has queued (when the link cannot
// keep up with short blocks, the motion slows instead of stopping dead on
// an empty queue).
#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "link_client.hpp"
#include "planner/planner.hpp"
#include "stream_chords.hpp"

namespace contour::board {

// One interp_top block, in steps of the program's grid (the program's
// origin at 0).
struct HwBlock {
  bool arc = false, cw = false;
  std::int64_t x0 = 0, y0 = 0;  // start
  std::int64_t cx = 0, cy = 0;  // arc: centre
  std::int64_t xs = 0, ys = 0;  // arc: start relative to the centre
  std::int64_t xe = 0, ye = 0;  // line: end relative to the start; arc: end relative to the centre
  int q = 0, k = 0;             // arc: start quadrant and crossings (Circular::validate)
  std::int64_t pulses = 0;      // the paper A model's count
  double a0 = 0, sweep = 0;     // arc: start angle about the centre, swept angle (rad, > 0)
  int line = 0;                 // the G-code line
  std::size_t seg = 0;          // the plan's segment
  std::int64_t end_x() const { return arc ? cx + xe : x0 + xe; }
  std::int64_t end_y() const { return arc ? cy + ye : y0 + ye; }
  std::string args() const;  // as `contour line|arc` takes it: "line XE YE", "arc XS YS XE YE --ccw"
};

// The plan's progress in hardware pulses, one value per control cycle.
class FeedSchedule {
 public:
  FeedSchedule() = default;
  FeedSchedule(std::vector<double> pulses, double cycle_s);
  double pulses_at(double t) const;  // N(t), linear between cycles
  double time_of(double n) const;    // the latest t with N(t) <= n
  double rate_at(double tau) const;  // (N(tau + T) - N(tau)) / T, pulses per second
  double total() const { return n_.empty() ? 0 : n_.back(); }
  double cycle() const { return cycle_s_; }

 private:
  std::vector<double> n_;
  double cycle_s_ = 1e-3;
};

struct BlockProgram {
  std::vector<HwBlock> blocks;
  FeedSchedule feed;
  std::int64_t x0 = 0, y0 = 0;  // the program's start and end, steps
  std::int64_t x1 = 0, y1 = 0;  // (the end: where the last block ends)
  unsigned width = 16;
  std::vector<double> ends;  // the plan's pulse count at the end of each block
  double decel = 0;          // pulses/s^2 the plan may always brake at (its least a_t, in steps)
};

// The blocks of a plan on a grid of `steps_per_mm`, for interp_top at
// `width` bits. Throws std::invalid_argument "line N: ..." for what the
// board cannot do: a Z move, an arc out of the XY plane (G18, G19, 3D, a
// helix), a coordinate beyond 2^width - 1 steps.
BlockProgram to_blocks(const planner::Plan& plan, double steps_per_mm, unsigned width = 16);

// The hardware's progress in pulses along the program, from the moves it
// has completed and its position (steps of the program's grid): exact on
// lines, within about a pulse on arcs; never decreasing.
class ProgressTracker {
 public:
  explicit ProgressTracker(const BlockProgram& p);
  double update(std::uint32_t moves_done, std::int64_t x, std::int64_t y);
  double value() const { return n_; }

 private:
  const BlockProgram* p_;
  std::vector<double> before_;
  std::size_t block_ = 0;
  double phi_ = 0, n_ = 0;
};

// Streams the blocks (queue kept filled) and writes FEED every cycle;
// resumes a tripped watchdog; `stop`: feed hold, rest, then abort.
// StreamResult.chords counts the blocks the board completed.
StreamResult stream_blocks(LinkClient& link, Transport& t, const BlockProgram& prog, const StreamConfig& cfg,
                           const std::function<void(const Progress&)>& progress = {},
                           const std::atomic<bool>* stop = nullptr);

}  // namespace contour::board
