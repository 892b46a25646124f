// `contour table1`: paper A's Table 1 (the 8085 routine per command pulse:
// instructions, clock cycles, time at 3 MHz, highest command rate),
// measured on our 8085 program and printed beside the paper's row.
//
// Everything is measured, on a fixed standard set of moves:
//   - per command pulse: T-states from the RST 7.5 acknowledge to the end of
//     the RET (both included), and the instructions executed;
//   - the highest rate: the moves are driven with command pulses every P
//     T-states, P lowered until the program's own overrun counter (IN 11h
//     edge count vs pulses served, in the mailbox) counts one; the rate kept
//     up with is 3 MHz / P_min.
// The paper's own measure (the longest routine and 1/T) is printed first;
// every figure says how it was obtained.
//
// On a slow engine (cpu: the Verilated board) the command period is first
// bisected on the ISS, which is T-state exact against the board (ctest
// -L cpu8085); the board then runs the per-pulse measurement and the two
// drives that settle the figure on its own: no overrun at P_min, one at
// P_min - 1 (a full bisection on the board if either disagrees). The
// expected T-states are known before the board starts, hence the time.
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iomanip>
#include <memory>
#include <numeric>
#include <sstream>
#include <stdexcept>
#include <tuple>
#include <utility>

#include "args.hpp"
#include "interp/circular.hpp"
#include "registry.hpp"
#include "sw8085/interp/host.hpp"
#include "sw8085/interp/table1_moves.hpp"
#if __has_include("board_machine.hpp")
#include "board_machine.hpp"
#endif

namespace contour::cli {
namespace {

const char* kHelp =
    "usage: contour table1 [--format text|json] [--engine iss|cpu] [--progress|--no-progress]\n"
    "Paper A's Table 1 reproduced: the 8085 program (sw8085/interp) per command\n"
    "pulse, measured over a standard set of lines and arcs. First the paper's own\n"
    "measure: the longest routine (T-states from the RST 7.5 acknowledge to the end\n"
    "of its RET), its time at 3 MHz and the rate 1/T it allows; then the routine's\n"
    "mean and shortest length; then the highest command rate kept up with, found by\n"
    "bisecting the command period until the program counts its first overrun (the\n"
    "paper did not measure this one). --engine cpu measures on the Verilog board,\n"
    "Verilated (the period bisected on the ISS first, then confirmed on the board).\n"
    "A progress line on stderr when stderr is a terminal (--progress: always,\n"
    "--no-progress: never), after a first line that says how long the run will take.\n";

constexpr double kClockHz = 3.0e6;

struct PaperRow {
  int instructions, tstates, time_us;
  double kpps;
};
constexpr PaperRow kPaperLinear{99, 737, 246, 4.0};
constexpr PaperRow kPaperCircular{126, 917, 306, 3.0};

struct Row {
  int instructions_max = 0;
  double instructions_mean = 0;
  int t_min = 0, t_max = 0;
  double t_mean = 0;
  std::uint64_t pulses = 0;
  int period_min = 0;  // smallest command period (T-states) with no overrun
  std::string period_method;  // how period_min was found
  std::string worst;   // the move and pulse of t_max
};

// ---- Progress ---------------------------------------------------------------

// T-states simulated against the expected total, on one stderr line redrawn
// in place (only when on), with the time left at the rate seen so far.
class Progress {
 public:
  explicit Progress(bool on) : on_(on) {}
  ~Progress() { clear(); }
  // A new phase: its name, the T-states it is expected to take (0: not
  // known), the clock of its rate restarted.
  void phase(const std::string& what, std::uint64_t expected_tstates) {
    what_ = what;
    start_ = Clock::now();
    phase_start_ = done_;
    total_ = expected_tstates;
    draw();
  }
  void label(const std::string& what) {
    what_ = what;
    draw();
  }
  void add(int t) {
    done_ += static_cast<std::uint64_t>(t);
    if (on_ && done_ >= next_check_) {
      next_check_ = done_ + 1000000;
      if (seconds() >= next_draw_s_) draw();
    }
  }
  // T-states per second in this phase.
  double rate_so_far() const { return double(done_ - phase_start_) / std::max(seconds(), 1e-3); }
  std::uint64_t done() const { return done_; }
  double seconds() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }
  void clear() {
    if (on_ && drawn_) std::fputs("\r\033[K", stderr);
    drawn_ = false;
  }

 private:
  using Clock = std::chrono::steady_clock;
  // At most five times a second.
  void draw() {
    if (!on_) return;
    next_draw_s_ = seconds() + 0.2;
    const double rate = seconds() > 0.5 ? rate_so_far() : 0.0;
    const std::uint64_t done = done_ - phase_start_;
    char what[96];
    if (total_ > 0)
      std::snprintf(what, sizeof what, "%.0f%% of %.0f M T-states", std::min(100.0, 100.0 * double(done) / double(total_)),
                    double(total_) / 1e6);
    else
      std::snprintf(what, sizeof what, "%.0f M T-states", double(done) / 1e6);
    char left[32] = "";
    if (rate > 0 && total_ > done) std::snprintf(left, sizeof left, ", %.0f s left", double(total_ - done) / rate);
    std::fprintf(stderr, "\r\033[Ktable1: %s: %s%s", what_.c_str(), what, left);
    std::fflush(stderr);
    drawn_ = true;
  }
  bool on_;
  bool drawn_ = false;
  std::string what_;
  std::uint64_t done_ = 0, total_ = 0, next_check_ = 0, phase_start_ = 0;
  double next_draw_s_ = 0;
  Clock::time_point start_ = Clock::now();
};

// A machine that reports the T-states of every step to a Progress.
class CountedMachine final : public i8085::Machine {
 public:
  CountedMachine(std::unique_ptr<i8085::Machine> m, Progress& p) : m_(std::move(m)), p_(p) {}
  i8085::Mode mode() const override { return m_->mode(); }
  void reset() override { m_->reset(); }
  int step() override {
    const int t = m_->step();
    p_.add(t);
    return t;
  }
  std::uint64_t tstates() const override { return m_->tstates(); }
  i8085::Regs regs() const override { return m_->regs(); }
  void set_regs(const i8085::Regs& r) override { m_->set_regs(r); }
  bool halted() const override { return m_->halted(); }
  bool ie() const override { return m_->ie(); }
  const i8085::Step& last() const override { return m_->last(); }
  void set_trap(bool level) override { m_->set_trap(level); }
  void set_rst75(bool level) override { m_->set_rst75(level); }
  void set_rst65(bool level) override { m_->set_rst65(level); }
  void set_rst55(bool level) override { m_->set_rst55(level); }
  void set_intr(bool level) override { m_->set_intr(level); }

 private:
  std::unique_ptr<i8085::Machine> m_;
  Progress& p_;
};

i8085::MachineFactory counted(i8085::MachineFactory f, Progress& p) {
  return [f = std::move(f), &p](i8085::Bus& bus, i8085::Mode mode) -> std::unique_ptr<i8085::Machine> {
    return std::make_unique<CountedMachine>(f(bus, mode), p);
  };
}

// ---- Measurement --------------------------------------------------------------

// Per command pulse: T-states and instructions of every routine.
Row measure_pulses(const std::vector<Move>& moves, const i8085::MachineFactory& factory) {
  Row row;
  std::vector<sw8085::CommandResult> all;
  sw8085::Host host(sw8085::Program::builtin(), factory);
  for (const auto& m : moves) {
    std::vector<sw8085::CommandResult> cs;
    host.run(m, &cs);
    for (std::size_t i = 0; i < cs.size(); ++i)
      if (cs[i].tstates > row.t_max) {
        row.t_max = cs[i].tstates;
        row.worst = describe(m) + ", pulse " + std::to_string(i + 1);
      }
    all.insert(all.end(), cs.begin(), cs.end());
  }
  if (all.empty()) throw std::logic_error("table1: no command pulses measured");
  row.pulses = all.size();
  row.t_min = all.front().tstates;
  double ts = 0, is = 0;
  for (const auto& c : all) {
    row.t_min = std::min(row.t_min, c.tstates);
    row.instructions_max = std::max(row.instructions_max, c.instructions);
    ts += c.tstates;
    is += c.instructions;
  }
  row.t_mean = ts / double(all.size());
  row.instructions_mean = is / double(all.size());
  return row;
}

// Whether the program keeps up with a command every `period` T-states.
bool keeps_up(const std::vector<Move>& moves, const i8085::MachineFactory& factory, int period) {
  sw8085::Host host(sw8085::Program::builtin(), factory);
  const auto t = host.drive(moves, double(period));
  return t.all_done && t.overruns == 0;
}

int first_hi(const Row& r) { return std::max(4 * r.t_max, 400); }

// The smallest period with no overrun, by bisection on [lo, hi].
int bisect_period(const std::vector<Move>& moves, const i8085::MachineFactory& factory, int lo, int hi) {
  if (!keeps_up(moves, factory, hi))
    throw std::logic_error("table1: overruns even at one command every " + std::to_string(hi) + " T-states");
  while (hi - lo > 1) {
    const int mid = (lo + hi) / 2;
    (keeps_up(moves, factory, mid) ? hi : lo) = mid;
  }
  return hi;
}

// Expected T-states of driving the moves at `period`: one command per pulse
// while it keeps up; past that, about one routine per pulse.
double drive_tstates(const Row& r, int period) { return double(r.pulses) * std::max<double>(period, r.t_mean); }

// Expected T-states of a bisection on [20, first_hi], the answer taken
// halfway between the mean and the longest routine.
double bisection_tstates(const Row& r) {
  const int guess = static_cast<int>((r.t_mean + r.t_max) / 2);
  int lo = 20, hi = first_hi(r);
  double sum = drive_tstates(r, hi);
  while (hi - lo > 1) {
    const int mid = (lo + hi) / 2;
    sum += drive_tstates(r, mid);
    (mid >= guess ? hi : lo) = mid;
  }
  return sum;
}

struct Rows {
  Row lin, circ;
};

// T-states per second of CPU time of an engine, over a short line.
double engine_rate(const i8085::MachineFactory& factory) {
  const auto t0 = std::chrono::steady_clock::now();
  sw8085::Host host(sw8085::Program::builtin(), factory);
  const std::uint64_t start = host.machine().tstates();
  host.run(Move::line(700, 300));
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return double(host.machine().tstates() - start) / std::max(s, 1e-3);
}

// One row on the slow engine, its period confirmed around the ISS's.
Row confirm_row(const std::vector<Move>& moves, const i8085::MachineFactory& factory, const Row& iss,
                const std::string& engine) {
  Row row = measure_pulses(moves, factory);
  const int p = iss.period_min;
  if (keeps_up(moves, factory, p) && !keeps_up(moves, factory, p - 1)) {
    row.period_min = p;
    row.period_method = "bisection on the ISS, confirmed on " + engine + " (no overrun at P min, one at P min - 1)";
  } else {
    row.period_min = bisect_period(moves, factory, 20, first_hi(row));
    row.period_method = "bisection on " + engine + " (the ISS's period did not hold there)";
  }
  return row;
}

// ---- Running ------------------------------------------------------------------

struct Plan {
  std::string engine;
  i8085::MachineFactory factory;  // the engine's, uncounted
  bool progress = false;
};

void say(Progress& progress, const std::string& line) {
  progress.clear();
  std::fprintf(stderr, "table1: %s\n", line.c_str());
  std::fflush(stderr);
}

std::string about(double seconds) {
  char buf[64];
  if (seconds < 90) std::snprintf(buf, sizeof buf, "about %.0f s", std::max(1.0, seconds));
  else std::snprintf(buf, sizeof buf, "about %.1f min", seconds / 60);
  return buf;
}

// The ISS's rows (the result on engine iss, the plan on any other), then the
// slow engine's. With progress on, a first line on stderr says how long it
// will take (so a pipe or a log gets only the table).
Rows run_table1(const Plan& plan, Progress& progress) {
  const auto iss = counted(i8085::make_iss, progress);
  sw8085::Program::builtin();  // loaded before the clock starts
  progress.phase("per-pulse lengths on the ISS", 0);
  Rows r{measure_pulses(sw8085::table1_lines(), iss), measure_pulses(sw8085::table1_arcs(), iss)};
  const double measure_t = double(progress.done());  // the same on any T-state exact engine
  const double iss_rate = progress.rate_so_far();
  const double bisect_t = bisection_tstates(r.lin) + bisection_tstates(r.circ);
  double engine_t = 0, engine_s = 0, engine_tps = 0;
  if (plan.engine != "iss") {
    engine_tps = engine_rate(plan.factory);
    auto guess = [](const Row& w) { return static_cast<int>((w.t_mean + w.t_max) / 2); };
    engine_t = measure_t + 2 * (drive_tstates(r.lin, guess(r.lin)) + drive_tstates(r.circ, guess(r.circ)));
    engine_s = engine_t / engine_tps;
  }
  std::ostringstream first;
  first << "engine " << plan.engine << ", " << about(bisect_t / iss_rate + engine_s) << ": " << std::fixed
        << std::setprecision(0) << (measure_t + bisect_t) / 1e6 << " M T-states on the ISS";
  if (plan.engine != "iss")
    first << ", then " << engine_t / 1e6 << " M on engine " << plan.engine << " at " << std::setprecision(1)
          << engine_tps / 1e6 << " M T-states/s";
  if (plan.progress) say(progress, first.str());  // a terminal, or --progress
  progress.phase("command period bisected on the ISS", static_cast<std::uint64_t>(bisect_t));
  r.lin.period_min = bisect_period(sw8085::table1_lines(), iss, 20, first_hi(r.lin));
  r.circ.period_min = bisect_period(sw8085::table1_arcs(), iss, 20, first_hi(r.circ));
  r.lin.period_method = r.circ.period_method = "bisection on the ISS";
  if (plan.engine == "iss") return r;
  const auto engine = counted(plan.factory, progress);
  progress.phase("engine " + plan.engine + ": lines", static_cast<std::uint64_t>(engine_t));
  Rows e;
  e.lin = confirm_row(sw8085::table1_lines(), engine, r.lin, "engine " + plan.engine);
  progress.label("engine " + plan.engine + ": arcs");
  e.circ = confirm_row(sw8085::table1_arcs(), engine, r.circ, "engine " + plan.engine);
  return e;
}

// ---- Output -------------------------------------------------------------------

std::string fmt(double v, int decimals) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}

double kpps_of(int period) { return kClockHz / period / 1000.0; }

// The paper's measure first: tstates_max, its time and 1/T; then the rest.
std::string json_row(const Row& r, const PaperRow& p) {
  std::ostringstream o;
  o << "{\"tstates_max\": " << r.t_max << ", \"time_us_3mhz\": " << fmt(r.t_max / kClockHz * 1e6, 2)
    << ", \"kpps_from_tstates_max\": " << fmt(kpps_of(r.t_max), 2) << ", \"instructions\": " << r.instructions_max
    << ", \"worst\": \"" << r.worst << "\", \"tstates_min\": " << r.t_min << ", \"tstates_mean\": " << fmt(r.t_mean, 2)
    << ", \"instructions_mean\": " << fmt(r.instructions_mean, 2) << ", \"pulses\": " << r.pulses
    << ", \"kpps_3mhz\": " << fmt(kpps_of(r.period_min), 2) << ", \"period_min_tstates\": " << r.period_min
    << ", \"period_min_method\": \"" << r.period_method << "\""
    << ", \"paper\": {\"instructions\": " << p.instructions << ", \"tstates\": " << p.tstates
    << ", \"time_us\": " << p.time_us << ", \"kpps\": " << fmt(p.kpps, 1) << "}}";
  return o.str();
}

void print_json(const Rows& r, const std::string& engine) {
  std::printf(
      "{\"linear\": %s, \"circular\": %s, \"engine\": \"%s\", \"clock_hz\": %.0f, \"measures\": {"
      "\"tstates_max\": \"the paper's measure: the longest routine, RST 7.5 acknowledge to the end of its RET\", "
      "\"kpps_from_tstates_max\": \"the paper's measure: 3 MHz / tstates_max, one command per routine\", "
      "\"kpps_3mhz\": \"bisection: 3 MHz / the shortest command period with no overrun counted "
      "(period_min_method)\"}}\n",
      json_row(r.lin, kPaperLinear).c_str(), json_row(r.circ, kPaperCircular).c_str(), engine.c_str(), kClockHz);
}

void print_text(const Rows& r, const std::string& engine) {
  std::printf("Paper A, Table 1: the 8085 routine per command pulse, 8085 at 3 MHz.\n");
  std::printf("ours: sw8085/interp on engine %s, measured over %llu + %llu command pulses.\n\n", engine.c_str(),
              static_cast<unsigned long long>(r.lin.pulses), static_cast<unsigned long long>(r.circ.pulses));
  std::printf("The paper's measure: the longest routine (T-states from the RST 7.5 acknowledge\n"
              "to the end of its RET) and the command rate 1/T it allows.\n");
  std::printf("%-9s %-5s %6s %8s %12s %14s\n", "routine", "", "instr", "T max", "us (T max)", "kpps (1/T max)");
  for (const auto& [name, row, paper] : {std::tuple{"linear", &r.lin, &kPaperLinear},
                                         std::tuple{"circular", &r.circ, &kPaperCircular}}) {
    std::printf("%-9s paper %6d %8d %12d %14s\n", name, paper->instructions, paper->tstates, paper->time_us,
                fmt(paper->kpps, 1).c_str());
    std::printf("%-9s ours  %6d %8d %12s %14s\n", "", row->instructions_max, row->t_max,
                fmt(row->t_max / kClockHz * 1e6, 1).c_str(), fmt(kpps_of(row->t_max), 2).c_str());
  }
  std::printf("longest routine: linear %s; circular %s\n\n", r.lin.worst.c_str(), r.circ.worst.c_str());
  std::printf("Routine length over all pulses (ours): T min / T mean.\n");
  std::printf("  linear %d / %s, circular %d / %s\n\n", r.lin.t_min, fmt(r.lin.t_mean, 1).c_str(), r.circ.t_min,
              fmt(r.circ.t_mean, 1).c_str());
  std::printf("Highest command rate with no overrun counted (bisection of the command period;\n"
              "the RST 7.5 latch absorbs a rare long routine; the paper did not measure this):\n");
  for (const auto& [name, row] : {std::pair{"linear", &r.lin}, std::pair{"circular", &r.circ}})
    std::printf("  %-9s P min %5d T  %6s kpps  (%s)\n", name, row->period_min, fmt(kpps_of(row->period_min), 1).c_str(),
                row->period_method.c_str());
}

int cmd_table1(const std::vector<std::string>& argv) {
  Args a(argv, {"progress", "no-progress"}, {"format", "engine"});
  if (a.help()) {
    std::fputs(kHelp, stdout);
    return 0;
  }
  a.expect_positional({});
  const std::string format = a.option_or("format", "text");
  if (format != "text" && format != "json") throw UsageError("--format: unknown format '" + format + "' (text or json)");
  if (a.flag("progress") && a.flag("no-progress")) throw UsageError("--progress and --no-progress: give one");
  Plan plan;
  plan.engine = a.option_or("engine", "iss");
  if (plan.engine == "iss") plan.factory = i8085::make_iss;
#if __has_include("board_machine.hpp")
  if (plan.engine == "cpu") plan.factory = board8085::make_board_machine;
#endif
  if (!plan.factory) throw UsageError(unknown_engine(plan.engine, "iss|cpu"));
  plan.progress = a.flag("progress") || (!a.flag("no-progress") && isatty(STDERR_FILENO) != 0);
  Rows rows;
  {
    Progress progress(plan.progress);
    rows = run_table1(plan, progress);
  }
  if (format == "json")
    print_json(rows, plan.engine);
  else
    print_text(rows, plan.engine);
  return 0;
}

const CommandRegistrar kTable1{{"table1", "paper A's Table 1, measured on the 8085 program (ISS)", cmd_table1}};

}  // namespace
}  // namespace contour::cli
