// `contour stream FILE --port DEVICE`: reads and plans a G-code program
// (model/gcode, model/planner: paper B) and streams its 1 ms chords over
// the serial link to the board's 3-axis peripheral (docs/board.md).
#if __has_include("stream_chords.hpp")
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "args.hpp"
#include "gcode/gcode.hpp"
#include "planner/planner.hpp"
#include "planner/two_stage.hpp"
#include "registry.hpp"
#include "serial_port.hpp"
#include "stream_blocks.hpp"
#include "stream_chords.hpp"

namespace contour::cli {
namespace {

const char* kHelp =
    "usage: contour stream FILE.ngc --port DEVICE [options]\n"
    "Reads a G-code program (G0-G3, G17-G19, G20/G21, G90/G91; 3D arcs as paper B), plans it\n"
    "with paper B's acc/dec planner and streams its chords, one per 1 ms control cycle, to\n"
    "the board's 3-axis chord peripheral over the serial link (rtl/board, docs/board.md),\n"
    "keeping the board's chord queue filled. Each chord is rounded to steps on the board's\n"
    "grid, so the board's STEP/DIR pins give the pulses of `contour gcode FILE --pulses`.\n"
    "\n"
    "  DEVICE  the iCEBreaker's second FTDI channel (e.g. /dev/ttyUSB1), or the pseudo-\n"
    "          terminal printed by `contour board-sim` (the simulated board)\n"
    "\noptions:\n"
    "  --baud N          line rate (default 1000000, the bitstream's)\n"
    "  --steps-per-mm N  steps per mm on every axis (default 1000)\n"
    "  --accel A         acceleration limit of every axis, mm/min^2 (default 3528000 = 0.1 g)\n"
    "  --cycle MS        control cycle, ms (default 1)\n"
    "  --step-len US     STEP high time, us (default 1; at most 4095 board clocks)\n"
    "  --step-space US   least STEP low time, us (default 1; at most 4095 board clocks)\n"
    "  --watchdog MS     board's hold after this long without a frame (default 50)\n"
    "  --timeout S       give up when the board has not answered for S seconds (default 3)\n"
    "  --quiet           no progress line\n"
    "  --progress        the progress line even when stderr is not a terminal (a line each)\n"
    "  --hw-arcs         paper A mode: the lines and arcs of the XY plane (G17) go to interp_top\n"
    "                    as hardware blocks (exact paper A arcs, at most 65535 steps from a\n"
    "                    start or centre), its feed written every cycle from the planner's\n"
    "                    profile; a Z move or an arc out of the XY plane is refused (exit 2)\n"
    "  --blocks FILE     with --hw-arcs: write the blocks sent, one a line, as `contour line`\n"
    "                    or `contour arc` takes them, with the G-code line\n"
    "While it runs: a progress line on a terminal (chords sent, the position every reply of\n"
    "the board carries, queue level).\n"
    "Ctrl-C: feed hold (the board slows to rest along the path in 49 ms), then stop (queue\n"
    "dropped); every pulse given is whole; the position at rest is printed.\n"
    "A frame the board refuses (CRC, length, sequence) or loses is sent again; a tripped\n"
    "watchdog is reported and resumed.\n"
    "Exit status: 0 done, the position read back equals the program's; 1 it does not;\n"
    "2 bad input, the board does not answer (after --timeout) or answers with an error (one\n"
    "line on stderr naming the port); 130 stopped by Ctrl-C (at rest, position printed).\n";

std::atomic<bool> g_stop{false};
extern "C" void on_sigint(int) { g_stop = true; }

double positive(const Args& a, const char* name, const char* fallback) {
  const std::string v = a.option_or(name, fallback);
  const double x = parse_real(v, std::string("--") + name);
  if (!(x > 0)) throw UsageError(std::string("--") + name + ": must be > 0 (got '" + v + "')");
  return x;
}

planner::Plan read_plan(const std::string& file, const planner::Config& cfg) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw UsageError("cannot read '" + file + "'");
  std::stringstream buf;
  buf << in.rdbuf();
  std::vector<gcode::Block> blocks;
  try {
    blocks = gcode::parse(buf.str());
  } catch (const gcode::Error& e) {
    throw UsageError(file + ": " + e.what());
  }
  planner::Plan plan;
  try {
    plan = planner::plan(blocks, cfg);
  } catch (const std::invalid_argument& e) {
    throw UsageError(file + ": " + e.what());
  }
  if (plan.total_time / cfg.cycle_s > 2e7) throw UsageError(file + ": more than 2e7 cycles, more than this tool plans");
  return plan;
}

std::vector<board::Chord3> plan_chords(const std::string& file, const planner::Config& cfg, double spm) {
  const planner::Plan plan = read_plan(file, cfg);
  std::vector<board::Chord3> out;
  for (const auto& c : planner::chords_in_steps(planner::interpolate(plan), spm)) out.push_back({c.dx, c.dy, c.dz});
  return out;
}

// At most every 0.1 s, and at the end.
void show_progress(const board::Progress& p, double spm, bool tty, const char* unit) {
  static std::size_t last = static_cast<std::size_t>(-1);
  static auto shown = std::chrono::steady_clock::time_point{};
  const auto now = std::chrono::steady_clock::now();
  if (p.sent == last || p.total == 0) return;
  if (p.sent != p.total && now - shown < std::chrono::milliseconds(100)) return;
  last = p.sent;
  shown = now;
  const int w = 30, done = static_cast<int>(w * p.sent / p.total);
  std::fprintf(stderr, "\r[%.*s%.*s] %3zu%% %zu/%zu %s  X %9.3f Y %9.3f Z %9.3f mm  queue %3u", done,
               "##############################", w - done, "                              ",
               100 * p.sent / p.total, p.sent, p.total, unit, p.pos[0] / spm, p.pos[1] / spm, p.pos[2] / spm, p.level);
  if (!tty) std::fputs("\n", stderr);
}

// The end of a run in either mode, after its first line: the link's figures,
// the position read back against the program's; the exit status.
int report(const board::StreamResult& r, std::size_t n) {
  std::printf("stream: link %llu frames, %llu resends, %llu refused, %llu bad replies\n",
              static_cast<unsigned long long>(r.link.frames), static_cast<unsigned long long>(r.link.resends),
              static_cast<unsigned long long>(r.link.refused), static_cast<unsigned long long>(r.link.bad_replies));
  std::printf("stream: position %lld %lld %lld steps (program: %lld %lld %lld)\n", static_cast<long long>(r.end[0]),
              static_cast<long long>(r.end[1]), static_cast<long long>(r.end[2]),
              static_cast<long long>(r.expected[0]), static_cast<long long>(r.expected[1]),
              static_cast<long long>(r.expected[2]));
  if (r.stopped) return 130;
  return (r.end == r.expected && r.chords == n) ? 0 : 1;
}

// What both modes share: the port, the link, Ctrl-C and the progress line
// (counting `unit`); `stream(link, port, progress)` runs the mode.
template <class Stream>
board::StreamResult on_board(const Args& a, const std::string& port, unsigned baud, double spm,
                             const board::LinkTimes& lt, const char* unit, Stream stream) {
  try {
    board::SerialPort sp(port, baud, lt.dead_s);
    board::LinkClient link(sp, lt);
    std::signal(SIGINT, on_sigint);
    const bool tty = isatty(STDERR_FILENO), bar = a.flag("progress") || (!a.flag("quiet") && tty);
    auto progress = [&](const board::Progress& p) {
      if (bar) show_progress(p, spm, tty, unit);
    };
    const board::StreamResult r = stream(link, sp, progress);
    if (bar && tty) std::fputs("\n", stderr);
    return r;
  } catch (const board::LinkError& e) {
    throw UsageError(port + ": " + e.what());
  } catch (const std::invalid_argument& e) {
    throw UsageError(a.positional()[0] + ": " + e.what());
  }
}

// --hw-arcs: paper A's blocks (tb/board/stream_blocks.hpp).
int run_hw_arcs(const Args& a, const std::string& port, unsigned baud, const planner::Config& pc, double spm,
                const board::StreamConfig& sc, const board::LinkTimes& lt) {
  const std::string file = a.positional()[0];
  board::BlockProgram prog;
  try {
    prog = board::to_blocks(read_plan(file, pc), spm);
  } catch (const std::invalid_argument& e) {
    throw UsageError(file + ": " + e.what());
  }
  if (auto path = a.option("blocks")) {
    std::ofstream out(*path);
    for (const auto& b : prog.blocks) out << b.args() << " # line " << b.line << "\n";
    if (!out) throw UsageError("--blocks: cannot write '" + *path + "'");
  }
  const auto r = on_board(a, port, baud, spm, lt, "blocks", [&](auto& link, auto& sp, const auto& progress) {
    return board::stream_blocks(link, sp, prog, sc, progress, &g_stop);
  });
  std::printf("stream: %u of %zu blocks run (paper A, --hw-arcs), watchdog trips %u%s\n", r.chords,
              prog.blocks.size(), r.wdog_trips, r.stopped ? ", STOPPED by Ctrl-C" : "");
  return report(r, prog.blocks.size());
}

int run_stream(const std::vector<std::string>& argv) {
  const Args a(argv, {"quiet", "progress", "hw-arcs"},
               {"port", "baud", "steps-per-mm", "accel", "cycle", "step-len", "step-space", "watchdog", "timeout",
                "blocks"});
  if (a.help()) {
    std::fputs(kHelp, stdout);
    return 0;
  }
  a.expect_positional({"FILE"});
  if (a.option("blocks") && !a.flag("hw-arcs")) throw UsageError("--blocks needs --hw-arcs");
  const auto port = a.option("port");
  if (!port) throw UsageError("--port DEVICE is required (e.g. /dev/ttyUSB1, or the path board-sim prints)");
  const auto baud = static_cast<unsigned>(parse_int(a.option_or("baud", "1000000"), "--baud"));
  if (!board::baud_supported(baud)) throw UsageError("--baud: " + std::to_string(baud) + " is not a rate the port takes");
  planner::Config pc;
  if (a.option("accel")) {
    const double acc = positive(a, "accel", "1") / 3600;
    pc.machine.amax = {acc, acc, acc};
  }
  pc.cycle_s = positive(a, "cycle", "1") / 1000;
  const double spm = positive(a, "steps-per-mm", "1000");
  board::StreamConfig sc;
  sc.cycle_s = pc.cycle_s;
  sc.step_len = static_cast<std::uint32_t>(positive(a, "step-len", "1") * sc.clock_hz / 1e6 + 0.5);
  sc.step_space = static_cast<std::uint32_t>(positive(a, "step-space", "1") * sc.clock_hz / 1e6 + 0.5);
  // interp_top's timing registers are 12 bits (docs/regmap.md).
  for (const auto& [name, clocks] : {std::pair<const char*, std::uint32_t>{"step-len", sc.step_len},
                                     std::pair<const char*, std::uint32_t>{"step-space", sc.step_space}})
    if (clocks > 4095)
      throw UsageError(std::string("--") + name + ": " + std::to_string(clocks) +
                       " clocks is more than the 4095 the board's timing registers hold");
  sc.wdog_clocks = static_cast<std::uint32_t>(positive(a, "watchdog", "50") * sc.clock_hz / 1e3);
  board::LinkTimes lt;
  lt.dead_s = positive(a, "timeout", "3");
  if (a.flag("hw-arcs")) return run_hw_arcs(a, *port, baud, pc, spm, sc, lt);
  const auto chords = plan_chords(a.positional()[0], pc, spm);
  const auto r = on_board(a, *port, baud, spm, lt, "chords", [&](auto& link, auto& sp, const auto& progress) {
    return board::stream_chords(link, sp, chords, sc, progress, &g_stop);
  });
  std::printf("stream: %u of %zu chords run, underruns %u, watchdog trips %u%s\n", r.chords, chords.size(),
              r.underruns, r.wdog_trips, r.stopped ? ", STOPPED by Ctrl-C" : "");
  return report(r, chords.size());
}

const CommandRegistrar kRegistrar{
    Command{"stream", "stream a G-code program's chords to the board over its serial link", run_stream}};

}  // namespace
}  // namespace contour::cli
#endif
