// Test support (GoogleTest): the program's run of a move, on whatever 8085
// the Host was given, against the golden model's run of the same move,
// pulse by pulse and state by state. Used by sw8085/interp's tests and by
// tb/cpu8085's (the program on the Verilog CPU and board).
#pragma once

#include <gtest/gtest.h>

#include "interp/engine.hpp"
#include "sw8085/interp/host.hpp"

namespace contour::sw8085 {

// Whether the host's validation at W = 24 accepts the move (a test that
// sweeps moves skips the others, and counts the ones it ran).
inline bool accepted(const Move& m) {
  try {
    validate<24>(m);
    return true;
  } catch (const InputError&) {
    return false;
  }
}

inline void expect_model_run(Host& h, const Move& m) {
  const RunResult want = run_model<24>(m);
  const RunResult got = h.run(m, nullptr, want.steps.size() + 1);
  ASSERT_EQ(got.initial_state, want.initial_state) << describe(m) << " initial state";
  ASSERT_EQ(got.steps.size(), want.steps.size()) << describe(m);
  for (std::size_t i = 0; i < want.steps.size(); ++i) {
    ASSERT_EQ(got.steps[i].pulse, want.steps[i].pulse) << describe(m) << " pulse " << i + 1;
    ASSERT_EQ(got.steps[i].state, want.steps[i].state)
        << describe(m) << " state after pulse " << i + 1 << ": got " << to_string(got.steps[i].state) << ", want "
        << to_string(want.steps[i].state);
  }
  ASSERT_EQ(got.final_state, want.final_state) << describe(m) << " final state";
}

}  // namespace contour::sw8085
