// The 8085 program against the golden model: pulses and state after every
// pulse, on the ISS.
#include <gtest/gtest.h>

#include <cstdlib>

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
  {
        const RunResult want = run_model<24>(m);
        expect_same(m, h.run(m, nullptr, want.steps.size() + 1), want);
      }
}

TEST(Program, PaperFig5Arc) {
  Host h;
  const Move m = Move::arc(6, 0, 0, 6, Sense::CCW);
  {
        const RunResult want = run_model<24>(m);
        expect_same(m, h.run(m, nullptr, want.steps.size() + 1), want);
      }
}

}  // namespace
}  // namespace contour::sw8085

namespace contour::sw8085 {
namespace {

bool full_run() { return std::getenv("SW8085_FULL") != nullptr; }

// Every line with |XE|, |YE| <= N (N = 16, 40 with SW8085_FULL=1).
TEST(Program, AllSmallLines) {
  Host h;
  const int n = full_run() ? 40 : 16;
  for (int xe = -n; xe <= n; ++xe)
    for (int ye = -n; ye <= n; ++ye) {
      const Move m = Move::line(xe, ye);
      {
        const RunResult want = run_model<24>(m);
        expect_same(m, h.run(m, nullptr, want.steps.size() + 1), want);
      }
      if (HasFatalFailure()) return;
    }
}

// Every accepted arc between points with |coordinates| <= N, both senses
// (N = 6, 9 with SW8085_FULL=1): quadrant crossings, full circles, the end
// rule in every quadrant.
TEST(Program, AllSmallArcs) {
  Host h;
  const int n = full_run() ? 9 : 6;
  int runs = 0;
  for (int xs = -n; xs <= n; ++xs)
    for (int ys = -n; ys <= n; ++ys)
      for (int xe = -n - 1; xe <= n + 1; ++xe)
        for (int ye = -n - 1; ye <= n + 1; ++ye)
          for (Sense s : {Sense::CCW, Sense::CW}) {
            const Move m = Move::arc(xs, ys, xe, ye, s);
            try {
              validate<24>(m);
            } catch (const InputError&) {
              continue;
            }
            {
        const RunResult want = run_model<24>(m);
        expect_same(m, h.run(m, nullptr, want.steps.size() + 1), want);
      }
            if (HasFatalFailure()) return;
            ++runs;
          }
  EXPECT_GT(runs, 1000);
}

}  // namespace
}  // namespace contour::sw8085
