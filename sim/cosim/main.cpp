// contour-cosim: the SystemC co-simulation program (docs/cosim.md). The CLI's
// `contour cosim` runs it with the same arguments.
#include <systemc>

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "options.hpp"
#include "report.hpp"
#include "top.hpp"

// SystemC prints its banner before sc_main unless told not to; stdout is the
// run's summary. A static initialiser runs before SystemC's main().
static const int kNoBanner = ::setenv("SYSTEMC_DISABLE_COPYRIGHT_MESSAGE", "1", 0);

namespace {

// One warning line per engine that had NOT RUN rows (above its max_rate),
// naming the rates.
void warn_not_run(const std::vector<contour::cosim::Row>& rows, double core_hz) {
  using namespace contour::cosim;
  std::map<std::string, std::pair<std::size_t, std::set<double>>> skipped;  // engine -> (rows, rates)
  for (const auto& r : rows)
    if (!r.ran()) {
      auto& s = skipped[r.engine];
      ++s.first;
      s.second.insert(r.rate_pps);
    }
  for (const auto& [engine, s] : skipped) {
    std::string rates;
    for (double r : s.second) rates += (rates.empty() ? "" : ", ") + rate_label(r);
    std::fprintf(stderr, "contour cosim: warning: %zu %s row(s) NOT RUN (%s takes command rates up to %s pps: not run at %s pps)\n",
                 s.first, engine.c_str(), engine.c_str(), rate_label(max_rate(engine, core_hz)).c_str(), rates.c_str());
  }
}

}  // namespace

int sc_main(int argc, char** argv) {
  using namespace contour::cosim;
  std::vector<std::string> args(argv + 1, argv + argc);
  Options opt;
  try {
    bool help = false;
    opt = parse_options(args, help);
    if (help) {
      std::fputs(usage().c_str(), stdout);
      return 0;
    }
  } catch (const UsageError& e) {
    std::fprintf(stderr, "contour cosim: %s\n", e.what());
    return 2;
  }
  try {
    const CosimOutcome out = run_cosim(opt);
    warn_not_run(out.rows, opt.core_hz);
    std::printf("%s\n", verdict_line(out.rows).c_str());
    for (const auto& r : out.rows)
      if (r.verdict == Verdict::Fail)
        std::printf("FAIL %s %s @ %s pps: %s\n", r.case_name.c_str(), r.engine.c_str(), rate_label(r.rate_pps).c_str(),
                    r.note.c_str());
    std::printf("%s\n", coverage_line(out.coverage).c_str());
    for (const auto& f : out.files) std::printf("wrote %s\n", f.c_str());
    std::fflush(stdout);
    return out.ok() ? 0 : 1;
  } catch (const UsageError& e) {
    std::fprintf(stderr, "contour cosim: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "contour cosim: %s\n", e.what());
    return 1;
  }
}
