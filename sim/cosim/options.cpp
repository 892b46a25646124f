#include "options.hpp"

#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <sstream>

namespace contour::cosim {

namespace {

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream ss(s);
  std::string item;
  while (std::getline(ss, item, ','))
    if (!item.empty()) out.push_back(item);
  return out;
}

std::uint32_t parse_clocks(const std::string& text, const std::string& what) {
  char* end = nullptr;
  const long v = std::strtol(text.c_str(), &end, 10);
  if (text.empty() || *end != '\0' || v < 1 || v > 65535)
    throw UsageError(what + " '" + text + "': expected clocks 1..65535");
  return static_cast<std::uint32_t>(v);
}

}  // namespace

double parse_rate(const std::string& text, const std::string& what) {
  if (text.empty()) throw UsageError(what + ": empty rate");
  double mult = 1;
  std::string num = text;
  const char last = text.back();
  if (last == 'k' || last == 'K') mult = 1e3, num.pop_back();
  else if (last == 'M') mult = 1e6, num.pop_back();
  char* end = nullptr;
  const double v = std::strtod(num.c_str(), &end);
  if (num.empty() || *end != '\0' || !std::isfinite(v))
    throw UsageError(what + " '" + text + "' is not a rate (examples: 4000, 3.5k, 250k, 1M)");
  const double r = v * mult;
  if (r < 1 || r > 50e6) throw UsageError(what + " '" + text + "' is outside 1 .. 50M pulses/s");
  return r;
}

std::string usage() {
  return "usage: contour cosim --suite paper|smoke|full[,...] (--rate R[,R...] | --sweep) [--report DIR] [--trace]\n"
         "         [--engines model,rtl,iss,8085] [--case NAME[,NAME...]] [--progress|--no-progress]\n"
         "         [--free-clock] [--step-len N] [--step-space N] [--inject ENGINE:drop|swap|flip:N]\n"
         "  Co-simulates the golden model, the Verilog core (rtl), the 8085 program on the ISS (iss)\n"
         "  and on the Verilog 8085 board (8085) on the same command pulse train; exit 0 only when\n"
         "  every required equivalence holds (docs/cosim.md).\n";
}

Options parse_options(const std::vector<std::string>& args, bool& help) {
  Options o;
  help = false;
  bool have_suite = false, sweep = false, progress_set = false;
  std::vector<std::string> cmd = {"contour", "cosim"};
  for (std::size_t i = 0; i < args.size(); ++i) {
    std::string a = args[i], val;
    bool has_val = false;
    if (const auto eq = a.find('='); a.rfind("--", 0) == 0 && eq != std::string::npos) {
      val = a.substr(eq + 1);
      a = a.substr(0, eq);
      has_val = true;
    }
    auto value = [&]() -> std::string {
      if (has_val) return val;
      if (i + 1 >= args.size()) throw UsageError(a + ": missing value");
      return args[++i];
    };
    if (a == "-h" || a == "--help") {
      help = true;
      return o;
    } else if (a == "--suite") {
      o.suite = value();
      try {
        combined(o.suite);
      } catch (const std::invalid_argument& e) {
        throw UsageError(std::string("--suite: ") + e.what());
      }
      have_suite = true;
      cmd.push_back("--suite " + o.suite);
    } else if (a == "--rate") {
      const std::string v = value();
      for (const auto& r : split(v)) o.rates.push_back(parse_rate(r, "--rate"));
      if (o.rates.empty()) throw UsageError("--rate: empty");
      cmd.push_back("--rate " + v);
    } else if (a == "--sweep") {
      sweep = true;
      cmd.push_back("--sweep");
    } else if (a == "--report") {
      o.report_dir = value();
      if (o.report_dir.empty()) throw UsageError("--report: empty directory name");
      cmd.push_back("--report " + o.report_dir);
    } else if (a == "--trace") {
      o.trace = true;
      cmd.push_back("--trace");
    } else if (a == "--engines") {
      const std::string v = value();
      o.engines.clear();
      for (const auto& e : split(v)) {
        bool known = false;
        for (const auto& n : engine_names()) known |= n == e;
        if (!known) throw UsageError("--engines: unknown engine '" + e + "' (known: model,rtl,iss,8085)");
        o.engines.insert(e);
      }
      if (!o.engines.count("model")) o.engines.insert("model");  // the reference always runs
      cmd.push_back("--engines " + v);
    } else if (a == "--case") {
      const std::string v = value();
      for (const auto& c : split(v)) o.cases.push_back(c);
      cmd.push_back("--case " + v);
    } else if (a == "--inject") {
      const std::string v = value();
      try {
        o.faults.push_back(parse_fault(v));
      } catch (const std::invalid_argument& e) {
        throw UsageError(e.what());
      }
      cmd.push_back("--inject " + v);
    } else if (a == "--free-clock") {
      o.free_clock = true;
      cmd.push_back("--free-clock");
    } else if (a == "--progress" || a == "--no-progress") {
      o.progress = a == "--progress";
      progress_set = true;
    } else if (a == "--step-len") {
      o.timing.len = parse_clocks(value(), "--step-len");
      cmd.push_back("--step-len " + std::to_string(o.timing.len));
    } else if (a == "--step-space") {
      o.timing.space = parse_clocks(value(), "--step-space");
      cmd.push_back("--step-space " + std::to_string(o.timing.space));
    } else {
      throw UsageError("unknown argument '" + args[i] + "' (see contour cosim --help)");
    }
  }
  if (!have_suite) throw UsageError("--suite is required (paper, smoke or full)");
  if (sweep == !o.rates.empty()) throw UsageError("give exactly one of --rate R and --sweep");
  if (!o.cases.empty()) {
    const Suite s = combined(o.suite);
    for (const auto& c : o.cases) {
      bool found = false;
      for (const auto& sc : s.cases) found |= sc.name == c;
      if (!found) throw UsageError("--case: suite " + o.suite + " has no case '" + c + "'");
    }
  }
  if (!progress_set) o.progress = ::isatty(2);
  for (std::size_t i = 0; i < cmd.size(); ++i) o.command_line += (i ? " " : "") + cmd[i];
  return o;
}

}  // namespace contour::cosim
