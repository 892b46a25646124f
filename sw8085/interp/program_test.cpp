// The 8085 program against the golden model: pulses and state after every
// pulse, on the ISS.
#include <gtest/gtest.h>

#include <cstdlib>

#include "interp/engine.hpp"
#include "sw8085/interp/expect_model.hpp"
#include "sw8085/interp/host.hpp"

namespace contour::sw8085 {
namespace {

TEST(Program, PaperFig2Line) {
  Host h;
  const Move m = Move::line(6, 5);
  expect_model_run(h, m);
}

TEST(Program, PaperFig5Arc) {
  Host h;
  const Move m = Move::arc(6, 0, 0, 6, Sense::CCW);
  expect_model_run(h, m);
}

// CONTOUR_FULL=1 (set, not empty, not 0): the long runs.
bool full_run() {
  const char* e = std::getenv("CONTOUR_FULL");
  return e != nullptr && *e != '\0' && *e != '0';
}

// Every line with |XE|, |YE| <= N (N = 16, 40 with CONTOUR_FULL=1).
TEST(Program, AllSmallLines) {
  Host h;
  const int n = full_run() ? 40 : 16;
  for (int xe = -n; xe <= n; ++xe)
    for (int ye = -n; ye <= n; ++ye) {
      const Move m = Move::line(xe, ye);
      expect_model_run(h, m);
      if (HasFatalFailure()) return;
    }
}

// Every accepted arc between points with |coordinates| <= N, both senses
// (N = 6, 9 with CONTOUR_FULL=1): quadrant crossings, full circles, the end
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
            if (!accepted(m)) continue;
            expect_model_run(h, m);
            if (HasFatalFailure()) return;
            ++runs;
          }
  EXPECT_GT(runs, 1000);
}

}  // namespace
}  // namespace contour::sw8085
