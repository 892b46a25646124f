// Paper B's real-time budget: planning and chord interpolation per 1 ms
// control cycle must take at most 1 % of the cycle (10 us) on this machine.
// Counter cycles_per_s: control cycles processed per second of CPU time; the
// 1 % target is met at >= 100k/s (10 us per 1 ms cycle).
#include <benchmark/benchmark.h>

#include "gcode/gcode.hpp"
#include "planner/planner.hpp"
#include "planner/two_stage.hpp"

namespace {

using namespace contour;

const char* kPaper3D = "G00X50.Y0.Z0.\nG03X0.Y-47.246Z-16.366I-50J0.K0.F6000\nG00X0.Y0.Z0.\n";
const char* kMixed =
    "G0 X10 Y5\nG1 X40 Y5 F9000\nG3 X50 Y15 I0 J10\nG1 X50 Y40\nG1 X30 Y60 Z-3\n"
    "G2 X10 Y60 Z-8 I-10 J0\nG18 G3 X0 Z-18 I-10 K0\nG0 X0 Y0 Z0\n";

void per_cycle(benchmark::State& state, std::size_t cycles_per_iteration) {
  state.counters["cycles_per_s"] =
      benchmark::Counter(static_cast<double>(cycles_per_iteration), benchmark::Counter::kIsIterationInvariantRate);
}

// Read + plan + every chord of the program, per control cycle.
void BM_PlanAndInterpolate(benchmark::State& state, const char* program) {
  std::size_t cycles = 0;
  for (auto _ : state) {
    const auto plan = planner::plan(gcode::parse(program), planner::Config{});
    planner::Interpolator it(plan);
    planner::Sample s;
    double acc = 0;
    while (it.next(s)) acc += s.p.x;
    benchmark::DoNotOptimize(acc);
    cycles = it.cycles();
  }
  per_cycle(state, cycles);
  state.counters["cycles"] = static_cast<double>(cycles);
}
BENCHMARK_CAPTURE(BM_PlanAndInterpolate, paper_b_3d, kPaper3D)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_PlanAndInterpolate, mixed, kMixed)->Unit(benchmark::kMillisecond);

// One chord (one control cycle) of the 3D arc, the real-time step alone.
void BM_ChordOfTheCycle(benchmark::State& state) {
  const auto plan = planner::plan(gcode::parse(kPaper3D), planner::Config{});
  planner::Interpolator it(plan);
  planner::Sample s;
  for (auto _ : state) {
    if (!it.next(s)) {
      state.PauseTiming();
      it = planner::Interpolator(plan);
      state.ResumeTiming();
      it.next(s);
    }
    benchmark::DoNotOptimize(s);
  }
  per_cycle(state, 1);
}
BENCHMARK(BM_ChordOfTheCycle);

// Stage 2: one cycle's chord spread into pulses by Linear3 (the 3D arc at
// 1000 steps/mm: about 100 pulses per cycle at 6000 mm/min).
void BM_TwoStagePulses(benchmark::State& state) {
  const auto plan = planner::plan(gcode::parse(kPaper3D), planner::Config{});
  const auto chords = planner::chords_in_steps(planner::interpolate(plan), 1000);
  std::size_t pulses = 0;
  for (auto _ : state) {
    const auto out = planner::two_stage_model(chords, plan.config.cycle_s);
    pulses = out.size();
    benchmark::DoNotOptimize(out.data());
  }
  per_cycle(state, chords.size());
  state.counters["pulses"] = static_cast<double>(pulses);
}
BENCHMARK(BM_TwoStagePulses)->Unit(benchmark::kMillisecond);

}  // namespace
