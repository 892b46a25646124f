#include "engines.hpp"

#include <verilated.h>
#include <verilated_fst_sc.h>

#include <cstdint>
#include <cstdio>
#include <functional>
#include <fstream>
#include <stdexcept>

#include "Vcosim_board.h"
#include "Vcosim_interp.h"
#include "interp/hw_order.hpp"
#include "interp_regs.h"
#include "sw8085/interp/host.hpp"
#include "sim/cli/numbers.hpp"
#include "sw8085/interp/mailbox.hpp"

using sc_core::sc_time;
using sc_core::sc_time_stamp;
using sc_core::SC_ZERO_TIME;

namespace contour::cosim {

namespace {

// Waits until the next multiple of `period` (now if on one): a clock that
// was stopped restarts on its grid.
void align(const sc_time& period) {
  const auto rem = sc_time_stamp().value() % period.value();
  if (rem) sc_core::wait(sc_time::from_value(period.value() - rem));
}

Pulse step_pulse(Axis a, bool dir_negative) { return Pulse{a, static_cast<std::int8_t>(dir_negative ? -1 : +1)}; }

// The move the program works on (or finished last) and its position, from
// the mailbox: the slot MB_ACTIVE names, else (idle) the latest write whose
// slot says done. Nothing when no move has started. The first is the move's
// index (a long line's segments map to their line); the state is in the
// whole move's terms.
std::optional<std::pair<std::size_t, State>> current_move(std::span<const std::uint8_t, 256> mb,
                                                          const sw8085::Codes& codes, const SlotLog& log) {
  const std::uint8_t active = mb[sw8085::kActive];
  int pick = -1;
  for (int w : log.in_slot)
    if (w >= 0 && log.writes[w].base == active) pick = w;
  if (pick < 0)
    for (int w : log.in_slot)
      if (w >= 0 && codes.is_done(mb[log.writes[w].base])) pick = std::max(pick, w);
  if (pick < 0) return std::nullopt;
  return std::make_pair(log.move_of[pick], sw8085::decode(log.writes[pick], mb, codes, 0));
}

// The engine's position at the end of a case (absolute, on the case's
// path), from the mailbox; a mailbox that does not decode is an error of the
// run, and the position is then unknown.
void read_final_position(std::span<const std::uint8_t, 256> mb, const sw8085::Codes& codes,
                         const SlotLog& log, const std::vector<Placed>& moves, EngineRun& run) {
  run.position_known = true;
  run.x = run.y = 0;
  try {
    if (const auto cur = current_move(mb, codes, log)) {
      run.x = moves[cur->first].origin_x + cur->second.x;
      run.y = moves[cur->first].origin_y + cur->second.y;
    }
  } catch (const std::exception& e) {
    run.position_known = false;
    run.error += (run.error.empty() ? "" : "; ") + std::string("mailbox: ") + e.what();
  }
}

}  // namespace

// --- faults --------------------------------------------------------------------

Fault parse_fault(const std::string& text) {
  const auto c1 = text.find(':');
  const auto c2 = c1 == std::string::npos ? std::string::npos : text.find(':', c1 + 1);
  if (c2 == std::string::npos)
    throw std::invalid_argument("--inject '" + text + "': expected ENGINE:drop|swap|flip:N");
  Fault f;
  f.engine = text.substr(0, c1);
  const std::string kind = text.substr(c1 + 1, c2 - c1 - 1), n = text.substr(c2 + 1);
  if (kind == "drop") f.kind = Fault::Kind::Drop;
  else if (kind == "swap") f.kind = Fault::Kind::Swap;
  else if (kind == "flip") f.kind = Fault::Kind::Flip;
  else throw std::invalid_argument("--inject '" + text + "': fault '" + kind + "' is not drop, swap or flip");
  bool known = false;
  for (const auto& e : engine_names()) known |= e == f.engine;
  if (!known) throw std::invalid_argument("--inject '" + text + "': unknown engine '" + f.engine + "'");
  std::int64_t v = 0;  // the CLI's number rules (sim/cli/numbers.hpp): "-1" is no pulse number
  if (cli::read_int(n, v) != cli::IntRead::Ok || v < 1)
    throw std::invalid_argument("--inject '" + text + "': pulse number '" + n + "' is not a positive integer");
  f.at = static_cast<std::uint64_t>(v);
  return f;
}

std::string to_string(const Fault& f) {
  const char* kind = f.kind == Fault::Kind::Drop ? "drop" : f.kind == Fault::Kind::Swap ? "swap" : "flip";
  return f.engine + ":" + kind + ":" + std::to_string(f.at);
}

void FaultInjector::pulse(const Pulse& p, const std::string& state) {
  ++n_;
  switch (fault_.kind) {
    case Fault::Kind::Drop:
      if (n_ != fault_.at) next_.pulse(p, state);
      return;
    case Fault::Kind::Flip:
      if (n_ == fault_.at) next_.pulse(Pulse{p.axis, static_cast<std::int8_t>(-p.sign)}, state);
      else next_.pulse(p, state);
      return;
    case Fault::Kind::Swap:
      if (n_ == fault_.at) {
        held_ = {p, state};  // goes out after the next one
        return;
      }
      next_.pulse(p, state);
      if (held_) {
        next_.pulse(held_->first, held_->second);
        held_.reset();
      }
      return;
  }
}

// --- model ---------------------------------------------------------------------

ModelCosimEngine::ModelCosimEngine(sc_core::sc_module_name n) : CosimEngine(n) {
  SC_METHOD(on_cmd);
  sensitive << i_cmd.pos();
  dont_initialize();
}

void ModelCosimEngine::begin_case(const Case& c) {
  moves_ = place(c.moves);
  next_ = 0;
  cur_ = nullptr;
  active_ = true;
  start_next();
}

bool ModelCosimEngine::start_next() {
  lin_.reset();
  circ_.reset();
  cur_ = nullptr;
  while (next_ < moves_.size()) {
    cur_ = &moves_[next_++];
    const Move& m = cur_->move;
    if (m.is_arc()) circ_.emplace(m.xs, m.ys, m.xe, m.ye, m.sense);
    else lin_.emplace(m.xe, m.ye);
    if (!(lin_ ? lin_->done() : circ_->done())) return true;
  }
  cur_ = nullptr;
  return false;
}

void ModelCosimEngine::on_cmd() {
  if (!active_ || !cur_) return;
  const std::optional<Pulse> p = lin_ ? lin_->step() : circ_->step();
  const State s = lin_ ? lin_->state() : circ_->state();
  if (p) emit(*p, to_string(s));
  if (lin_ ? lin_->done() : circ_->done()) start_next();
}

void ModelCosimEngine::end_case(EngineRun& run) {
  active_ = false;
  run.overruns_known = true;  // the model never refuses a command pulse
  run.overruns = 0;
}

// --- the Verilated engines ------------------------------------------------------------

VerilatedCosimEngine::VerilatedCosimEngine(sc_core::sc_module_name n) : CosimEngine(n) {}

VerilatedCosimEngine::~VerilatedCosimEngine() { close_trace(); }

void VerilatedCosimEngine::open_trace(const std::string& path) {
  trace_ = std::make_unique<VerilatedFstSc>();
  trace_model(*trace_);
  trace_->open(path.c_str());
}

void VerilatedCosimEngine::close_trace() {
  if (trace_) trace_->close();
  trace_.reset();
}

void VerilatedCosimEngine::watch_step_pins() {
  SC_METHOD(on_step);
  sensitive << step_x_ << step_y_;
  dont_initialize();
}

void VerilatedCosimEngine::on_step() {
  const bool x = step_x_.read(), y = step_y_.read();
  if (x && !last_x_) emit(step_pulse(Axis::X, dir_x_.read()));
  if (y && !last_y_) emit(step_pulse(Axis::Y, dir_y_.read()));
  last_x_ = x;
  last_y_ = y;
}

// --- core: interp_top -----------------------------------------------------------------

// Register offsets and fields: the header generated from the one register
// table, rtl/interp/regmap.def (docs/regmap.md).
constexpr std::uint32_t kCtrlSrcPin = 1u << INTERP_CTRL_SRC_LSB;  // command source 1: the input pin

CoreCosimEngine::CoreCosimEngine(sc_core::sc_module_name n, double f_clk_hz, StepTiming timing, bool free_clock)
    : VerilatedCosimEngine(n),
      period_(sc_time::from_value(static_cast<sc_dt::uint64>(1e12 / f_clk_hz + 0.5))),
      timing_(timing),
      free_clock_(free_clock) {
  // Clocks the core needs after a command edge to settle: the pin
  // synchroniser, the datapath, and one step through the output stage.
  awake_cycles_ = 64 + 2ull * (timing.len + timing.space + timing.setup + timing.hold);
  top_ = std::make_unique<Vcosim_interp>("interp_top");
  top_->i_clk(clk_);
  top_->i_rst(rst_);
  top_->i_wb_cyc(cyc_);
  top_->i_wb_stb(stb_);
  top_->i_wb_we(we_);
  top_->i_wb_adr(adr_);
  top_->i_wb_dat(wdat_);
  top_->o_wb_dat(rdat_);
  top_->o_wb_ack(ack_);
  top_->i_cmd_pin(i_cmd);
  top_->i_cmd_ce(one_);
  top_->o_step_x(step_x_);
  top_->o_dir_x(dir_x_);
  top_->o_step_y(step_y_);
  top_->o_dir_y(dir_y_);
  top_->o_pulse(pulse_);
  top_->o_pulse_y(pulse_y_);
  top_->o_pulse_neg(pulse_neg_);
  top_->o_busy(busy_);
  SC_THREAD(clock_thread);
  SC_THREAD(feeder_thread);
  SC_METHOD(on_cmd);
  sensitive << i_cmd.pos();
  dont_initialize();
  watch_step_pins();
}

CoreCosimEngine::~CoreCosimEngine() { close_trace(); }

void CoreCosimEngine::trace_model(VerilatedFstSc& fst) { top_->trace(&fst, 99); }

void CoreCosimEngine::keep_awake(std::uint64_t cycles) {
  const sc_time until = sc_time_stamp() + period_ * static_cast<double>(cycles);
  if (until > run_until_) run_until_ = until;
  wake_.notify(SC_ZERO_TIME);
}

void CoreCosimEngine::clock_thread() {
  const sc_time half = period_ / 2.0;
  const sc_time rest = period_ - half;
  while (true) {
    if (!free_clock_ && sc_time_stamp() >= run_until_) {
      sc_core::wait(wake_);
      continue;
    }
    align(period_);
    clk_.write(true);
    ++clocks_;
    sc_core::wait(half);
    clk_.write(false);
    sc_core::wait(rest);
  }
}

void CoreCosimEngine::on_cmd() { keep_awake(awake_cycles_); }

void CoreCosimEngine::wb_cycle(bool we, std::uint32_t adr, std::uint32_t v, std::uint32_t* out) {
  keep_awake(64);
  sc_core::wait(clk_.negedge_event());
  cyc_.write(true);
  stb_.write(true);
  we_.write(we);
  adr_.write(adr);
  wdat_.write(v);
  for (int n = 0;; ++n) {
    if (n > 32) throw std::runtime_error("core: no Wishbone ACK at offset " + std::to_string(adr));
    keep_awake(64);
    sc_core::wait(clk_.negedge_event());
    if (ack_.read()) break;
  }
  if (out) *out = rdat_.read();
  cyc_.write(false);
  stb_.write(false);
  we_.write(false);
}

void CoreCosimEngine::wb_write(std::uint32_t adr, std::uint32_t v) { wb_cycle(true, adr, v, nullptr); }

std::uint32_t CoreCosimEngine::wb_read(std::uint32_t adr) {
  std::uint32_t v = 0;
  wb_cycle(false, adr, 0, &v);
  return v;
}

namespace {

// The host's part (docs/regmap.md) for one move: validate, then stage
// magnitudes, signs, and for an arc the start quadrant and crossings.
void stage_move(const Move& m, const std::function<void(std::uint32_t, std::uint32_t)>& write) {
  validate<24>(m);
  auto mag = [](std::int64_t v) { return static_cast<std::uint32_t>(v < 0 ? -v : v); };
  std::uint32_t mode = 0;
  if (m.is_arc()) {
    const auto plan = Circular<24>::validate(m.xs, m.ys, m.xe, m.ye, m.sense);
    mode = INTERP_BLK_MODE_ARC_MASK | (m.sense == Sense::CW ? INTERP_BLK_MODE_CW_MASK : 0u) |
           static_cast<std::uint32_t>(plan.q_start) << INTERP_BLK_MODE_Q_LSB |
           static_cast<std::uint32_t>(plan.crossings) << INTERP_BLK_MODE_K_LSB;
    const InOutMagnitudes io =
        inout_order(true, m.sense, plan.q_start, plan.crossings, mag(m.xs), mag(m.ys), mag(m.xe), mag(m.ye));
    write(INTERP_REG_BLK_CI, static_cast<std::uint32_t>(io.ci));
    write(INTERP_REG_BLK_CO, static_cast<std::uint32_t>(io.co));
    write(INTERP_REG_BLK_TI, static_cast<std::uint32_t>(io.ti));
    write(INTERP_REG_BLK_TO, static_cast<std::uint32_t>(io.to));
  } else {
    mode = (m.xe < 0 ? INTERP_BLK_MODE_SXN_MASK : 0u) | (m.ye < 0 ? INTERP_BLK_MODE_SYN_MASK : 0u);
    write(INTERP_REG_BLK_TI, mag(m.xe));  // a line: |Xe|, |Ye| (inout_order's line case)
    write(INTERP_REG_BLK_TO, mag(m.ye));
  }
  write(INTERP_REG_BLK_MODE, mode);
}

}  // namespace

// Stages and pushes `p`; false when the queue is full (then, with
// `probe_reject`, it pushes anyway once: the core must refuse it, set
// REJECT and queue nothing; CLEAR resets REJECT, and OVR_COUNT, so only
// before the first command pulse).
bool CoreCosimEngine::push_move(const Placed& p, bool probe_reject) {
  stage_move(p.move, [this](std::uint32_t a, std::uint32_t v) { wb_write(a, v); });
  if (wb_read(INTERP_REG_STATUS) & INTERP_STATUS_FULL_MASK) {
    if (waited_for_ != next_push_) ++events_["queue_full"], waited_for_ = next_push_;
    if (probe_reject && !events_.count("push_refused")) {
      const std::uint32_t level = wb_read(INTERP_REG_STATUS) >> INTERP_STATUS_LEVEL_LSB & 0xFFu;
      wb_write(INTERP_REG_PUSH, 1);
      const std::uint32_t st = wb_read(INTERP_REG_STATUS);
      if (!(st & INTERP_STATUS_REJECT_MASK) || (st >> INTERP_STATUS_LEVEL_LSB & 0xFFu) != level)
        throw std::runtime_error("core: a PUSH into the full queue was not refused");
      ++events_["push_refused"];
      wb_write(INTERP_REG_CTRL, INTERP_CTRL_CLEAR_MASK);
    }
    return false;
  }
  wb_write(INTERP_REG_PUSH, 1);
  if (wb_read(INTERP_REG_STATUS) & INTERP_STATUS_REJECT_MASK) throw std::runtime_error("core: PUSH refused");
  return true;
}

// Before each case: two moves pushed (the first one loaded, no command
// source yet), then ABORT; the core must drop both (not busy, queue empty).
// Were one left, it would run before the case's moves and the scoreboard
// would see its pulses.
void CoreCosimEngine::exercise_abort() {
  const Move junk[2] = {Move::line(7, -3), Move::arc(5, 0, 0, 5, Sense::CCW)};
  for (const Move& m : junk) {
    stage_move(m, [this](std::uint32_t a, std::uint32_t v) { wb_write(a, v); });
    wb_write(INTERP_REG_PUSH, 1);
  }
  for (int n = 0; !(wb_read(INTERP_REG_STATUS) & INTERP_STATUS_BUSY_MASK); ++n)
    if (n > 100) throw std::runtime_error("core: the core did not load the move to abort");
  wb_write(INTERP_REG_CTRL, INTERP_CTRL_ABORT_MASK);
  const std::uint32_t st = wb_read(INTERP_REG_STATUS);
  if ((st & INTERP_STATUS_BUSY_MASK) || !(st & INTERP_STATUS_EMPTY_MASK) || (st >> INTERP_STATUS_LEVEL_LSB & 0xFFu))
    throw std::runtime_error("core: ABORT left a move (STATUS " + std::to_string(st) + ")");
  ++events_["abort"];
}

void CoreCosimEngine::begin_case(const Case& c) {
  moves_ = place(c.moves);
  next_push_ = 0;
  waited_for_ = SIZE_MAX;
  error_.clear();
  keep_awake(64);
  rst_.write(true);
  for (int i = 0; i < 4; ++i) sc_core::wait(clk_.negedge_event());
  rst_.write(false);
  wb_write(INTERP_REG_STEP_LEN, timing_.len);
  wb_write(INTERP_REG_STEP_SPACE, timing_.space);
  wb_write(INTERP_REG_DIR_SETUP, timing_.setup);
  wb_write(INTERP_REG_DIR_HOLD, timing_.hold);
  exercise_abort();
  while (next_push_ < moves_.size() && push_move(moves_[next_push_], true)) ++next_push_;
  wb_write(INTERP_REG_CTRL, kCtrlSrcPin);
  // The first block is loaded before the first command pulse.
  for (int n = 0; !(wb_read(INTERP_REG_STATUS) & INTERP_STATUS_BUSY_MASK); ++n)
    if (n > 100) throw std::runtime_error("core: the core did not start the first move");
  if (next_push_ < moves_.size()) {
    feeding_ = true;
    feed_ev_.notify(SC_ZERO_TIME);
  }
}

// Pushes the moves that did not fit, as the queue makes room (polled every
// 2 us, well inside the 15 moves the queue holds), until end_case.
void CoreCosimEngine::feeder_thread() {
  while (true) {
    sc_core::wait(feed_ev_);
    feeder_busy_ = true;
    try {
      while (feeding_ && next_push_ < moves_.size()) {
        if (push_move(moves_[next_push_], false)) ++next_push_;
        else sc_core::wait(2, sc_core::SC_US);
      }
    } catch (const std::exception& e) {
      error_ = e.what();
    }
    feeder_busy_ = false;
    feeder_idle_.notify(SC_ZERO_TIME);
  }
}

void CoreCosimEngine::end_case(EngineRun& run) {
  feeding_ = false;
  while (feeder_busy_) sc_core::wait(feeder_idle_);
  run.error = error_;
  if (next_push_ < moves_.size())
    run.error += (run.error.empty() ? "" : "; ") + std::to_string(moves_.size() - next_push_) + " moves never pushed";
  run.overruns_known = true;
  run.overruns = wb_read(INTERP_REG_OVR_COUNT);
  run.position_known = true;
  run.x = static_cast<std::int32_t>(wb_read(INTERP_REG_POS_X));
  run.y = static_cast<std::int32_t>(wb_read(INTERP_REG_POS_Y));
  wb_write(INTERP_REG_CTRL, 0);
}

// --- iss: the program on the C++ ISS ------------------------------------------------

IssCosimEngine::IssCosimEngine(sc_core::sc_module_name n, double f_clk_hz)
    : CosimEngine(n), period_(sc_time::from_value(static_cast<sc_dt::uint64>(1e12 / f_clk_hz + 0.5))) {
  SC_THREAD(cpu_thread);
  SC_METHOD(on_cmd);
  sensitive << i_cmd;
  dont_initialize();
}

IssCosimEngine::~IssCosimEngine() = default;

void IssCosimEngine::begin_case(const Case& c) {
  moves_ = place(c.moves);
  next_move_ = 0;
  slots_.clear();
  pulses_ = 0;
  waited_ = 0;
  per_move_.clear();
  edge_ = false;
  error_.clear();
  host_ = std::make_unique<sw8085::Host>();  // boots: the program is in its idle loop
  feed();
  parked_ = false;
  active_ = true;
  started_.notify(SC_ZERO_TIME);
}

// Fills free slots: first the waiting segments of the last move queued (a
// line of more than 65536 P steps, sw8085::Host::pump), then new moves.
void IssCosimEngine::feed() {
  for (const auto& sm : host_->pump()) slots_.push(sm, next_move_ - 1);
  while (next_move_ < moves_.size() && host_->can_queue()) {
    slots_.push(host_->queue(moves_[next_move_].move), next_move_);
    ++next_move_;
    for (const auto& sm : host_->pump()) slots_.push(sm, next_move_ - 1);
  }
  // Both mailbox slots busy with a move waiting: the program's queue is full.
  if (next_move_ < moves_.size() && waited_ < next_move_ + 1) ++events_["queue_full"], waited_ = next_move_ + 1;
}

std::span<const std::uint8_t, 256> IssCosimEngine::mailbox() const {
  return std::span<const std::uint8_t, 256>(host_->bus().mem.data() + sw8085::kMailbox, 256);
}

void IssCosimEngine::collect() {
  auto& bus = host_->bus();
  for (const auto& w : bus.outs) {
    if (w.port != sw8085::kPortStep) continue;
    const auto p = sw8085::decode_pattern(w.value);
    if (!p) {
      error_ = "OUT 10h with a bad step pattern " + std::to_string(w.value);
      continue;
    }
    ++pulses_;
    std::string state;
    try {
      if (auto cur = current_move(mailbox(), host_->codes(), slots_)) {
        // The pulse belongs to this move: count it there.
        if (per_move_.size() < moves_.size()) per_move_.resize(moves_.size(), 0);
        cur->second.pulses = ++per_move_[cur->first];
        state = "move " + std::to_string(cur->first + 1) + ": " + to_string(cur->second);
      }
    } catch (const std::exception& e) {
      state = std::string("(mailbox: ") + e.what() + ")";
    }
    emit(*p, state);
  }
  bus.outs.clear();
}

void IssCosimEngine::cpu_thread() {
  while (true) {
    if (!active_ || !error_.empty()) {
      parked_ = true;
      parked_ev_.notify(SC_ZERO_TIME);
      sc_core::wait(started_);
      continue;
    }
    auto& m = host_->machine();
    // Halted with nothing pending (the last step was an idle unit): sleep
    // until the next command edge instead of stepping 1-T idle units.
    if (m.halted() && !edge_ && m.last().kind == i8085::StepKind::idle) {
      sc_core::wait(rise_ | stop_);
      if (active_) align(period_);
      continue;
    }
    edge_ = false;
    const int t = m.step();
    if (!host_->bus().fault.empty()) {
      char buf[32];
      std::snprintf(buf, sizeof buf, " (PC was %04X)", m.last().pc);
      error_ = host_->bus().fault + buf;
    }
    sc_core::wait(period_ * static_cast<double>(t));
    collect();
    feed();
  }
}

void IssCosimEngine::on_cmd() {
  if (!active_) return;
  const bool level = i_cmd.read();
  host_->machine().set_rst75(level);
  if (level) {
    ++host_->bus().edges;
    edge_ = true;
    rise_.notify(SC_ZERO_TIME);
  }
}

void IssCosimEngine::end_case(EngineRun& run) {
  active_ = false;
  stop_.notify(SC_ZERO_TIME);
  while (!parked_) sc_core::wait(parked_ev_);
  run.error = error_;
  run.overruns_known = true;
  run.overruns = host_->overruns();
  read_final_position(mailbox(), host_->codes(), slots_, moves_, run);
}

// --- cpu: board8085 --------------------------------------------------------------

void write_rom_memh(const std::string& path) {
  const auto& img = sw8085::Program::builtin().image;
  std::ofstream f(path);
  if (!f) throw std::runtime_error(path + ": cannot write the ROM image");
  char buf[8];
  for (std::size_t a = 0; a < sw8085::kRomEnd; ++a) {
    std::snprintf(buf, sizeof buf, "%02X\n", img[a]);
    f << buf;
  }
  if (!f) throw std::runtime_error(path + ": write failed");
}

BoardCosimEngine::BoardCosimEngine(sc_core::sc_module_name n, double f_clk_hz, const std::string& rom_memh)
    : VerilatedCosimEngine(n),
      clk_("clk", sc_time::from_value(static_cast<sc_dt::uint64>(1e12 / f_clk_hz + 0.5))),
      codes_(std::make_unique<sw8085::Codes>(sw8085::Codes::from_symbols(sw8085::Program::builtin().symbols))) {
  const std::string plus = "+rom=" + rom_memh;
  const char* argv[] = {"contour-cosim", plus.c_str()};
  Verilated::commandArgs(2, argv);
  top_ = std::make_unique<Vcosim_board>("board8085");
  top_->i_clk(clk_);
  top_->i_rst(rst_);
  top_->i_cmd(cmd_sync_);
  top_->i_trap(zero_);
  top_->i_rst65(zero_);
  top_->i_rst55(zero_);
  top_->i_intr(zero_);
  top_->i_intr_vec(intr_vec_);
  top_->o_step_x(step_x_);
  top_->o_step_y(step_y_);
  top_->o_step_z(step_z_);
  top_->o_dir_x(dir_x_);
  top_->o_dir_y(dir_y_);
  top_->o_dir_z(dir_z_);
  top_->o_done(done_);
  top_->o_debug(debug_);
  top_->o_debug_we(debug_we_);
  top_->i_host_addr(host_addr_);
  top_->i_host_wdata(host_wdata_);
  top_->i_host_we(host_we_);
  top_->o_host_rdata(host_rdata_);
  top_->o_host_overrun(host_ovr_);
  top_->o_cpu_addr(cpu_addr_);
  top_->o_cpu_dout(cpu_dout_);
  top_->o_cpu_wr(cpu_wr_);
  top_->o_cpu_io(cpu_io_);
  top_->o_retire(retire_);
  top_->o_dbg_kind(dbg_kind_);
  top_->o_dbg_irq(dbg_irq_);
  top_->o_dbg_ipc(dbg_ipc_);
  top_->o_dbg_op(dbg_op_);
  top_->o_dbg_pc(dbg_pc_);
  top_->o_dbg_sp(dbg_sp_);
  top_->o_dbg_regs(dbg_regs_);
  top_->o_halted(halted_);
  top_->o_ie(ie_);
  top_->o_sod(sod_);
  SC_THREAD(host_thread);
  SC_METHOD(on_clk);
  sensitive << clk_.posedge_event();
  dont_initialize();
  watch_step_pins();
}

BoardCosimEngine::~BoardCosimEngine() { close_trace(); }

void BoardCosimEngine::trace_model(VerilatedFstSc& fst) { top_->trace(&fst, 99); }

// The command input, registered into the board's clock domain (the board
// wants it synchronous: it drives RST 7.5 and the edge counter).
void BoardCosimEngine::on_clk() { cmd_sync_.write(i_cmd.read()); }

void BoardCosimEngine::poke(std::uint8_t addr, std::uint8_t v) {
  sc_core::wait(clk_.negedge_event());
  host_addr_.write(addr);
  host_wdata_.write(v);
  host_we_.write(true);
  sc_core::wait(clk_.negedge_event());
  host_we_.write(false);
}

std::uint8_t BoardCosimEngine::peek(std::uint8_t addr) {
  sc_core::wait(clk_.negedge_event());
  host_addr_.write(addr);
  sc_core::wait(clk_.negedge_event());  // the read port answers one clock later
  return static_cast<std::uint8_t>(host_rdata_.read());
}

bool BoardCosimEngine::slot_free(int i) {
  // A finished slot is free once the program has left it (sw8085 host rule).
  if (slots_.in_slot[i] < 0) return true;
  const std::uint8_t base = sw8085::kSlots[i];
  const std::uint8_t mode = peek(base);
  if (!codes_->is_done(mode)) return false;
  return peek(sw8085::kActive) != base;
}

void BoardCosimEngine::queue_next() {
  const std::uint8_t base = sw8085::kSlots[slots_.next_slot];
  std::array<std::uint8_t, 256> img{};
  if (!segmenter_) segmenter_.emplace(moves_[next_move_].move);
  auto sm = segmenter_->next(base, *codes_, std::span<std::uint8_t, 256>(img));
  const int lo = base + sw8085::kSlotLow, hi = base + sw8085::kStatus;  // the slot
  for (int a = 0; a < 256; ++a)
    if (img[a] != 0 && (a < lo || a > hi))
      throw std::logic_error("cpu: sw8085::encode wrote outside its slot at " + std::to_string(a));
  for (int a = lo; a < hi; ++a) poke(static_cast<std::uint8_t>(a), img[a]);
  poke(static_cast<std::uint8_t>(hi), sw8085::kQueued);
  slots_.push(sm, next_move_);
  if (!segmenter_->more()) segmenter_.reset(), ++next_move_;  // else the move's next segment
}

void BoardCosimEngine::host_thread() {
  while (true) {
    if (request_ == Request::Begin) {
      try {
        rst_.write(true);
        for (int a = 0; a < 256; ++a) poke(static_cast<std::uint8_t>(a), 0);
        sc_core::wait(clk_.negedge_event());
        rst_.write(false);
        for (int n = 0; peek(sw8085::kReady) != sw8085::kReadyMagic; ++n)
          if (n > 50000) throw std::runtime_error("the program did not become ready");
        if (peek(sw8085::kLayout) != sw8085::kLayoutVersion) throw std::runtime_error("mailbox layout version mismatch");
        while (next_move_ < moves_.size() && slot_free(slots_.next_slot)) queue_next();
      } catch (const std::exception& e) {
        error_ = e.what();
      }
      active_ = true;
      request_ = Request::None;
      reply_.notify(SC_ZERO_TIME);
    } else if (request_ == Request::End) {
      active_ = false;
      std::array<std::uint8_t, 256> mb{};
      for (int a = 0; a < 256; ++a) mb[a] = peek(static_cast<std::uint8_t>(a));
      final_mailbox_ = mb;
      request_ = Request::None;
      reply_.notify(SC_ZERO_TIME);
    } else if (active_ && error_.empty() && next_move_ < moves_.size()) {
      if (slot_free(slots_.next_slot)) queue_next();
      else if (waited_ < next_move_ + 1) ++events_["queue_full"], waited_ = next_move_ + 1;  // both slots busy
    } else {
      sc_core::wait(request_ev_);
    }
  }
}

void BoardCosimEngine::begin_case(const Case& c) {
  moves_ = place(c.moves);
  next_move_ = 0;
  segmenter_.reset();
  slots_.clear();
  waited_ = 0;
  error_.clear();
  request_ = Request::Begin;
  request_ev_.notify(SC_ZERO_TIME);
  sc_core::wait(reply_);
}

void BoardCosimEngine::end_case(EngineRun& run) {
  request_ = Request::End;
  request_ev_.notify(SC_ZERO_TIME);
  sc_core::wait(reply_);
  run.error = error_;
  if (host_ovr_.read()) run.error += (run.error.empty() ? "" : "; ") + std::string("a host mailbox write was lost");
  const auto& mb = final_mailbox_;
  run.overruns_known = true;
  run.overruns = mb[sw8085::kOverruns] | mb[sw8085::kOverruns + 1] << 8 | mb[sw8085::kOverruns + 2] << 16;
  read_final_position(std::span<const std::uint8_t, 256>(mb), *codes_, slots_, moves_, run);
}

}  // namespace contour::cosim
