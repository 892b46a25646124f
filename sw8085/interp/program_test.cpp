// The 8085 program against the golden model: pulses and state after every
// pulse, on the ISS.
#include <gtest/gtest.h>

#include "interp/engine.hpp"
#include "sw8085/interp/host.hpp"

namespace contour::sw8085 {
namespace {

void expect_same(const Move& m, const RunResult& got, const RunResult& want) {
  ASSERT_EQ(got.initial_state, want.initial_state) << describe(m) << " initial state";
  ASSERT_EQ(got.steps.size(), want.steps.size()) << describe(m);
  for (std::size_t i = 0; i < want.steps.size(); ++i) {
    ASSERT_EQ(got.steps[i].pulse, want.steps[i].pulse) << describe(m) << " pulse " << i + 1;
    ASSERT_EQ(got.steps[i].state, want.steps[i].state)
        << describe(m) << " state after pulse " << i + 1 << ": got " << to_string(got.steps[i].state) << ", want "
        << to_string(want.steps[i].state);
  }
  ASSERT_EQ(got.final_state, want.final_state) << describe(m);
}

TEST(Program, PaperFig2Line) {
  Host h;
  const Move m = Move::line(6, 5);
  expect_same(m, h.run(m), run_model<24>(m));
}

TEST(Program, PaperFig5Arc) {
  Host h;
  const Move m = Move::arc(6, 0, 0, 6, Sense::CCW);
  expect_same(m, h.run(m), run_model<24>(m));
}

}  // namespace
}  // namespace contour::sw8085
