// Lockstep regression: the Verilated cpu8085 against the ISS (lockstep.hpp).
//
// CONTOUR_FULL=1 runs the random streams ten times as long (default: about
// a minute in all on one core); CONTOUR_FST=FILE writes the waveform of the
// last run (use with --gtest_filter).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include "i8085/hex.hpp"
#include "lockstep.hpp"
#include "sw8085_paths.hpp"

namespace cpu8085::tb {
namespace {

// CONTOUR_FULL=1 (set, not empty, not 0): the long runs.
bool full_run() {
  const char* e = std::getenv("CONTOUR_FULL");
  return e != nullptr && *e != '\0' && *e != '0';
}

// The random runs: ten times as long with CONTOUR_FULL=1.
std::uint64_t scale() { return full_run() ? 10 : 1; }

// The harness itself: a byte that differs on the RTL side must stop the run
// at the step that reads it, naming what differs, with both trace lines.
TEST(Lockstep, ReportsTheFirstDivergenceWithBothTraceLines) {
  std::array<std::uint8_t, 65536> mem{};
  const std::uint8_t prog[] = {0x3E, 0x01,         // MVI A,01
                               0x3A, 0x00, 0x10,   // LDA 1000
                               0x00};              // NOP
  std::copy(std::begin(prog), std::end(prog), mem.begin());
  mem[0x1000] = 0x05;
  Lockstep ls(mem);
  ls.poke_rtl_side(0x1000, 0x06);
  ASSERT_TRUE(ls.step());
  ASSERT_FALSE(ls.step());
  const std::string& r = ls.report();
  EXPECT_NE(r.find("divergence at step 2: A differs"), std::string::npos) << r;
  EXPECT_NE(r.find("ISS: T=         7 PC=0002 OP=3A LDA 1000"), std::string::npos) << r;
  EXPECT_NE(r.find("A=05"), std::string::npos) << r;
  EXPECT_NE(r.find("RTL: T=         7 PC=0002 OP=3A LDA 1000"), std::string::npos) << r;
  EXPECT_NE(r.find("A=06"), std::string::npos) << r;
  EXPECT_NE(r.find("MVI A,01"), std::string::npos) << "context line missing:\n" << r;
}

// Every opcode (HLT included) from many random register and memory states:
// one step each, compared. Flags are random over the bits the 8085 keeps.
TEST(Lockstep, EveryOpcodeFromRandomStates) {
  std::mt19937_64 rng(85);
  for (int op = 0; op < 256; ++op) {
    for (int rep = 0; rep < 16; ++rep) {
      std::array<std::uint8_t, 65536> mem{};
      for (auto& b : mem) b = static_cast<std::uint8_t>(rng());
      i8085::Regs r{};
      r.a = static_cast<std::uint8_t>(rng());
      r.f = static_cast<std::uint8_t>(rng() & 0xD5);
      r.b = static_cast<std::uint8_t>(rng());
      r.c = static_cast<std::uint8_t>(rng());
      r.d = static_cast<std::uint8_t>(rng());
      r.e = static_cast<std::uint8_t>(rng());
      r.h = static_cast<std::uint8_t>(rng());
      r.l = static_cast<std::uint8_t>(rng());
      r.sp = static_cast<std::uint16_t>(rng());
      r.pc = static_cast<std::uint16_t>(rng());
      mem[r.pc] = static_cast<std::uint8_t>(op);
      Lockstep ls(mem);
      ls.set_regs(r);
      ASSERT_TRUE(ls.step()) << "opcode " << op << " rep " << rep << "\n" << ls.report();
      // A second step: the following instruction from the state the first left.
      ASSERT_TRUE(ls.step()) << "after opcode " << op << " rep " << rep << "\n" << ls.report();
    }
  }
}

// A random 64 KiB memory run as code (most HLT bytes replaced; the HLTs that
// remain are woken by the interrupts, TRAP at the latest), with every interrupt
// input driven at random T-states: TRAP and RST 7.5 pulses, RST 6.5 / 5.5 and
// INTR levels; INTR supplies RST n or CALL nnnn.
// What the random runs went through, so that the test can insist that every
// kind of step was in fact compared.
struct Coverage {
  std::array<std::uint64_t, 6> irq{};  // by i8085::Interrupt
  std::uint64_t idle = 0, hlt = 0, intr_call = 0;
  std::array<std::uint64_t, 256> op{};
};

void random_run(std::uint64_t seed, std::uint64_t steps, Coverage& cov) {
  std::mt19937_64 rng(seed);
  std::array<std::uint8_t, 65536> mem{};
  for (auto& b : mem) {
    b = static_cast<std::uint8_t>(rng());
    if (b == 0x76 && rng() % 8 != 0) b = 0x00;  // a few HLTs stay
  }
  Lockstep ls(mem);  // CONTOUR_FST=FILE: the waveform of the last run
  ls.set_in_value([](std::uint8_t port, std::uint64_t n) {
    return static_cast<std::uint8_t>(port * 37u + n * 101u + (n >> 8));
  });
  Pins pins;
  std::uint64_t next_change = 200;
  std::uint64_t wake_at = 0;
  for (std::uint64_t i = 0; i < steps; ++i) {
    if (ls.tstates() >= next_change) {
      next_change = ls.tstates() + 20 + rng() % 1500;
      switch (rng() % 8) {
        case 0: pins.trap = !pins.trap; break;
        case 1: case 2: pins.rst75 = !pins.rst75; break;
        case 3: pins.rst65 = !pins.rst65; break;
        case 4: pins.rst55 = !pins.rst55; break;
        case 5: {
          pins.intr = !pins.intr;
          if (pins.intr) {
            if (rng() % 2) {
              ls.queue_inta({static_cast<std::uint8_t>(0xC7 | (rng() % 8) << 3)});
            } else {
              ls.queue_inta({0xCD, static_cast<std::uint8_t>(rng()), static_cast<std::uint8_t>(rng())});
            }
          }
          break;
        }
        default: break;
      }
      ls.set_pins(pins);
    }
    // A halted CPU may have interrupts off: a TRAP edge wakes it within 300 T.
    if (ls.halted() && ls.last().kind != i8085::StepKind::idle) {
      wake_at = ls.tstates() + rng() % 300;
      pins.trap = false;
      ls.set_pins(pins);
    } else if (ls.halted() && ls.tstates() >= wake_at) {
      pins.trap = true;
      ls.set_pins(pins);
    }
    ASSERT_TRUE(ls.step()) << "seed " << seed << "\n" << ls.report();
    const i8085::Step& s = ls.last();
    switch (s.kind) {
      case i8085::StepKind::instruction:
        ++cov.op[s.bytes[0]];
        break;
      case i8085::StepKind::interrupt:
        ++cov.irq[static_cast<std::size_t>(s.irq)];
        if (s.irq == i8085::Interrupt::intr && s.bytes[0] == 0xCD) ++cov.intr_call;
        break;
      case i8085::StepKind::idle:
        ++cov.idle;
        break;
    }
  }
}

TEST(Lockstep, RandomStreamsWithInterrupts) {
  const std::uint64_t n = 4 * scale();
  Coverage cov;
  for (std::uint64_t seed = 1; seed <= n; ++seed) random_run(seed, 250000, cov);
  for (int op = 0; op < 256; ++op) {
    if (op == 0x76) continue;  // HLT: only where the program wrote it
    EXPECT_GT(cov.op[static_cast<std::size_t>(op)], 0u) << "opcode " << op << " never ran";
  }
  const char* names[] = {"none", "TRAP", "RST 7.5", "RST 6.5", "RST 5.5", "INTR"};
  for (std::size_t i = 1; i < cov.irq.size(); ++i)
    EXPECT_GT(cov.irq[i], 0u) << names[i] << " was never acknowledged";
  EXPECT_GT(cov.intr_call, 0u) << "INTR with CALL never happened";
  std::printf("  acknowledged: TRAP %llu, RST 7.5 %llu, RST 6.5 %llu, RST 5.5 %llu, INTR %llu (CALL %llu);"
              " HLT %llu, idle T-states %llu\n",
              static_cast<unsigned long long>(cov.irq[1]), static_cast<unsigned long long>(cov.irq[2]),
              static_cast<unsigned long long>(cov.irq[3]), static_cast<unsigned long long>(cov.irq[4]),
              static_cast<unsigned long long>(cov.irq[5]), static_cast<unsigned long long>(cov.intr_call),
              static_cast<unsigned long long>(cov.op[0x76]), static_cast<unsigned long long>(cov.idle));
}

// Every assembled sw8085 program (the .hex files under the build tree's
// sw8085/), run in lockstep from reset: bare programs until HLT, CP/M-style
// ones (loaded at 0x0100) with the CP/M set-up of `contour sim85 --cpm` until
// their final OUT 0. Programs that wait for interrupts are run to a T-state
// cap, still in lockstep.
TEST(Lockstep, Sw8085Programs) {
  namespace fs = std::filesystem;
  std::vector<fs::path> hexes;
  for (const auto& e : fs::recursive_directory_iterator(contour::sw8085::kHexDir))
    if (e.is_regular_file() && e.path().extension() == ".hex") hexes.push_back(e.path());
  std::sort(hexes.begin(), hexes.end());
  ASSERT_FALSE(hexes.empty()) << "no assembled programs under " << contour::sw8085::kHexDir;
  constexpr std::uint64_t kCap = 2'000'000;
  for (const fs::path& p : hexes) {
    SCOPED_TRACE(p.string());
    const i8085::HexImage img = i8085::read_hex_file(p.string());
    std::array<std::uint8_t, 65536> mem{};
    img.load_into(mem);
    const bool cpm = img.lowest() >= 0x0100;
    if (cpm) {
      mem[0x0000] = 0xD3;  // OUT 0: end
      mem[0x0001] = 0x00;
      mem[0x0005] = 0xD3;  // OUT 1; RET: BDOS
      mem[0x0006] = 0x01;
      mem[0x0007] = 0xC9;
    }
    Lockstep ls(mem);
    if (cpm) {
      i8085::Regs r{};
      r.pc = 0x0100;
      r.sp = 0xFFFE;
      ls.set_regs(r);
    }
    bool ended = false;
    int pulses = 0;  // RST 7.5 pulses given to a program halted with IE on
    Pins pins;
    while (ls.tstates() < kCap) {
      ASSERT_TRUE(ls.step()) << ls.report();
      const i8085::Step& s = ls.last();
      if (pins.rst75) {
        pins.rst75 = false;
        ls.set_pins(pins);
      }
      if (!cpm && ls.halted()) {
        if (ls.ie() && pulses < 5) {
          ++pulses;
          pins.rst75 = true;
          ls.set_pins(pins);
          continue;
        }
        ended = true;
        break;
      }
      if (cpm && s.kind == i8085::StepKind::instruction && s.bytes[0] == 0xD3 && s.bytes[1] == 0x00) {
        ended = true;
        break;
      }
    }
    std::printf("  %-40s %s, %d RST 7.5 pulses, %llu steps, %llu T-states\n", p.filename().c_str(),
                ended ? "ended" : "capped", pulses, static_cast<unsigned long long>(ls.steps()),
                static_cast<unsigned long long>(ls.tstates()));
  }
}

}  // namespace
}  // namespace cpu8085::tb
