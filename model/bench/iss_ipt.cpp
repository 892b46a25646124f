// iss_ipt: x86 instructions per emulated T-state of the ISS (model/i8085),
// counted by callgrind on model/i8085/programs/opmix.a80 run the way
// `contour sim85 --cpm` runs it (run_cpm on the Machine make_iss builds).
//
//   iss_ipt                runs itself under callgrind at two pass counts in
//                          each mode and prints (instructions(N2) -
//                          instructions(N1)) / (T-states(N2) - T-states(N1)),
//                          which cancels start-up, loading and printing
//   iss_ipt MODE N         one run of N passes (MODE 8080|8085), as
//                          measured; prints the program's line and T-states
//
// Instruction counts do not depend on the machine's load: the figure is
// repeatable, which a time is not.
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "i8085/machine.hpp"
#include "i8085/system.hpp"

#ifndef OPMIX_HEX
#error "OPMIX_HEX: the assembled model/i8085/programs/opmix.hex"
#endif

namespace {

constexpr std::uint16_t kPassesAddr = 0x0103;  // `iters` in opmix.a80

struct Run {
  std::string console;
  std::uint64_t tstates = 0;
};

Run run_opmix(i8085::Mode mode, std::uint16_t passes) {
  std::ifstream f(OPMIX_HEX, std::ios::binary);
  const std::vector<std::uint8_t> file{std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
  i8085::RamBus bus;
  i8085::load_program(bus, file, OPMIX_HEX, 0x0100);
  bus.mem[kPassesAddr] = static_cast<std::uint8_t>(passes & 0xFF);
  bus.mem[kPassesAddr + 1] = static_cast<std::uint8_t>(passes >> 8);
  const auto m = i8085::make_iss(bus, mode);
  std::ostringstream console;
  const i8085::RunResult r = i8085::run_cpm(*m, bus, console, {});
  return {console.str(), r.tstates};
}

struct Count {
  long long instructions = -1;
  unsigned long long tstates = 0;
};

// Instructions callgrind counted for `self MODE N`, and the run's T-states.
Count count(const char* self, const std::string& mode, int n) {
  const std::string cmd = "valgrind --tool=callgrind --callgrind-out-file=/dev/null " + std::string(self) + " " +
                          mode + " " + std::to_string(n) + " 2>&1 | grep -E 'Collected :|^T-states'";
  std::unique_ptr<FILE, int (*)(FILE*)> p(popen(cmd.c_str(), "r"), pclose);
  Count c;
  char line[256];
  while (p && std::fgets(line, sizeof line, p.get())) {
    if (std::sscanf(line, "T-states %llu", &c.tstates) == 1) continue;
    long long v = 0;
    if (std::sscanf(line, "%*[^:]: %lld", &v) == 1) c.instructions = v;
  }
  return c;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 3) {
    const std::string mode = argv[1];
    const int n = std::atoi(argv[2]);
    if ((mode != "8080" && mode != "8085") || n <= 0 || n > 0xFFFF) return 2;
    const Run r = run_opmix(mode == "8080" ? i8085::Mode::i8080 : i8085::Mode::i8085, static_cast<std::uint16_t>(n));
    std::printf("%sT-states %llu\n", r.console.c_str(), static_cast<unsigned long long>(r.tstates));
    return 0;
  }
  std::printf("%-5s %14s %14s %12s\n", "mode", "T-states", "instructions", "per T-state");
  for (const std::string mode : {"8085", "8080"}) {
    const int n1 = 500, n2 = 2500;
    const Count c1 = count(argv[0], mode, n1), c2 = count(argv[0], mode, n2);
    if (c1.instructions < 0 || c2.instructions < 0 || c2.tstates <= c1.tstates) {
      std::fprintf(stderr, "iss_ipt: valgrind --tool=callgrind failed (is valgrind installed?)\n");
      return 1;
    }
    const unsigned long long dt = c2.tstates - c1.tstates;
    std::printf("%-5s %14llu %14lld %12.2f\n", mode.c_str(), dt, c2.instructions - c1.instructions,
                double(c2.instructions - c1.instructions) / double(dt));
  }
  return 0;
}
