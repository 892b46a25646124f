#include "stream_blocks.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "interp/circular.hpp"
#include "interp/hw_order.hpp"

namespace contour::board {

namespace {

constexpr double kPi = 3.14159265358979323846;

std::int64_t to_steps(double mm, double spm) { return std::llround(mm * spm); }

[[noreturn]] void refuse(int line, const std::string& what) {
  throw std::invalid_argument("line " + std::to_string(line) + ": " + what);
}

// The L1 length (|dx| + |dy|) of the unit circle from angle 0 to th:
// 2 per quarter turn, sin r + 1 - cos r within one.
double l1_turn(double th) {
  const double quarter = kPi / 2;
  const double k = std::floor(th / quarter);
  const double r = th - k * quarter;
  return 2 * k + std::sin(r) + 1 - std::cos(r);
}

// The fraction of an arc's L1 length between its start and the swept
// angle phi (0..sweep).
double arc_l1_fraction(const HwBlock& b, double phi) {
  const double s = b.cw ? -1.0 : 1.0;
  const double whole = std::abs(l1_turn(b.a0 + s * b.sweep) - l1_turn(b.a0));
  if (whole <= 0) return 1;
  return std::clamp(std::abs(l1_turn(b.a0 + s * phi) - l1_turn(b.a0)) / whole, 0.0, 1.0);
}

void check_width(const HwBlock& b, std::int64_t v, const char* what, unsigned width) {
  const std::int64_t lim = (std::int64_t{1} << width) - 1;
  if (std::llabs(v) > lim)
    refuse(b.line, std::string(what) + " = " + std::to_string(v) + " steps is beyond the board's 2^" +
                       std::to_string(width) + " - 1 = " + std::to_string(lim) + " (interp_top's W)");
}

HwBlock line_block(std::int64_t hx, std::int64_t hy, std::int64_t tx, std::int64_t ty, int line, unsigned width) {
  HwBlock b;
  b.line = line;
  b.x0 = hx;
  b.y0 = hy;
  b.xe = tx - hx;
  b.ye = ty - hy;
  check_width(b, b.xe, "a line's X", width);
  check_width(b, b.ye, "a line's Y", width);
  b.pulses = std::llabs(b.xe) + std::llabs(b.ye);
  return b;
}

// The swept angle of the hardware arc, consistent with its crossings k.
double hw_sweep(const HwBlock& b) {
  if (b.xs == b.xe && b.ys == b.ye) return 2 * kPi;
  double d = std::atan2(static_cast<double>(b.ye), static_cast<double>(b.xe)) - b.a0;
  if (b.cw) d = -d;
  d = std::fmod(d, 2 * kPi);
  if (d < 0) d += 2 * kPi;
  if (b.k == 0 && d > kPi) d = 0;          // a lattice end a hair behind on the circle: just ahead
  if (b.k == 4 && d < kPi) d += 2 * kPi;   // all the way round
  return d;
}

// Paper A accepts the arc (the rules of Circular<W>::validate at the
// board's width), and it sweeps about as far as the program's arc.
bool accept_arc(HwBlock& b, double sweep, unsigned width) {
  const std::int64_t lim = (std::int64_t{1} << width) - 1;
  for (std::int64_t v : {b.xs, b.ys, b.xe, b.ye})
    if (std::llabs(v) > lim) return false;
  if (b.xs * b.xs + b.ys * b.ys > lim * lim) return false;
  try {
    const auto p = Circular<30>::validate(b.xs, b.ys, b.xe, b.ye, b.cw ? Sense::CW : Sense::CCW);
    b.q = p.q_start;
    b.k = p.crossings;
  } catch (const InputError&) {
    return false;
  }
  b.a0 = std::atan2(static_cast<double>(b.ys), static_cast<double>(b.xs));
  b.sweep = hw_sweep(b);
  return std::abs(b.sweep - sweep) < kPi / 4;
}

std::int64_t arc_pulses(const HwBlock& b) {
  Circular<30> c(b.xs, b.ys, b.xe, b.ye, b.cw ? Sense::CW : Sense::CCW);
  std::int64_t n = 0;
  while (c.step()) ++n;
  return n;
}

// The arc about the lattice centre nearest the programmed centre (within
// 2 steps) for which paper A accepts the hardware's start and the rounded
// end point with the program's sweep; false if there is none.
bool centre_for(HwBlock& b, double cx, double cy, std::int64_t tx, std::int64_t ty, double sweep, unsigned width) {
  HwBlock best;
  double best_d = -1;
  for (std::int64_t dy = -2; dy <= 2; ++dy)
    for (std::int64_t dx = -2; dx <= 2; ++dx) {
      HwBlock c = b;
      c.cx = std::llround(cx) + dx;
      c.cy = std::llround(cy) + dy;
      c.xs = b.x0 - c.cx;
      c.ys = b.y0 - c.cy;
      c.xe = tx - c.cx;
      c.ye = ty - c.cy;
      const double d = std::hypot(static_cast<double>(c.cx) - cx, static_cast<double>(c.cy) - cy);
      if ((best_d < 0 || d < best_d) && accept_arc(c, sweep, width)) {
        best = c;
        best_d = d;
      }
    }
  if (best_d < 0) return false;
  b = best;
  return true;
}

// An XY arc from the hardware's position (hx, hy) to the rounded end point
// (full circle: back to the start); else to the rounded point of its own
// circle toward the programmed end; a line when too short for an arc.
HwBlock arc_block(const planner::Segment& g, std::int64_t hx, std::int64_t hy, double spm, unsigned width) {
  const Vec3 c = g.origin + g.qc.u * g.u_hat + g.qc.v * g.v_hat;
  HwBlock b;
  b.arc = true;
  b.line = g.line;
  b.x0 = hx;
  b.y0 = hy;
  const Vec3 r0 = g.start - c, t0 = g.tangent(0);
  b.cw = r0.x * t0.y - r0.y * t0.x < 0;  // the sense from the geometry (the UV frame's handedness varies)
  b.cx = to_steps(c.x, spm);
  b.cy = to_steps(c.y, spm);
  b.xs = hx - b.cx;
  b.ys = hy - b.cy;
  check_width(b, b.xs, "an arc's start X about its centre", width);
  check_width(b, b.ys, "an arc's start Y about its centre", width);
  const std::int64_t tx = g.full_circle ? hx : to_steps(g.end.x, spm), ty = g.full_circle ? hy : to_steps(g.end.y, spm);
  check_width(b, tx - b.cx, "an arc's end X about its centre", width);
  check_width(b, ty - b.cy, "an arc's end Y about its centre", width);
  const double sweep = g.full_circle ? 2 * kPi : g.sweep;
  if (!centre_for(b, c.x * spm, c.y * spm, tx, ty, sweep, width)) {
    const double ex = g.end.x * spm - static_cast<double>(b.cx), ey = g.end.y * spm - static_cast<double>(b.cy);
    const double r = std::hypot(static_cast<double>(b.xs), static_cast<double>(b.ys)), n = std::hypot(ex, ey);
    b.xe = n > 0 ? std::llround(r * ex / n) : b.xs;
    b.ye = n > 0 ? std::llround(r * ey / n) : b.ys;
    if (g.full_circle || !accept_arc(b, sweep, width)) {
      if (g.full_circle)
        refuse(g.line, "a full circle of radius " + std::to_string(r) + " steps: not a paper A arc (R^2 >= 2)");
      return line_block(hx, hy, tx, ty, g.line, width);
    }
  }
  b.pulses = arc_pulses(b);
  return b;
}

void check_plane(const planner::Segment& g, double spm) {
  if (g.kind == planner::Segment::Kind::Dwell) return;
  if (to_steps(g.start.z, spm) != to_steps(g.end.z, spm))
    refuse(g.line, "a Z move: paper A's blocks (--hw-arcs) drive X and Y only");
  if (g.kind == planner::Segment::Kind::Arc && (g.arc3d || g.helix() || std::abs(g.normal.z) < 0.5))
    refuse(g.line, "an arc out of the XY plane (G18, G19, 3D or a helix): --hw-arcs takes G17 arcs only");
}

// The fraction of block b's pulses planned done at path length s.
double block_fraction(const HwBlock& b, const planner::Segment& g, double s) {
  if (g.length <= 0) return 1;
  const double f = std::clamp(s / g.length, 0.0, 1.0);
  return b.arc ? arc_l1_fraction(b, f * b.sweep) : f;
}

FeedSchedule schedule(const planner::Plan& plan, const std::vector<HwBlock>& blocks) {
  std::vector<int> of_seg(plan.segs.size(), -1);
  std::vector<double> before(plan.segs.size() + 1, 0);
  for (std::size_t i = 0; i < blocks.size(); ++i) of_seg[blocks[i].seg] = static_cast<int>(i);
  for (std::size_t j = 0; j < plan.segs.size(); ++j)
    before[j + 1] = before[j] + (of_seg[j] >= 0 ? static_cast<double>(blocks[of_seg[j]].pulses) : 0.0);
  std::vector<double> n;
  planner::Interpolator it(plan);
  planner::Sample s;
  while (it.next(s)) {
    const auto j = static_cast<std::size_t>(s.seg);
    double v = before[j];
    if (of_seg[j] >= 0) {
      const HwBlock& b = blocks[of_seg[j]];
      v += static_cast<double>(b.pulses) * block_fraction(b, plan.segs[j].geom, s.s);
    }
    n.push_back(n.empty() ? v : std::max(v, n.back()));
  }
  n.push_back(before.back());
  return FeedSchedule(std::move(n), plan.config.cycle_s);
}

}  // namespace

std::string HwBlock::args() const {
  if (!arc) return "line " + std::to_string(xe) + " " + std::to_string(ye);
  return "arc " + std::to_string(xs) + " " + std::to_string(ys) + " " + std::to_string(xe) + " " +
         std::to_string(ye) + (cw ? " --cw" : " --ccw");
}

FeedSchedule::FeedSchedule(std::vector<double> pulses, double cycle_s) : n_(std::move(pulses)), cycle_s_(cycle_s) {}

double FeedSchedule::pulses_at(double t) const {
  if (n_.empty()) return 0;
  const double k = t / cycle_s_;
  if (k <= 0) return n_.front();
  if (k >= static_cast<double>(n_.size() - 1)) return n_.back();
  const auto i = static_cast<std::size_t>(k);
  return n_[i] + (n_[i + 1] - n_[i]) * (k - static_cast<double>(i));
}

double FeedSchedule::time_of(double n) const {
  if (n_.empty()) return 0;
  const auto it = std::upper_bound(n_.begin(), n_.end(), n);  // the first cycle with N > n
  if (it == n_.end()) return static_cast<double>(n_.size() - 1) * cycle_s_;
  if (it == n_.begin()) return 0;
  const auto i = static_cast<std::size_t>(it - n_.begin()) - 1;
  const double f = (n - n_[i]) / (n_[i + 1] - n_[i]);
  return (static_cast<double>(i) + f) * cycle_s_;
}

double FeedSchedule::rate_at(double tau) const { return (pulses_at(tau + cycle_s_) - pulses_at(tau)) / cycle_s_; }

BlockProgram to_blocks(const planner::Plan& plan, double spm, unsigned width) {
  BlockProgram p;
  p.width = width;
  if (!plan.segs.empty()) {
    p.x0 = to_steps(plan.segs.front().geom.start.x, spm);
    p.y0 = to_steps(plan.segs.front().geom.start.y, spm);
  }
  std::int64_t hx = p.x0, hy = p.y0;
  for (std::size_t j = 0; j < plan.segs.size(); ++j) {
    const planner::Segment& g = plan.segs[j].geom;
    check_plane(g, spm);
    if (g.kind == planner::Segment::Kind::Dwell) continue;
    HwBlock b = g.kind == planner::Segment::Kind::Arc
                    ? arc_block(g, hx, hy, spm, width)
                    : line_block(hx, hy, to_steps(g.end.x, spm), to_steps(g.end.y, spm), g.line, width);
    if (b.pulses == 0) continue;  // nothing to move on this grid
    b.seg = j;
    hx = b.end_x();
    hy = b.end_y();
    p.blocks.push_back(b);
  }
  p.x1 = hx;
  p.y1 = hy;
  p.feed = schedule(plan, p.blocks);
  double n = 0, a = 0;
  for (const HwBlock& b : p.blocks) {
    p.ends.push_back(n += static_cast<double>(b.pulses));
    const double at = plan.segs[b.seg].a_t;
    if (at > 0 && (a == 0 || at < a)) a = at;
  }
  p.decel = a * spm;
  return p;
}

ProgressTracker::ProgressTracker(const BlockProgram& p) : p_(&p), before_(p.blocks.size() + 1, 0) {
  for (std::size_t i = 0; i < p.blocks.size(); ++i)
    before_[i + 1] = before_[i] + static_cast<double>(p.blocks[i].pulses);
}

double ProgressTracker::update(std::uint32_t moves_done, std::int64_t x, std::int64_t y) {
  const std::size_t m = std::min<std::size_t>(moves_done, p_->blocks.size());
  if (m != block_) {
    block_ = m;
    phi_ = 0;
  }
  if (m == p_->blocks.size()) return n_ = before_.back();
  const HwBlock& b = p_->blocks[m];
  double f = 0;
  if (!b.arc) {
    f = static_cast<double>(std::llabs(x - b.x0) + std::llabs(y - b.y0)) / static_cast<double>(b.pulses);
  } else {
    // The swept angle, taken nearest the last one (a full circle passes 0).
    double d = std::atan2(static_cast<double>(y - b.cy), static_cast<double>(x - b.cx)) - b.a0;
    if (b.cw) d = -d;
    d -= 2 * kPi * std::round((d - phi_) / (2 * kPi));
    phi_ = std::clamp(d, phi_, b.sweep);
    f = arc_l1_fraction(b, phi_);
  }
  const double v = before_[m] + static_cast<double>(b.pulses) * std::min(f, 1.0);
  n_ = std::max(n_, std::min(v, before_[m + 1]));
  return n_;
}

namespace {

Op rd(std::uint8_t word) { return Op{false, word, 0}; }
Op wr(std::uint8_t word, std::uint32_t data) { return Op{true, word, data}; }

constexpr std::uint32_t kEnable = 1u << BOARD_LINK_CTRL_ENABLE_LSB;
constexpr std::uint32_t kPins = 1u << BOARD_LINK_CTRL_PINS_LSB;  // X, Y pins from interp_top
constexpr std::uint32_t kResume = 1u << BOARD_LINK_CTRL_RESUME_LSB;
constexpr std::uint32_t kSrcFeed = 2u << BOARD_INTERP_CTRL_SRC_LSB;
constexpr std::size_t kMaxInFlight = 3;  // frames: the feed must not lag by more

std::int64_t to_signed(std::uint32_t v) { return static_cast<std::int32_t>(v); }

std::vector<Op> block_ops(const HwBlock& b) {
  const std::uint32_t mode =
      (std::uint32_t(b.arc) << BOARD_INTERP_BLK_MODE_ARC_LSB) | (std::uint32_t(b.cw) << BOARD_INTERP_BLK_MODE_CW_LSB) |
      (std::uint32_t(!b.arc && b.xe < 0) << BOARD_INTERP_BLK_MODE_SXN_LSB) |
      (std::uint32_t(!b.arc && b.ye < 0) << BOARD_INTERP_BLK_MODE_SYN_LSB) |
      (std::uint32_t(b.q) << BOARD_INTERP_BLK_MODE_Q_LSB) | (std::uint32_t(b.k) << BOARD_INTERP_BLK_MODE_K_LSB);
  auto mag = [](std::int64_t v) { return static_cast<std::uint64_t>(std::llabs(v)); };
  const InOutMagnitudes io = inout_order(b.arc, b.cw ? Sense::CW : Sense::CCW, b.q, b.k, mag(b.xs), mag(b.ys),
                                         mag(b.xe), mag(b.ye));
  return {wr(BOARD_INTERP_BLK_MODE, mode),
          wr(BOARD_INTERP_BLK_CI, static_cast<std::uint32_t>(io.ci)),
          wr(BOARD_INTERP_BLK_CO, static_cast<std::uint32_t>(io.co)),
          wr(BOARD_INTERP_BLK_TI, static_cast<std::uint32_t>(io.ti)),
          wr(BOARD_INTERP_BLK_TO, static_cast<std::uint32_t>(io.to)),
          wr(BOARD_INTERP_PUSH, 0)};
}

std::uint32_t feed_word(double rate, double clock_hz) {
  const double w = std::round(std::max(rate, 0.0) * 4294967296.0 / clock_hz);
  return static_cast<std::uint32_t>(std::min(w, 4294967295.0));
}

// The run's state between frames.
struct BlockRun {
  BlockRun(LinkClient& l, const BlockProgram& p, const StreamConfig& c) : link(l), prog(p), cfg(c), track(p) {}
  LinkClient& link;
  const BlockProgram& prog;
  const StreamConfig& cfg;
  ProgressTracker track;
  std::size_t depth = 0, next = 0;
  std::uint32_t moves0 = 0, moves_done = 0;
  std::int64_t hx0 = 0, hy0 = 0;  // the board's position at the program's start
  double tau = 0, last_cycle = 0, last_rate = 0;
  double read_at = 0;                 // host time of the frame whose reads gave the progress
  std::array<double, 256> posted{};   // host time each frame (by sequence number) was posted
  bool wdog_seen = false, resume_posted = false;
  Progress prog_out;
  StreamResult res;
};

// The fastest rate from which the board brakes to rest (at the plan's
// least deceleration) within the blocks it has surely queued, less what it
// may have run since its last report; no cap once every block is there.
double braking_cap(const BlockRun& r, double n) {
  const std::size_t on_board = r.next - r.link.chords_in_flight();
  if (on_board >= r.prog.blocks.size() || r.prog.decel <= 0) return 1e30;
  const double end = on_board == 0 ? 0 : r.prog.ends[on_board - 1];
  const double left = end - n - r.last_rate * 2 * r.prog.feed.cycle();
  return left <= 0 ? 0 : std::sqrt(2 * r.prog.decel * left);
}

// The feed of this cycle (docs/board.md, "The feed"): the plan time tau
// advances with the host's clock, but not past the time the plan gives
// the pulse after the board's last read progress, plus the age of that
// read (at most two cycles); the rate is the plan's over the next cycle,
// at least a pulse a cycle once tau has passed the hardware's next pulse
// (so the end is always reached).
double cycle_rate(BlockRun& r, double now) {
  const FeedSchedule& f = r.prog.feed;
  const double n = r.track.value();
  const double due = f.time_of(n + 1);
  const double age = std::min(now - r.read_at, 2 * f.cycle());
  r.tau = std::min(r.tau + (now - r.last_cycle), due + age);
  r.last_cycle = now;
  double rate = std::min(f.rate_at(r.tau), braking_cap(r, n));
  if (r.tau >= due && n < f.total()) rate = std::max(rate, 1 / f.cycle());
  r.last_rate = rate;
  return rate;
}

// One control cycle: the feed, a block if the queue has room, and the
// reads the next cycle's progress comes from.
void post_cycle(BlockRun& r, Transport& t) {
  const double now = t.now_s();
  std::vector<Op> ops{wr(BOARD_INTERP_FEED, feed_word(cycle_rate(r, now), r.cfg.clock_hz))};
  std::size_t k = 0;
  const std::size_t used = r.link.last().level2 + r.link.chords_in_flight();
  if (r.next < r.prog.blocks.size() && used + 3 < r.depth) {
    const auto b = block_ops(r.prog.blocks[r.next++]);
    ops.insert(ops.end(), b.begin(), b.end());
    k = 1;
  }
  ops.insert(ops.end(), {rd(BOARD_INTERP_MOVES), rd(BOARD_INTERP_POS_X), rd(BOARD_INTERP_POS_Y)});
  r.posted[r.link.next_seq()] = now;
  r.link.post(ops, k);
}

// Between the cycles, while the queue is below half full: a frame of
// blocks only (two fit), so that blocks shorter than a cycle keep it fed.
void post_blocks(BlockRun& r) {
  const std::size_t used = r.link.last().level2 + r.link.chords_in_flight();
  if (r.next >= r.prog.blocks.size() || 2 * used >= r.depth) return;
  std::vector<Op> ops;
  std::size_t k = 0;
  for (; k < 2 && r.next < r.prog.blocks.size() && used + k + 3 < r.depth; ++k) {
    const auto b = block_ops(r.prog.blocks[r.next++]);
    ops.insert(ops.end(), b.begin(), b.end());
  }
  r.link.post(ops, k);
}

void post_resume(BlockRun& r) {
  if (!r.wdog_seen || r.resume_posted) return;
  r.link.post({wr(BOARD_LINK_CTRL, kEnable | kPins | kResume)}, 0);
  r.resume_posted = true;
  ++r.res.wdog_trips;
}

void stop_blocks(BlockRun& r) {
  r.link.drain();
  r.link.transact({wr(BOARD_LINK_CTRL, kEnable | kPins | (1u << BOARD_LINK_CTRL_HOLD_LSB))});
  for (;;) {
    const Reply s = r.link.transact({rd(BOARD_LINK_STATUS)});
    if ((s.data[0] >> BOARD_LINK_STATUS_STOPPED_LSB) & 1u) break;
  }
  r.link.transact({wr(BOARD_INTERP_CTRL, 1u << BOARD_INTERP_CTRL_ABORT_LSB), wr(BOARD_INTERP_FEED, 0),
                   wr(BOARD_LINK_CTRL, kPins)});
  r.res.stopped = true;
}

void setup_board(BlockRun& r) {
  check_board(r.link);
  const std::uint32_t params = r.link.transact({rd(BOARD_INTERP_PARAMS)}).data[0];
  const unsigned w = (params & BOARD_INTERP_PARAMS_W_MASK) >> BOARD_INTERP_PARAMS_W_LSB;
  r.depth = (params & BOARD_INTERP_PARAMS_QDEPTH_MASK) >> BOARD_INTERP_PARAMS_QDEPTH_LSB;
  if (w < r.prog.width)
    throw LinkError("the board's interp_top has W = " + std::to_string(w) + ", the blocks need " +
                    std::to_string(r.prog.width));
  const StreamConfig& c = r.cfg;
  r.link.transact({wr(BOARD_INTERP_CTRL, (1u << BOARD_INTERP_CTRL_ABORT_LSB) | (1u << BOARD_INTERP_CTRL_CLEAR_LSB)),
                   wr(BOARD_INTERP_FEED, 0), wr(BOARD_INTERP_STEP_LEN, c.step_len),
                   wr(BOARD_INTERP_STEP_SPACE, c.step_space), wr(BOARD_LINK_WDOG, c.wdog_clocks),
                   wr(BOARD_LINK_CTRL, kEnable | kPins | kResume), wr(BOARD_INTERP_CTRL, kSrcFeed)});
  const Reply p = r.link.transact(
      {rd(BOARD_INTERP_POS_X), rd(BOARD_INTERP_POS_Y), rd(BOARD_AXIS3_POS_Z), rd(BOARD_INTERP_MOVES)});
  r.hx0 = to_signed(p.data[0]);
  r.hy0 = to_signed(p.data[1]);
  r.res.start = {r.hx0, r.hy0, to_signed(p.data[2])};
  r.moves0 = p.data[3];
  r.res.expected = {r.hx0 + r.prog.x1 - r.prog.x0, r.hy0 + r.prog.y1 - r.prog.y0, r.res.start[2]};
}

void watch_replies(BlockRun& r) {
  r.link.on_reply = [&r](const Reply& rep) {
    r.wdog_seen = rep.flag(BOARD_FLAG_WDOG);
    if (!r.wdog_seen) r.resume_posted = false;
    r.prog_out.level = rep.level2;
  };
  r.link.on_data = [&r](const Reply& rep) {
    if (rep.data.size() < 3) return;
    const std::size_t n = rep.data.size();
    r.moves_done = rep.data[n - 3] - r.moves0;
    const std::int64_t x = to_signed(rep.data[n - 2]) - r.hx0 + r.prog.x0;
    const std::int64_t y = to_signed(rep.data[n - 1]) - r.hy0 + r.prog.y0;
    r.track.update(r.moves_done, x, y);
    r.read_at = r.posted[rep.seq];
    r.prog_out.pos = {to_signed(rep.data[n - 2]), to_signed(rep.data[n - 1]), r.res.start[2]};
  };
}

}  // namespace

StreamResult stream_blocks(LinkClient& link, Transport& t, const BlockProgram& prog, const StreamConfig& cfg,
                           const std::function<void(const Progress&)>& progress, const std::atomic<bool>* stop) {
  BlockRun r{link, prog, cfg};
  setup_board(r);
  watch_replies(r);
  r.prog_out.total = prog.blocks.size();
  r.last_cycle = t.now_s();
  const std::size_t n = prog.blocks.size();
  while (r.moves_done < n) {
    if (stop && stop->load()) break;
    if (t.now_s() - r.last_cycle >= cfg.cycle_s && link.in_flight() < kMaxInFlight) post_cycle(r, t);
    else if (link.in_flight() + 1 < kMaxInFlight) post_blocks(r);
    post_resume(r);
    link.pump(cfg.cycle_s / 4);
    r.prog_out.sent = r.next;
    if (progress) progress(r.prog_out);
  }
  if (stop && stop->load()) stop_blocks(r);
  link.drain();
  link.on_reply = nullptr;
  link.on_data = nullptr;
  // The write alone: a frame with writes that is sent again is answered DUP,
  // without its reads.
  link.transact({wr(BOARD_INTERP_FEED, 0)});
  const Reply e =
      link.transact({rd(BOARD_INTERP_POS_X), rd(BOARD_INTERP_POS_Y), rd(BOARD_AXIS3_POS_Z), rd(BOARD_INTERP_MOVES)});
  r.res.end = {to_signed(e.data[0]), to_signed(e.data[1]), to_signed(e.data[2])};
  r.res.chords = e.data[3] - r.moves0;
  r.res.link = link.stats();
  return r.res;
}

}  // namespace contour::board
