// The board's output ports at the pins, clock by clock (rtl/board8085,
// docs/board8085.md "I/O ports"): a straight-line program of OUTs to every
// port, each axis stepped alone (X, Y, Z, each sign), two and three
// together, back to back and with other writes between, step bits written
// to the other ports, debug writes alone and back to back. The expected
// waveform of every STEP pin and of the debug strobe comes from the
// program and the page alone: each step bit written as 1 to port 10h is
// one pulse, high for exactly one clock (the OUT's T3, its 10th T-state),
// each write to port 13h one clock of o_debug_we with the byte on
// o_debug; every write to 10h latches the three DIR bits; nothing else
// strobes. The instructions' T-states are the 8085 data sheet's (MVI 7,
// OUT 10, NOP 4), written here, so the strobes' spacing is checked too. A
// strobe left high, never dropped, doubled or lost fails here.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "Vboard8085.h"
#include "harness.hpp"

namespace cpu8085::tb {
namespace {

// One instruction of the program: MVI A,v / OUT p / NOP / HLT.
struct Ins {
  enum Kind { mvi, out, nop, hlt } kind;
  std::uint8_t arg = 0;
};

constexpr std::uint8_t kStep = 0x10, kCmdCount = 0x11, kDone = 0x12, kDebug = 0x13;

const std::vector<Ins> kProgram = {
    {Ins::mvi, 0x04}, {Ins::out, kStep},       // Y+ alone
    {Ins::out, kStep},                         // Y+ alone again, back to back
    {Ins::nop}, {Ins::nop}, {Ins::nop},
    {Ins::mvi, 0x0C}, {Ins::out, kStep},       // Y- alone
    {Ins::mvi, 0x5A}, {Ins::out, kDebug},      // a debug byte
    {Ins::mvi, 0x10}, {Ins::out, kStep},       // Z+ alone
    {Ins::out, kStep},                         // and again
    {Ins::mvi, 0x30}, {Ins::out, kStep},       // Z- alone
    {Ins::mvi, 0x15}, {Ins::out, kDone},       // step bits to the done port: no step
    {Ins::mvi, 0xA5}, {Ins::out, kDebug},      // debug bytes back to back
    {Ins::out, kDebug},
    {Ins::mvi, 0x01}, {Ins::out, kStep},       // X+ alone
    {Ins::mvi, 0x2A}, {Ins::out, kStep},       // the DIR bits only
    {Ins::mvi, 0x03}, {Ins::out, kStep},       // X- alone (Y, Z directions back to +)
    {Ins::mvi, 0x15}, {Ins::out, kStep},       // X+ Y+ Z+
    {Ins::mvi, 0x3F}, {Ins::out, kStep},       // X- Y- Z-
    {Ins::mvi, 0x14}, {Ins::out, kStep},       // Y+ Z+
    {Ins::mvi, 0x11}, {Ins::out, kStep},       // X+ Z+
    {Ins::mvi, 0x05}, {Ins::out, kStep},       // X+ Y+
    {Ins::mvi, 0x15}, {Ins::out, 0x20},        // an unmapped port: nothing
    {Ins::out, kCmdCount},                     // the IN port written: nothing
    {Ins::mvi, 0xC4}, {Ins::out, kStep},       // Y+ (bits 6-7 ignored)
    {Ins::mvi, 0x00}, {Ins::out, kDebug},      // a debug byte of 0
    {Ins::mvi, 0xC0}, {Ins::out, kStep},       // no step bits
    {Ins::nop}, {Ins::nop}, {Ins::nop}, {Ins::nop},
    {Ins::hlt},
};

// The 8085 data sheet's T-states and encodings of these four.
int tstates(const Ins& i) {
  switch (i.kind) {
    case Ins::mvi: return 7;
    case Ins::out: return 10;
    case Ins::nop: return 4;
    case Ins::hlt: return 5;
  }
  return 0;
}

std::vector<std::uint8_t> encode(const std::vector<Ins>& prog) {
  std::vector<std::uint8_t> rom;
  for (const Ins& i : prog) {
    switch (i.kind) {
      case Ins::mvi: rom.insert(rom.end(), {0x3E, i.arg}); break;
      case Ins::out: rom.insert(rom.end(), {0xD3, i.arg}); break;
      case Ins::nop: rom.push_back(0x00); break;
      case Ins::hlt: rom.push_back(0x76); break;
    }
  }
  return rom;
}

// The ROM image for the board's +rom= loader (docs/board8085.md "ROM
// image"): 8192 lines of two hex digits, FF where nothing is programmed.
std::string write_memh(const std::vector<std::uint8_t>& rom) {
  const std::string path = ::testing::TempDir() + "board_io_test.memh";
  std::ofstream f(path);
  for (std::size_t a = 0; a < 0x2000; ++a) {
    char line[4];
    std::snprintf(line, sizeof line, "%02X", a < rom.size() ? rom[a] : 0xFF);
    f << line << '\n';
  }
  return path;
}

// What the pins show after each clock.
struct Pins {
  std::array<bool, 3> step{}, dir{};
  bool debug_we = false;
  std::uint8_t debug = 0, done = 0;
};

// Each OUT's strobe, at its offset (clocks) from the program's first
// T-state: its 10th T-state.
struct Strobe {
  std::uint64_t t = 0;
  std::uint8_t port = 0, value = 0;
};

std::vector<Strobe> strobes_of(const std::vector<Ins>& prog) {
  std::vector<Strobe> s;
  std::uint64_t t = 0, a = 0;
  for (const Ins& i : prog) {
    if (i.kind == Ins::mvi) a = i.arg;
    if (i.kind == Ins::out) s.push_back({t + 9, i.arg, static_cast<std::uint8_t>(a)});
    t += static_cast<std::uint64_t>(tstates(i));
  }
  return s;
}

TEST(BoardIo, EveryStepAndDebugStrobeIsOneClockAtItsOutsThirdTState) {
  const std::string memh = write_memh(encode(kProgram));
  contour::tb::Harness<Vboard8085> h("", "board", {"+rom=" + memh});
  auto& top = h.top();
  top.i_intr_vec = 0xFF;
  top.i_cmd = 0;
  h.hold_reset(1);

  // Run to the HLT and 40 clocks past it. pins[c]: the pins during the c'th
  // clock after the reset (0: the one that follows the reset's edge).
  std::vector<Pins> pins;
  std::uint64_t halted_at = 0;
  while (pins.size() < 2000 && (halted_at == 0 || pins.size() < halted_at + 40)) {
    if (!pins.empty()) h.tick();
    Pins p;
    p.step = {top.o_step_x != 0, top.o_step_y != 0, top.o_step_z != 0};
    p.dir = {top.o_dir_x != 0, top.o_dir_y != 0, top.o_dir_z != 0};
    p.debug_we = top.o_debug_we != 0;
    p.debug = top.o_debug;
    p.done = top.o_done;
    pins.push_back(p);
    if (top.o_halted && halted_at == 0) halted_at = pins.size();
  }
  ASSERT_NE(halted_at, 0u) << "the program did not reach its HLT";

  // The expected strobes, placed by the first one seen: it must lie in the
  // first OUT (the CPU's first T-state is at most a few clocks after the
  // reset; 0 here).
  const std::vector<Strobe> strobes = strobes_of(kProgram);
  std::size_t first = 0;
  while (first < pins.size() && !pins[first].step[0] && !pins[first].step[1] && !pins[first].step[2] &&
         !pins[first].debug_we)
    ++first;
  ASSERT_LT(first, pins.size()) << "no strobe at all";
  ASSERT_GE(first, strobes.front().t) << "the first strobe is before the program's first OUT's T3";
  const std::uint64_t origin = first - strobes.front().t;
  ASSERT_LE(origin, 4u) << "the first strobe is not in the program's first OUT";

  // The expected waveform, clock by clock, from the program alone.
  std::vector<Pins> want(pins.size());
  std::array<int, 3> pulses{};
  int debug_writes = 0;
  std::array<bool, 3> dir{};
  std::uint8_t debug = 0, done = 0;
  std::size_t k = 0;
  for (std::size_t c = 0; c < want.size(); ++c) {
    Pins& w = want[c];
    while (k < strobes.size() && origin + strobes[k].t == c) {
      const Strobe& s = strobes[k++];
      if (s.port == kStep) {
        for (std::size_t a = 0; a < 3; ++a) {
          dir[a] = (s.value >> (2 * a + 1)) & 1;
          if ((s.value >> (2 * a)) & 1) {
            w.step[a] = true;
            ++pulses[a];
          }
        }
      } else if (s.port == kDebug) {
        w.debug_we = true;
        debug = s.value;
        ++debug_writes;
      } else if (s.port == kDone) {
        done = s.value;
      }
    }
    w.dir = dir;
    w.debug = debug;
    w.done = done;
  }
  ASSERT_EQ(k, strobes.size());
  // The program's own counts (from its comments): X 6, Y 8, Z 7 pulses, 4 debug writes.
  EXPECT_EQ(pulses, (std::array<int, 3>{6, 8, 7}));
  EXPECT_EQ(debug_writes, 4);

  // Every clock: each STEP pin, each DIR pin, the debug strobe and byte.
  const char* axis = "XYZ";
  std::array<int, 3> rises{}, mismatches{};
  int debug_rises = 0, debug_mismatches = 0, other_mismatches = 0;
  for (std::size_t c = 0; c < pins.size(); ++c) {
    const Pins& p = pins[c];
    const Pins& w = want[c];
    const Pins* before = c > 0 ? &pins[c - 1] : nullptr;
    for (std::size_t a = 0; a < 3; ++a) {
      if (p.step[a] && !(before && before->step[a])) ++rises[a];
      if (p.step[a] != w.step[a] && ++mismatches[a] <= 3)
        ADD_FAILURE() << "STEP " << axis[a] << " at clock " << c << " (program T-state " << c - origin << "): "
                      << p.step[a] << ", expected " << w.step[a];
    }
    if (p.debug_we && !(before && before->debug_we)) ++debug_rises;
    if (p.debug_we != w.debug_we && ++debug_mismatches <= 3)
      ADD_FAILURE() << "o_debug_we at clock " << c << " (program T-state " << c - origin << "): " << p.debug_we
                    << ", expected " << w.debug_we;
    if ((p.dir != w.dir || (w.debug_we && p.debug != w.debug) || p.done != w.done) && ++other_mismatches <= 3)
      ADD_FAILURE() << "clock " << c << ": DIR " << p.dir[0] << p.dir[1] << p.dir[2] << " (expected " << w.dir[0]
                    << w.dir[1] << w.dir[2] << "), debug " << int{p.debug} << " (" << int{w.debug} << "), done "
                    << int{p.done} << " (" << int{w.done} << ")";
  }
  // Each pulse and each debug write one rising edge, counted once.
  EXPECT_EQ(rises, pulses);
  EXPECT_EQ(debug_rises, debug_writes);
  EXPECT_EQ(mismatches, (std::array<int, 3>{}));
  EXPECT_EQ(debug_mismatches, 0);
  EXPECT_EQ(other_mismatches, 0);
}

}  // namespace
}  // namespace cpu8085::tb
