// cpu8085_tps: simulated T-states per second of CPU time of the 8085
// machines (`make bench`; docs/cpu8085.md "Speed"):
//   cpu    the Verilated CPU with a C++ bus (`contour sim85 --engine cpu`)
//          on model/i8085/programs/opmix.a80, CP/M-style
//   board  the Verilated board (the engine "cpu" of line/arc/table1):
//          sw8085/interp driven by its host, command pulses at a fixed
//          period, over table1's standard lines
//   iss    the same two runs on the ISS, for scale
// CPU time (std::clock), so the figure varies with the machine's load less
// than a wall-clock time would; still a time: run it on a quiet machine.
//
//   cpu8085_tps            all four runs
//   cpu8085_tps cpu N      the Verilated CPU alone, opmix N passes: for
//                          `valgrind --tool=callgrind` (x86 instructions per
//                          T-state = Ir / the T-states printed)
//   cpu8085_tps board N    the Verilated board, the first N (1..5) lines
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include "board_machine.hpp"
#include "cpu_machine.hpp"
#include "i8085/machine.hpp"
#include "i8085/system.hpp"
#include "sw8085/interp/host.hpp"

#ifndef OPMIX_HEX
#error "OPMIX_HEX: the assembled model/i8085/programs/opmix.hex"
#endif

namespace {

struct Figure {
  std::uint64_t tstates = 0;
  double seconds = 0;
};

double cpu_seconds() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

Figure opmix(const i8085::MachineFactory& factory, std::uint16_t passes) {
  std::ifstream f(OPMIX_HEX, std::ios::binary);
  const std::vector<std::uint8_t> file{std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
  i8085::RamBus bus;
  i8085::load_program(bus, file, OPMIX_HEX, 0x0100);
  bus.mem[0x0103] = static_cast<std::uint8_t>(passes & 0xFF);  // `iters`
  bus.mem[0x0104] = static_cast<std::uint8_t>(passes >> 8);
  const auto m = factory(bus, i8085::Mode::i8085);
  std::ostringstream console;
  const double t0 = cpu_seconds();
  const i8085::RunResult r = i8085::run_cpm(*m, bus, console, {});
  return {r.tstates, cpu_seconds() - t0};
}

// The program on its board: table1's lines (sim/cli/cmd_table1.cpp), one
// command every 600 T-states.
Figure interp(const i8085::MachineFactory& factory, std::size_t lines = 5) {
  using contour::Move;
  std::vector<Move> moves = {Move::line(3000, 1234), Move::line(-2600, -2599), Move::line(1, 2000),
                             Move::line(-4000, 0), Move::line(12345, -6789)};
  moves.resize(lines);
  contour::sw8085::Host host(contour::sw8085::Program::builtin(), factory);
  const std::uint64_t t_start = host.machine().tstates();
  const double t0 = cpu_seconds();
  host.drive(moves, 600.0);
  return {host.machine().tstates() - t_start, cpu_seconds() - t0};
}

void print(const char* what, const char* engine, const Figure& f) {
  std::printf("%-34s %-6s %12llu %9.2f %10.1f\n", what, engine, static_cast<unsigned long long>(f.tstates), f.seconds,
              double(f.tstates) / f.seconds / 1e6);
}

}  // namespace

int main(int argc, char** argv) {
  const i8085::MachineFactory cpu = [](i8085::Bus& b, i8085::Mode m) { return cpu8085::make_cpu_machine(b, m); };
  std::printf("%-34s %-6s %12s %9s %10s\n", "run", "engine", "T-states", "CPU s", "M T/s");
  if (argc == 3 && std::string(argv[1]) == "cpu") {
    const int passes = std::atoi(argv[2]);
    if (passes < 1 || passes > 65535) {
      std::fprintf(stderr, "cpu8085_tps: passes '%s' is not 1..65535\n", argv[2]);
      return 2;
    }
    print("opmix (CP/M)", "cpu", opmix(cpu, static_cast<std::uint16_t>(passes)));
    return 0;
  }
  if (argc == 3 && std::string(argv[1]) == "board") {
    const int lines = std::atoi(argv[2]);
    if (lines < 1 || lines > 5) {
      std::fprintf(stderr, "cpu8085_tps: lines '%s' is not 1..5\n", argv[2]);
      return 2;
    }
    print("sw8085/interp, P = 600 T", "board", interp(board8085::make_board_machine, static_cast<std::size_t>(lines)));
    return 0;
  }
  if (argc != 1) {
    std::fprintf(stderr, "usage: cpu8085_tps [cpu PASSES | board LINES]\n");
    return 2;
  }
  print("opmix, 2000 passes (CP/M)", "cpu", opmix(cpu, 2000));
  print("opmix, 2000 passes (CP/M)", "iss", opmix(i8085::make_iss, 2000));
  print("sw8085/interp, 5 lines, P = 600 T", "board", interp(board8085::make_board_machine));
  print("sw8085/interp, 5 lines, P = 600 T", "iss", interp(i8085::make_iss));
  return 0;
}
