// interp_ipp: x86 instructions per output pulse of the model's hot loops.
//
//   interp_ipp            runs itself under callgrind at two move lengths and
//                         prints (instructions(N2) - instructions(N1)) / pulses,
//                         which cancels start-up and set-up costs
//   interp_ipp KIND N     the loop alone (KIND linear|circular), as measured
//
// Instruction counts do not depend on the machine's load: the figure is
// repeatable, which a time is not.
#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>

#include "interp/circular.hpp"
#include "interp/linear.hpp"

namespace {

using namespace contour;

// A slope of 2/3: both branches of the linear step are taken.
[[gnu::noinline]] std::uint64_t run_linear(std::int64_t n) {
  Linear<24> l(n, n * 2 / 3);
  std::uint64_t h = 0;
  while (auto p = l.step()) h += static_cast<std::uint64_t>(p->sign);
  return h;
}

// A full circle of radius n: 8n pulses through every quadrant.
[[gnu::noinline]] std::uint64_t run_circular(std::int64_t n) {
  Circular<24> c(n, 0, n, 0, Sense::CCW);
  std::uint64_t h = 0;
  while (auto p = c.step()) h += static_cast<std::uint64_t>(p->sign);
  return h;
}

std::uint64_t pulses(const std::string& kind, std::int64_t n) {
  return kind == "linear" ? static_cast<std::uint64_t>(n + n * 2 / 3) : 8 * static_cast<std::uint64_t>(n);
}

// Instructions callgrind counted for `self KIND N`.
long long count(const char* self, const std::string& kind, std::int64_t n) {
  const std::string cmd = "valgrind --tool=callgrind --callgrind-out-file=/dev/null " + std::string(self) + " " +
                          kind + " " + std::to_string(n) + " 2>&1 >/dev/null | grep 'Collected :'";
  std::unique_ptr<FILE, int (*)(FILE*)> p(popen(cmd.c_str(), "r"), pclose);
  long long total = -1;
  if (p && std::fscanf(p.get(), "%*[^:]: %lld", &total) != 1) total = -1;
  return total;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 3) {
    const std::string kind = argv[1];
    const std::int64_t n = std::atoll(argv[2]);
    if ((kind != "linear" && kind != "circular") || n <= 0) return 2;
    std::printf("%llu\n", static_cast<unsigned long long>(kind == "linear" ? run_linear(n) : run_circular(n)));
    return 0;
  }
  std::printf("%-10s %14s %14s %12s\n", "loop", "pulses", "instructions", "per pulse");
  for (const std::string kind : {"linear", "circular"}) {
    const std::int64_t n1 = 100000, n2 = 200000;
    const long long c1 = count(argv[0], kind, n1), c2 = count(argv[0], kind, n2);
    if (c1 < 0 || c2 < 0) {
      std::fprintf(stderr, "interp_ipp: valgrind --tool=callgrind failed (is valgrind installed?)\n");
      return 1;
    }
    const std::uint64_t dp = pulses(kind, n2) - pulses(kind, n1);
    std::printf("%-10s %14llu %14lld %12.2f\n", kind.c_str(), static_cast<unsigned long long>(dp), c2 - c1,
                double(c2 - c1) / double(dp));
  }
  return 0;
}
