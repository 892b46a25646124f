#include "stream_chords.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace contour::board {

namespace {

Op rd(std::uint8_t word) { return Op{false, word, 0}; }
Op wr(std::uint8_t word, std::uint32_t data) { return Op{true, word, data}; }

constexpr std::uint32_t kRun = 1u << BOARD_AXIS3_CTRL_RUN_LSB;
constexpr std::uint32_t kDrain = 1u << BOARD_AXIS3_CTRL_DRAIN_LSB;
constexpr std::uint32_t kEnable = 1u << BOARD_LINK_CTRL_ENABLE_LSB;

std::int64_t to_signed(std::uint32_t v) { return static_cast<std::int32_t>(v); }

std::array<std::int64_t, 3> reply_positions(const Reply& r) { return {r.pos[0], r.pos[1], r.pos[2]}; }

// The positions at rest: every reply carries them (board.def REPLY POS_*);
// the POS registers read in the same frame must agree.
std::array<std::int64_t, 3> read_positions(LinkClient& link) {
  const Reply r = link.transact({rd(BOARD_AXIS3_POS_X), rd(BOARD_AXIS3_POS_Y), rd(BOARD_AXIS3_POS_Z)});
  const std::array<std::int64_t, 3> regs{to_signed(r.data[0]), to_signed(r.data[1]), to_signed(r.data[2])};
  if (regs != reply_positions(r))
    throw LinkError("the reply's positions " + std::to_string(r.pos[0]) + " " + std::to_string(r.pos[1]) + " " +
                    std::to_string(r.pos[2]) + " differ from the POS registers " + std::to_string(regs[0]) + " " +
                    std::to_string(regs[1]) + " " + std::to_string(regs[2]));
  return regs;
}

// The ops that queue one chord: the packed word if it fits, else the
// staged registers and PUSH. Throws for a chord the board cannot give.
std::vector<Op> chord_ops(const Chord3& c, std::size_t k, const StreamConfig& cfg, unsigned width) {
  const std::int64_t lim = (std::int64_t{1} << width) - 1;
  auto where = [&] {
    return "chord " + std::to_string(k) + " (" + std::to_string(c.dx) + ", " + std::to_string(c.dy) + ", " +
           std::to_string(c.dz) + ")";
  };
  if (std::llabs(c.dx) > lim || std::llabs(c.dy) > lim || std::llabs(c.dz) > lim)
    throw std::invalid_argument(where() + ": an axis beyond the board's 2^" + std::to_string(width) + " - 1 steps");
  const double cycle_clk = cfg.cycle_s * cfg.clock_hz;
  const double per_step = std::max(cfg.step_len, 1u) + std::max(cfg.step_space, 1u) + 2.0;
  const auto most = static_cast<std::int64_t>(cycle_clk / per_step);
  if (std::llabs(c.dx) + std::llabs(c.dy) + std::llabs(c.dz) > most)
    throw std::invalid_argument(where() + ": more steps than the board gives in one cycle (" + std::to_string(most) +
                                " with the step timing)");
  if (auto w = pack_chord(c.dx, c.dy, c.dz)) return {wr(BOARD_AXIS3_CHORD, *w)};
  return {wr(BOARD_AXIS3_CH_X, static_cast<std::uint32_t>(c.dx)), wr(BOARD_AXIS3_CH_Y, static_cast<std::uint32_t>(c.dy)),
          wr(BOARD_AXIS3_CH_Z, static_cast<std::uint32_t>(c.dz)), wr(BOARD_AXIS3_PUSH, 0)};
}

// The run's state between frames.
struct Run {
  Run(LinkClient& l, const std::vector<Chord3>& c, const StreamConfig& k) : link(l), chords(c), cfg(k) {}
  LinkClient& link;
  const std::vector<Chord3>& chords;
  const StreamConfig& cfg;
  std::size_t depth = 0, next = 0;
  unsigned width = 0;  // the board's chord magnitude width
  bool running = false, wdog_seen = false, resume_posted = false;
  double last_post = 0;
  Progress prog;
  StreamResult res;
};

// Fills one frame with chords (as many as the queue and the frame take).
void post_chords(Run& r, Transport& t) {
  const std::size_t used = r.link.last().level3 + r.link.chords_in_flight();
  const std::size_t cap = used + 1 >= r.depth ? 0 : r.depth - 1 - used;
  std::vector<Op> ops;
  std::size_t k = 0;
  while (r.next < r.chords.size() && k < cap && k < r.cfg.chords_per_frame) {
    std::vector<Op> c = chord_ops(r.chords[r.next], r.next, r.cfg, r.width);
    std::vector<Op> trial = ops;
    trial.insert(trial.end(), c.begin(), c.end());
    if (request_size(trial) + 5 > BOARD_MAX_FRAME) break;  // room for CTRL
    ops = trial;
    ++k;
    ++r.next;
  }
  if (!r.running && (r.next == r.chords.size() || k == cap)) {
    ops.push_back(wr(BOARD_AXIS3_CTRL, kRun));
    r.running = true;
  }
  if (ops.empty()) return;
  r.link.post(ops, k);
  r.last_post = t.now_s();
}

// A keepalive (the watchdog) or a resume, when due.
void post_service(Run& r, Transport& t) {
  if (r.wdog_seen && !r.resume_posted) {
    r.link.post({wr(BOARD_LINK_CTRL, kEnable | (1u << BOARD_LINK_CTRL_RESUME_LSB))}, 0);
    r.resume_posted = true;
    ++r.res.wdog_trips;
    r.last_post = t.now_s();
  } else if (t.now_s() - r.last_post > 0.02 && r.link.in_flight() == 0) {
    r.link.post({wr(BOARD_LINK_WDOG, r.cfg.wdog_clocks)}, 0);  // a keepalive; its reply has the positions
    r.last_post = t.now_s();
  }
}

// Feed hold, wait for rest (the ramp: 65536 * RAMP clocks, 49 ms), then
// drop the queue.
void stop_motion(Run& r, Transport& t) {
  r.link.drain();
  r.link.transact({wr(BOARD_LINK_CTRL, kEnable | (1u << BOARD_LINK_CTRL_HOLD_LSB))});
  const double t0 = t.now_s();
  for (;;) {
    const Reply s = r.link.transact({rd(BOARD_LINK_STATUS)});
    if ((s.data[0] >> BOARD_LINK_STATUS_STOPPED_LSB) & 1u) break;
    if (t.now_s() - t0 > r.cfg.rest_s) {
      char b[80];
      std::snprintf(b, sizeof b, "the board did not come to rest within %g s of a feed hold", r.cfg.rest_s);
      throw LinkError(b);
    }
  }
  r.link.transact({wr(BOARD_AXIS3_CTRL, 1u << BOARD_AXIS3_CTRL_ABORT_LSB), wr(BOARD_LINK_CTRL, 0)});
  r.res.stopped = true;
}

// After the last chord: DRAIN, then wait until the run has ended.
void finish(Run& r) {
  r.link.post({wr(BOARD_AXIS3_CTRL, kRun | kDrain)}, 0);
  r.link.drain();
  for (;;) {
    const Reply s = r.link.transact({rd(BOARD_AXIS3_STATUS)});
    const std::uint32_t st = s.data[0];
    if (!((st >> BOARD_AXIS3_STATUS_RUN_LSB) & 1u) && !((st >> BOARD_AXIS3_STATUS_BUSY_LSB) & 1u)) break;
    if (s.flag(BOARD_FLAG_WDOG)) {
      r.link.transact({wr(BOARD_LINK_CTRL, kEnable | (1u << BOARD_LINK_CTRL_RESUME_LSB))});
      ++r.res.wdog_trips;
    }
  }
}

std::uint32_t read_word(LinkClient& link, std::uint8_t word) { return link.transact({rd(word)}).data[0]; }

}  // namespace

void check_board(LinkClient& link) {
  link.sync(BOARD_LINK_ID);
  const Reply r = link.transact({rd(BOARD_INTERP_ID), rd(BOARD_AXIS3_ID), rd(BOARD_LINK_ID)});
  if (r.data[0] != BOARD_INTERP_ID_RESET || r.data[1] != BOARD_AXIS3_ID_RESET || r.data[2] != BOARD_LINK_ID_RESET) {
    char b[128];
    std::snprintf(b, sizeof b, "not a contour board: IDs 0x%08X 0x%08X 0x%08X", r.data[0], r.data[1], r.data[2]);
    throw LinkError(b);
  }
}

StreamResult stream_chords(LinkClient& link, Transport& t, const std::vector<Chord3>& chords,
                           const StreamConfig& cfg, const std::function<void(const Progress&)>& progress,
                           const std::atomic<bool>* stop) {
  Run r{link, chords, cfg};
  check_board(link);
  const std::uint32_t params = read_word(link, BOARD_AXIS3_PARAMS);
  r.depth = (params & BOARD_AXIS3_PARAMS_QDEPTH_MASK) >> BOARD_AXIS3_PARAMS_QDEPTH_LSB;
  r.width = (params & BOARD_AXIS3_PARAMS_W_MASK) >> BOARD_AXIS3_PARAMS_W_LSB;
  for (std::size_t k = 0; k < chords.size(); ++k) chord_ops(chords[k], k, cfg, r.width);  // refuse before moving
  link.transact({wr(BOARD_AXIS3_CTRL, (1u << BOARD_AXIS3_CTRL_ABORT_LSB) | (1u << BOARD_AXIS3_CTRL_CLEAR_LSB)),
                 wr(BOARD_AXIS3_CYCLE, static_cast<std::uint32_t>(std::lround(cfg.cycle_s * cfg.clock_hz))),
                 wr(BOARD_AXIS3_STEP_LEN, cfg.step_len), wr(BOARD_AXIS3_STEP_SPACE, cfg.step_space),
                 wr(BOARD_LINK_WDOG, cfg.wdog_clocks),
                 wr(BOARD_LINK_CTRL, kEnable | (1u << BOARD_LINK_CTRL_RESUME_LSB))});
  r.res.start = read_positions(link);
  const std::uint32_t chords0 = read_word(link, BOARD_AXIS3_CHORDS);
  r.res.expected = r.res.start;
  for (const Chord3& c : chords) {
    r.res.expected[0] += c.dx;
    r.res.expected[1] += c.dy;
    r.res.expected[2] += c.dz;
  }
  r.prog.total = chords.size();
  r.prog.pos = r.res.start;
  link.on_reply = [&](const Reply& rep) {
    r.wdog_seen = rep.flag(BOARD_FLAG_WDOG);
    if (!r.wdog_seen) r.resume_posted = false;
    r.prog.level = rep.level3;
    r.prog.pos = reply_positions(rep);
    ++r.prog.replies;
  };
  r.last_post = t.now_s();
  while (r.next < chords.size() || link.in_flight() != 0) {
    if (stop && stop->load()) break;
    if (link.in_flight() < 8 && r.next < chords.size()) post_chords(r, t);
    post_service(r, t);
    link.pump(0.001);
    r.prog.sent = r.next;
    if (progress) progress(r.prog);
  }
  if (stop && stop->load()) stop_motion(r, t);
  else finish(r);
  link.on_reply = nullptr;
  r.res.end = read_positions(link);
  r.res.chords = read_word(link, BOARD_AXIS3_CHORDS) - chords0;
  r.res.underruns = read_word(link, BOARD_AXIS3_UNDERRUNS);
  r.res.link = link.stats();
  return r.res;
}

}  // namespace contour::board
