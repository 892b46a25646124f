// The Verilated CPU clocked with one eval() per T-state (one_eval_clock.hpp,
// the path without a waveform) against the same model clocked with the
// harness's two evals (the path a waveform takes): random memory run as
// code, TRAP pulses and RST 5.5 / 6.5 levels changed between steps on
// both; every step's kind, interrupt, T-states, registers, HALT and IE
// must be equal, and the memories at the end.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <random>

#include "cpu_machine.hpp"
#include "i8085/system.hpp"

namespace {

void set_pins(i8085::Machine& m, int step) {
  m.set_trap(step % 997 == 0);
  m.set_rst55((step / 301) % 3 == 0);
  m.set_rst65((step / 499) % 4 == 0);
}

TEST(OneEvalClock, SameUnitsAsTwoEvals) {
  i8085::RamBus one_bus, two_bus;
  std::mt19937 rng(85);
  for (auto& b : one_bus.mem) b = static_cast<std::uint8_t>(rng());
  two_bus.mem = one_bus.mem;
  const std::string fst = (std::filesystem::temp_directory_path() / "one_eval_clock_test.fst").string();
  const auto one = cpu8085::make_cpu_machine(one_bus, i8085::Mode::i8085);
  const auto two = cpu8085::make_cpu_machine(two_bus, i8085::Mode::i8085, fst);
  int interrupts = 0;
  for (int i = 0; i < 20000; ++i) {
    set_pins(*one, i);
    set_pins(*two, i);
    ASSERT_EQ(one->step(), two->step()) << "step " << i;
    const i8085::Step &a = one->last(), &b = two->last();
    ASSERT_EQ(a.kind, b.kind) << "step " << i;
    ASSERT_EQ(a.irq, b.irq) << "step " << i;
    ASSERT_EQ(a.pc, b.pc) << "step " << i;
    const i8085::Regs ra = one->regs(), rb = two->regs();
    ASSERT_EQ(std::vector<int>({ra.a, ra.f, ra.b, ra.c, ra.d, ra.e, ra.h, ra.l, ra.sp, ra.pc}),
              std::vector<int>({rb.a, rb.f, rb.b, rb.c, rb.d, rb.e, rb.h, rb.l, rb.sp, rb.pc}))
        << "step " << i;
    ASSERT_EQ(one->halted(), two->halted()) << "step " << i;
    ASSERT_EQ(one->ie(), two->ie()) << "step " << i;
    interrupts += a.kind == i8085::StepKind::interrupt;
  }
  EXPECT_EQ(one->tstates(), two->tstates());
  EXPECT_TRUE(one_bus.mem == two_bus.mem);
  EXPECT_GT(interrupts, 10);  // the pins did something
  std::remove(fst.c_str());
}

}  // namespace
