// Output pulses per second of the golden model's interpolators.
#include <benchmark/benchmark.h>

#include "interp/circular.hpp"
#include "interp/linear.hpp"

namespace contour {
namespace {

void BM_LinearPulses(benchmark::State& state) {
  const std::int64_t xe = max_magnitude(24), ye = 11184810;  // 2/3 slope, 2^24-scale
  std::uint64_t pulses = 0;
  for (auto _ : state) {
    Linear<24> l(xe, ye);
    for (int i = 0; i < 1 << 16; ++i) benchmark::DoNotOptimize(l.step());
    pulses += 1 << 16;
  }
  state.counters["pulses/s"] = benchmark::Counter(double(pulses), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_LinearPulses);

void BM_CircularPulses(benchmark::State& state) {
  const std::int64_t r = state.range(0);
  std::uint64_t pulses = 0;
  for (auto _ : state) {
    Circular<24> c(r, 0, r, 0, Sense::CCW);  // full circle: 8R pulses, every quadrant
    while (auto p = c.step()) benchmark::DoNotOptimize(p);
    pulses += 8 * static_cast<std::uint64_t>(r);
  }
  state.counters["pulses/s"] = benchmark::Counter(double(pulses), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_CircularPulses)->Arg(1000)->Arg(100000);

void BM_CircularValidate(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(Circular<24>::validate(12345, 6789, -6789, 12345, Sense::CW));
}
BENCHMARK(BM_CircularValidate);

}  // namespace
}  // namespace contour
