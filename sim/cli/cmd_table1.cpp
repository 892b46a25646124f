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
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <sstream>
#include <stdexcept>

#include "args.hpp"
#include "interp/circular.hpp"
#include "registry.hpp"
#include "sw8085/interp/host.hpp"
#if __has_include("board_machine.hpp")
#include "board_machine.hpp"
#endif

namespace contour::cli {
namespace {

const char* kHelp =
    "usage: contour table1 [--format text|json] [--engine iss|cpu]\n"
    "Paper A's Table 1 reproduced: the 8085 program (sw8085/interp) per command\n"
    "pulse, measured over a standard set of lines and arcs: instructions executed,\n"
    "T-states (min/mean/max, interrupt acknowledge included), time at 3 MHz, and\n"
    "the highest command rate kept up with, found by driving command pulses at\n"
    "rising rates until the program counts the first overrun. The paper's row\n"
    "is printed beside ours. --engine cpu measures on the Verilog board, Verilated (slow).\n";

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
  std::string worst;   // the move and pulse of t_max
};

// An arc over about n pulses of the circle through (xs, ys), ending at an
// accepted end point (the model's position there).
Move walk_arc(std::int64_t xs, std::int64_t ys, Sense s, int n) {
  Circular<24> walk(xs, ys, xs, ys, s);
  for (int i = 0; i < n; ++i) walk.step();
  auto near = [](const State& st) { return std::llabs(st.d) <= std::llabs(st.x) + std::llabs(st.y); };
  while (!near(walk.state())) walk.step();
  return Move::arc(xs, ys, walk.state().x, walk.state().y, s);
}

std::vector<Move> standard_lines() {
  return {Move::line(3000, 1234), Move::line(-2600, -2599), Move::line(1, 2000),   Move::line(-4000, 0),
          Move::line(0, -300),    Move::line(257, -65),     Move::line(12345, -6789), Move::line(65537, -3),
          Move::line(-7, 9)};
}

std::vector<Move> standard_arcs() {
  const std::int64_t big = (std::int64_t{1} << 24) - 1;
  return {Move::arc(100, 0, 100, 0, Sense::CCW),
          Move::arc(0, -100, 0, -100, Sense::CW),
          Move::arc(1000, 0, 0, 1000, Sense::CCW),
          Move::arc(-707, 707, 707, -707, Sense::CW),
          Move::arc(3, 4, -4, -3, Sense::CCW),
          walk_arc(big, 0, Sense::CCW, 3000),
          walk_arc(5, -16777200, Sense::CW, 3000),
          walk_arc(11863282, -11863282, Sense::CCW, 2000)};
}

Row measure(const std::vector<Move>& moves, const i8085::MachineFactory& factory) {
  Row row;
  std::vector<sw8085::CommandResult> all;
  {
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
  }
  if (all.empty()) throw std::logic_error("table1: no command pulses measured");
  row.pulses = all.size();
  row.t_min = row.t_max = all.front().tstates;
  double ts = 0, is = 0;
  for (const auto& c : all) {
    row.t_min = std::min(row.t_min, c.tstates);
    row.t_max = std::max(row.t_max, c.tstates);
    row.instructions_max = std::max(row.instructions_max, c.instructions);
    ts += c.tstates;
    is += c.instructions;
  }
  row.t_mean = ts / double(all.size());
  row.instructions_mean = is / double(all.size());

  // The highest rate: bisect the command period. `ok(P)`: no overrun.
  auto ok = [&](int period) {
    sw8085::Host host(sw8085::Program::builtin(), factory);
    const auto t = host.drive(moves, double(period));
    if (!t.all_done) return false;
    return t.overruns == 0;
  };
  int lo = 20, hi = std::max(4 * row.t_max, 400);
  if (!ok(hi)) throw std::logic_error("table1: overruns even at one command every " + std::to_string(hi) + " T-states");
  while (hi - lo > 1) {
    const int mid = (lo + hi) / 2;
    (ok(mid) ? hi : lo) = mid;
  }
  row.period_min = hi;
  return row;
}

std::string fmt(double v, int decimals) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}

std::string json_row(const Row& r, const PaperRow& p) {
  std::ostringstream o;
  o << "{\"instructions\": " << r.instructions_max << ", \"instructions_mean\": " << fmt(r.instructions_mean, 2)
    << ", \"tstates_min\": " << r.t_min << ", \"tstates_mean\": " << fmt(r.t_mean, 2)
    << ", \"tstates_max\": " << r.t_max << ", \"time_us_3mhz\": " << fmt(r.t_max / kClockHz * 1e6, 2)
    << ", \"kpps_3mhz\": " << fmt(kClockHz / r.period_min / 1000.0, 2)
    << ", \"period_min_tstates\": " << r.period_min << ", \"kpps_from_tstates_max\": "
    << fmt(kClockHz / r.t_max / 1000.0, 2) << ", \"pulses\": " << r.pulses << ", \"worst\": \"" << r.worst
    << "\", \"paper\": {\"instructions\": " << p.instructions << ", \"tstates\": " << p.tstates
    << ", \"time_us\": " << p.time_us << ", \"kpps\": " << fmt(p.kpps, 1) << "}}";
  return o.str();
}

void text_rows(const char* name, const Row& r, const PaperRow& p) {
  std::printf("%-9s paper %6d %27d %13d %12s\n", name, p.instructions, p.tstates, p.time_us, fmt(p.kpps, 1).c_str());
  std::printf("%-9s ours  %6d %8d %8s %8d %13s %12s\n", "", r.instructions_max, r.t_min, fmt(r.t_mean, 1).c_str(),
              r.t_max, fmt(r.t_max / kClockHz * 1e6, 1).c_str(), fmt(kClockHz / r.period_min / 1000.0, 1).c_str());
}

int cmd_table1(const std::vector<std::string>& argv) {
  Args a(argv, {}, {"format", "engine"});
  if (a.help()) {
    std::fputs(kHelp, stdout);
    return 0;
  }
  a.expect_positional({});
  const std::string format = a.option_or("format", "text");
  if (format != "text" && format != "json") throw UsageError("--format: unknown format '" + format + "' (text or json)");
  const std::string engine = a.option_or("engine", "iss");
  i8085::MachineFactory factory;
  if (engine == "iss") factory = i8085::make_iss;
#if __has_include("board_machine.hpp")
  if (engine == "cpu") factory = board8085::make_board_machine;
#endif
  if (!factory) throw UsageError(unknown_engine(engine, "iss|cpu"));
  const Row lin = measure(standard_lines(), factory);
  const Row circ = measure(standard_arcs(), factory);
  if (format == "json") {
    std::printf("{\"linear\": %s, \"circular\": %s, \"engine\": \"%s\", \"clock_hz\": %.0f}\n",
                json_row(lin, kPaperLinear).c_str(), json_row(circ, kPaperCircular).c_str(), engine.c_str(), kClockHz);
    return 0;
  }
  std::printf("Paper A, Table 1: the 8085 routine per command pulse, 8085 at 3 MHz.\n");
  std::printf("ours: sw8085/interp on engine %s, measured over %llu + %llu command pulses\n", engine.c_str(),
              static_cast<unsigned long long>(lin.pulses), static_cast<unsigned long long>(circ.pulses));
  std::printf("(T-states: acknowledge to RET; kpps: highest command rate with no overrun counted).\n\n");
  std::printf("%-9s %-5s %6s %8s %8s %8s %13s %12s\n", "routine", "", "instr", "T min", "T mean", "T max", "us (T max)",
              "kpps");
  text_rows("linear", lin, kPaperLinear);
  text_rows("circular", circ, kPaperCircular);
  std::printf("\nworst pulse: linear %s; circular %s\n", lin.worst.c_str(), circ.worst.c_str());
  return 0;
}

const CommandRegistrar kTable1{{"table1", "paper A's Table 1, measured on the 8085 program (ISS)", cmd_table1}};

}  // namespace
}  // namespace contour::cli
