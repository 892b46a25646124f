// `contour board-sim`: the Verilated board (rtl/board) on a pseudo-
// terminal, its UART at the bit level, as fast as it runs: `contour stream
// FILE --port PATH` drives it exactly as it drives /dev/ttyUSB1. Records
// the STEP/DIR pins and, on request, an FST waveform; injects faults on
// the wire on request (docs/board.md, "The simulated board").
#if __has_include("board_sim.hpp")
#include <chrono>
#include <cstdio>
#include <fstream>

#include "args.hpp"
#include "board_sim.hpp"
#include "registry.hpp"
#include "serial_port.hpp"

namespace contour::cli {
namespace {

const char* kHelp =
    "usage: contour board-sim [options]\n"
    "Runs the board design (rtl/board: UART at 1 Mbaud on a 12 MHz clock, the 3-axis chord\n"
    "peripheral, interp_top, the link) Verilated, its UART at the bit level, on a pseudo-\n"
    "terminal, and prints the terminal's path on the first line:\n"
    "  board-sim: port /dev/pts/N\n"
    "Drive it with `contour stream FILE --port /dev/pts/N`. The simulation runs as fast as it\n"
    "can (not in real time); its clock stands still until the host first writes. It ends\n"
    "when the host closes the port after using it, or at --max-time.\n"
    "\noptions:\n"
    "  --pulses FILE     record the STEP/DIR pins: one line per step, '<time s> <+X|-Y|...>'\n"
    "                    (time of the STEP rising edge from the board's reset)\n"
    "  --fst FILE        FST waveform of the whole board (large)\n"
    "  --max-time S      end after S simulated seconds\n"
    "  --port-file FILE  also write the terminal's path to FILE (for scripts)\n"
    "faults on the wire (both ways unless said):\n"
    "  --flip-every N    flip one bit of every Nth character\n"
    "  --drop-every N    drop every Nth character\n"
    "  --cut-at S        host-to-board line dead from S simulated seconds ...\n"
    "  --cut-for S       ... for S seconds (default 0.3: longer than the watchdog)\n"
    "Exit status: 0, or 2 for bad input (one line on stderr).\n";

board::Faults parse_faults(const Args& a) {
  board::Faults f;
  auto count = [&](const char* name) -> std::uint64_t {
    auto v = a.option(name);
    if (!v) return 0;
    const std::int64_t n = parse_int(*v, std::string("--") + name);
    if (n < 1) throw UsageError(std::string("--") + name + ": must be >= 1 (got '" + *v + "')");
    return static_cast<std::uint64_t>(n);
  };
  f.flip_every = count("flip-every");
  f.drop_every = count("drop-every");
  if (auto v = a.option("cut-at")) {
    f.cut_at_s = parse_real(*v, "--cut-at");
    if (f.cut_at_s < 0) throw UsageError("--cut-at: must be >= 0 (got '" + *v + "')");
    f.cut_for_s = parse_real(a.option_or("cut-for", "0.3"), "--cut-for");
  } else if (a.option("cut-for")) {
    throw UsageError("--cut-for needs --cut-at");
  }
  return f;
}

void write_pulses(const std::string& path, const std::vector<board::StepEvent>& steps) {
  std::FILE* f = std::fopen(path.c_str(), "w");
  if (!f) throw UsageError("--pulses: cannot write '" + path + "'");
  for (const auto& s : steps)
    std::fprintf(f, "%.9f %s\n", static_cast<double>(s.clock) / board::kClockHz, to_string(s.pulse).c_str());
  std::fclose(f);
}

// The loop: host bytes in, 100 us of board, board bytes out.
void serve(board::PtyMaster& pty, board::BoardSim& sim, double max_time) {
  bool used = false;
  for (;;) {
    bool hangup = false;
    const board::Bytes in = pty.read_some(hangup);
    if (!in.empty()) {
      used = true;
      sim.send(in);
    }
    if (hangup && used && sim.line_idle()) return;
    if (!used) {
      pty.wait_readable(0.01);
      continue;
    }
    sim.run(1200);
    const board::Bytes out = sim.take_received();
    if (!out.empty()) pty.write_all(out);
    if (max_time > 0 && sim.seconds() >= max_time) return;
  }
}

int run_board_sim(const std::vector<std::string>& argv) {
  const Args a(argv, {}, {"pulses", "fst", "max-time", "port-file", "flip-every", "drop-every", "cut-at", "cut-for"});
  if (a.help()) {
    std::fputs(kHelp, stdout);
    return 0;
  }
  a.expect_positional({});
  const board::Faults faults = parse_faults(a);
  const double max_time = a.option("max-time") ? parse_real(*a.option("max-time"), "--max-time") : 0;
  board::PtyMaster pty;
  board::BoardSim sim(a.option_or("fst", ""), faults);
  std::printf("board-sim: port %s\n", pty.slave_path().c_str());
  std::fflush(stdout);
  if (auto p = a.option("port-file")) {
    std::ofstream(*p) << pty.slave_path() << "\n";
  }
  const auto t0 = std::chrono::steady_clock::now();
  serve(pty, sim, max_time);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (auto p = a.option("pulses")) write_pulses(*p, sim.steps());
  std::printf("board-sim: %.4f s simulated (%llu clocks) in %.2f s: %.2f M clocks/s, %zu steps, %llu faults\n",
              sim.seconds(), static_cast<unsigned long long>(sim.clocks()), wall,
              static_cast<double>(sim.clocks()) / wall / 1e6, sim.steps().size(),
              static_cast<unsigned long long>(sim.faults_done()));
  return 0;
}

const CommandRegistrar kRegistrar{
    Command{"board-sim", "the Verilated board with its host link on a pseudo-terminal", run_board_sim}};

}  // namespace
}  // namespace contour::cli
#endif
