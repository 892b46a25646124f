// Programs from sw8085/tests, assembled by the build (asm80), run through
// the runners; plus the runners' error paths. Expected T-states are the hand
// counts written in each program's header.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include "i8085/system.hpp"
#include "sw8085_paths.hpp"

namespace i8085 {
namespace {

std::vector<std::uint8_t> read_all(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  EXPECT_TRUE(in) << "cannot open " << path << " (is sw8085_hex built?)";
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::string program(const std::string& rel) { return std::string(contour::sw8085::kHexDir) + "/" + rel; }

TEST(Programs, Rst75HandlerTimingMatchesTheHandCount) {
  RamBus bus;
  auto m = make_iss(bus, Mode::i8085);
  load_program(bus, read_all(program("tests/rst75.hex")), "rst75.hex", 0);
  m->reset();
  run_bare(*m, bus, {});
  ASSERT_EQ(m->tstates(), 40u);
  std::uint64_t t0 = 100;
  RunResult res;
  for (int pulse = 1; pulse <= 3; ++pulse) {
    while (m->tstates() < t0) run_step(*m, bus, {}, res);  // idle units of 1 T-state
    m->set_rst75(true);
    m->set_rst75(false);
    run_step(*m, bus, {}, res);
    EXPECT_EQ(m->last().irq, Interrupt::rst75);
    while (!m->halted()) run_step(*m, bus, {}, res);
    ASSERT_EQ(bus.outs.size(), static_cast<std::size_t>(pulse));
    EXPECT_EQ(bus.outs.back().t, t0 + 54);
    EXPECT_EQ(bus.outs.back().value, pulse);
    EXPECT_EQ(m->tstates(), t0 + 103);
    t0 += 250;
  }
}

TEST(Programs, HelloPrintsThroughBdos) {
  RamBus bus;
  auto m = make_iss(bus, Mode::i8085);
  EXPECT_EQ(load_program(bus, read_all(program("tests/hello.hex")), "hello.hex", 0x100), 0x0100);
  std::ostringstream out;
  const RunResult r = run_cpm(*m, bus, out, {});
  EXPECT_EQ(out.str(), "Hello from CP/M!");
  EXPECT_EQ(r.tstates, 127u);
}

TEST(Programs, CpmFlagDiagnosticPassesInBothModes) {
  for (Mode mode : {Mode::i8085, Mode::i8080}) {
    RamBus bus;
    auto m = make_iss(bus, mode);
    load_program(bus, read_all(program("tests/cpmtest.hex")), "cpmtest.hex", 0x100);
    std::ostringstream out;
    run_cpm(*m, bus, out, {});
    EXPECT_NE(out.str().find("CPMTEST PASSED"), std::string::npos) << out.str();
  }
}

TEST(Runner, RawBinaryAtBaseAndTrace) {
  RamBus bus;
  auto m = make_iss(bus, Mode::i8085);
  // MVI A,41; OUT 02; HLT
  load_program(bus, {0x3E, 0x41, 0xD3, 0x02, 0x76}, "raw.bin", 0x0000);
  m->reset();
  std::ostringstream trace;
  RunOptions opt;
  opt.trace = &trace;
  const RunResult r = run_bare(*m, bus, opt);
  EXPECT_EQ(r.tstates, 7u + 10u + 5u);
  EXPECT_EQ(r.steps, 3u);
  ASSERT_EQ(bus.outs.size(), 1u);
  EXPECT_EQ(bus.outs[0], (PortWrite{7, 0x02, 0x41}));
  const std::string text = trace.str();
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 3);
}

TEST(Runner, UndocumentedOpcodeStopsTheRun) {
  RamBus bus;
  auto m = make_iss(bus, Mode::i8085);
  load_program(bus, {0x00, 0x08, 0x76}, "raw.bin", 0);
  m->reset();
  try {
    run_bare(*m, bus, {});
    FAIL() << "no error";
  } catch (const RunError& e) {
    EXPECT_STREQ(e.what(), "undocumented 8085 opcode 08 (UNDOC DSUB) at PC=0001: not implemented (docs/i8085.md)");
  }
  // The 8080 runs 08 as a NOP.
  RamBus bus80;
  auto m80 = make_iss(bus80, Mode::i8080);
  load_program(bus80, {0x00, 0x08, 0x76}, "raw.bin", 0);
  m80->reset();
  EXPECT_EQ(run_bare(*m80, bus80, {}).tstates, 4u + 4u + 7u);
}

TEST(Runner, TStateLimitIsAnError) {
  RamBus bus;
  auto m = make_iss(bus, Mode::i8085);
  load_program(bus, {0xC3, 0x00, 0x00}, "loop.bin", 0);  // JMP 0000 forever
  m->reset();
  RunOptions opt;
  opt.max_tstates = 1000;
  EXPECT_THROW(run_bare(*m, bus, opt), RunError);
  EXPECT_EQ(m->tstates(), 1010u);  // the first step that ends past the limit
}

TEST(Runner, ARunUsingExactlyTheLimitFinishes) {
  RamBus bus;
  auto m = make_iss(bus, Mode::i8085);
  load_program(bus, {0x00, 0x76}, "nop_hlt.bin", 0);  // 4 + 5 T-states
  m->reset();
  RunOptions opt;
  opt.max_tstates = 9;
  EXPECT_EQ(run_bare(*m, bus, opt).tstates, 9u);
  RamBus bus2;
  auto m2 = make_iss(bus2, Mode::i8085);
  load_program(bus2, {0x00, 0x76}, "nop_hlt.bin", 0);
  m2->reset();
  opt.max_tstates = 8;
  EXPECT_THROW(run_bare(*m2, bus2, opt), RunError);
}

TEST(Runner, UnsupportedBdosFunctionIsAnError) {
  RamBus bus;
  auto m = make_iss(bus, Mode::i8085);
  load_program(bus, {0x0E, 0x01, 0xCD, 0x05, 0x00, 0xC9}, "bdos1.com", 0x100);  // MVI C,1; CALL 5
  std::ostringstream out;
  try {
    run_cpm(*m, bus, out, {});
    FAIL() << "no error";
  } catch (const RunError& e) {
    EXPECT_STREQ(e.what(), "unsupported BDOS function C=01 (only 2 and 9 are served), return address 0105");
  }
}

TEST(Runner, HexErrorsNameTheFile) {
  RamBus bus;
  const std::string bad = ":0100000001FF\n";  // checksum wrong
  EXPECT_THROW(load_program(bus, std::vector<std::uint8_t>(bad.begin(), bad.end()), "bad.hex", 0), HexError);
}

}  // namespace
}  // namespace i8085
