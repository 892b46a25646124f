#include "options.hpp"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sstream>

#include "sim/cli/numbers.hpp"

namespace contour::cosim {

namespace {

// "a,b,c" -> {a, b, c}; an empty list or an empty item ("", "a,", "a,,b")
// is an error naming `what`.
std::vector<std::string> split(const std::string& s, const std::string& what) {
  if (s.empty()) throw UsageError(what + ": empty list");
  std::vector<std::string> out;
  std::size_t start = 0;
  while (true) {
    const auto comma = s.find(',', start);
    out.push_back(s.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
    if (out.back().empty()) throw UsageError(what + " '" + s + "': an empty item in the list");
    if (comma == std::string::npos) return out;
    start = comma + 1;
  }
}

// Clocks of the core (1..4095: the 12-bit timing registers of
// docs/regmap.md), or a duration with its unit ("2us",
// "1500ns") that must be a whole number of clocks at `core_hz`.
std::uint32_t parse_clocks(const std::string& text, const std::string& what, double core_hz) {
  std::int64_t v = 0;
  if (const auto ns = cli::read_duration_ns(text)) {
    const double clocks = *ns * core_hz / 1e9;
    if (std::fabs(clocks - std::round(clocks)) > 1e-6) {
      char clk[32];
      std::snprintf(clk, sizeof clk, "%g ns", 1e9 / core_hz);
      throw UsageError(what + " '" + text + "' is not a whole number of core clocks (" + clk + ")");
    }
    v = static_cast<std::int64_t>(std::llround(clocks));
  } else if (cli::read_int(text, v) != cli::IntRead::Ok) {
    v = -1;
  }
  if (v < 1 || v > 4095)
    throw UsageError(what + " '" + text + "': expected clocks 1..4095 or a duration (2us, 1500ns) of 1..4095 clocks");
  return static_cast<std::uint32_t>(v);
}

}  // namespace

double parse_rate(const std::string& text, const std::string& what) {
  if (text.empty()) throw UsageError(what + ": empty rate");
  const auto v = cli::read_real(text);  // the CLI's number rules (sim/cli/numbers.hpp)
  if (!v) throw UsageError(what + " '" + text + "' is not a rate (examples: 4000, 3.5k, 250k, 1M; decimal only)");
  const double r = *v;
  if (r < 1 || r > kMaxRate) throw UsageError(what + " '" + text + "' is outside 1 .. 50M pulses/s");
  return r;
}

std::string usage() {
  return "usage: contour cosim --suite paper|smoke|full|long[,...] (--rate R[,R...] | --sweep) [--report DIR] [--trace]\n"
         "         [--engines model,core,iss,cpu] [--case NAME[,NAME...]] [--progress|--no-progress]\n"
         "         [--free-clock] [--step-len N|T] [--step-space N|T] [--inject ENGINE:drop|swap|flip:N]\n"
         "  --step-len, --step-space: N core clocks, or a duration T with its unit (2us, 1500ns)\n"
         "  Co-simulates the golden model, the Verilog core (core), the 8085 program on the ISS (iss)\n"
         "  and on the Verilog 8085 board (cpu) on the same command pulse train; exit 0 only when\n"
         "  every required equivalence holds (docs/cosim.md).\n"
         "  Command rates: 1 .. 50M pps; the core takes up to 25M (its command pin is sampled at\n"
         "  50 MHz: a higher --rate with the core is refused); the 8085 engines run up to 250k,\n"
         "  above it their rows say NOT RUN. The core must lose nothing up to 250k pps or the rate\n"
         "  its output stage carries, 50M / (step-len + step-space + 20) pps, whichever is lower.\n" +
         std::string(cli::kNumberRules);
}

namespace {

// One parse of the arguments: the options so far, the argument at hand,
// and the command line to show in the report (the arguments as understood).
struct Parse {
  explicit Parse(const std::vector<std::string>& a) : args(a) {}
  const std::vector<std::string>& args;
  std::size_t i = 0;
  std::string name, inline_value;  // --name=value: the value is inline
  bool has_inline = false;
  Options o;
  bool have_suite = false, sweep = false, progress_set = false;
  std::vector<std::string> cmd = {"contour", "cosim"};

  // Splits args[i] into its name and inline value.
  void read_name() {
    name = args[i];
    inline_value.clear();
    has_inline = false;
    if (const auto eq = name.find('='); name.rfind("--", 0) == 0 && eq != std::string::npos) {
      inline_value = name.substr(eq + 1);
      name = name.substr(0, eq);
      has_inline = true;
    }
  }
  // The argument's value: inline, or the next argument.
  std::string value() {
    if (has_inline) return inline_value;
    if (i + 1 >= args.size()) throw UsageError(name + ": missing value");
    return args[++i];
  }
};

void parse_suite(Parse& p) {
  p.o.suite = p.value();
  try {
    combined(p.o.suite);
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--suite: ") + e.what());
  }
  p.have_suite = true;
  p.cmd.push_back("--suite " + p.o.suite);
}

void parse_rates(Parse& p) {
  const std::string v = p.value();
  for (const auto& r : split(v, "--rate")) p.o.rates.push_back(parse_rate(r, "--rate"));
  p.cmd.push_back("--rate " + v);
}

void parse_report_dir(Parse& p) {
  p.o.report_dir = p.value();
  if (p.o.report_dir.empty()) throw UsageError("--report: empty directory name");
  std::error_code ec;
  if (std::filesystem::exists(p.o.report_dir, ec) && !std::filesystem::is_directory(p.o.report_dir, ec))
    throw UsageError("--report '" + p.o.report_dir + "' is a file, not a directory");
  p.cmd.push_back("--report " + p.o.report_dir);
}

void parse_engines(Parse& p) {
  const std::string v = p.value();
  p.o.engines.clear();
  for (const auto& e : split(v, "--engines")) {
    bool known = false;
    for (const auto& n : engine_names()) known |= n == e;
    if (!known)
      throw UsageError("--engines: unknown engine '" + e + "' (known: model,core,iss,cpu)" +
                       (e == "rtl" || e == "8085" ? "; the Verilog core is now 'core', the Verilog 8085 'cpu'" : ""));
    p.o.engines.insert(e);
  }
  if (!p.o.engines.count("model")) p.o.engines.insert("model");  // the reference always runs
  p.cmd.push_back("--engines " + v);
}

void parse_cases(Parse& p) {
  const std::string v = p.value();
  for (const auto& c : split(v, "--case")) p.o.cases.push_back(c);
  p.cmd.push_back("--case " + v);
}

void parse_injection(Parse& p) {
  const std::string v = p.value();
  try {
    p.o.faults.push_back(parse_fault(v));
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  p.cmd.push_back("--inject " + v);
}

// A flag without a value: sets `on` and shows in the command line.
void parse_flag(Parse& p, bool& on) {
  on = true;
  p.cmd.push_back(p.name);
}

// --progress or --no-progress (neither: a bar when stderr is a terminal).
void parse_progress(Parse& p) {
  p.o.progress = p.name == "--progress";
  p.progress_set = true;
}

void parse_step_clocks(Parse& p, std::uint32_t& clocks) {
  clocks = parse_clocks(p.value(), p.name, p.o.core_hz);
  p.cmd.push_back(p.name + " " + std::to_string(clocks));
}

// Parses args[p.i] (and its value); false for -h/--help.
bool parse_argument(Parse& p) {
  const std::string& a = p.name;
  if (a == "-h" || a == "--help") return false;
  if (a == "--suite") parse_suite(p);
  else if (a == "--rate") parse_rates(p);
  else if (a == "--sweep") parse_flag(p, p.sweep);
  else if (a == "--report") parse_report_dir(p);
  else if (a == "--trace") parse_flag(p, p.o.trace);
  else if (a == "--engines") parse_engines(p);
  else if (a == "--case") parse_cases(p);
  else if (a == "--inject") parse_injection(p);
  else if (a == "--free-clock") parse_flag(p, p.o.free_clock);
  else if (a == "--progress" || a == "--no-progress") parse_progress(p);
  else if (a == "--step-len") parse_step_clocks(p, p.o.timing.len);
  else if (a == "--step-space") parse_step_clocks(p, p.o.timing.space);
  else throw UsageError("unknown argument '" + p.args[p.i] + "' (see contour cosim --help)");
  return true;
}

// What no single argument can check: a suite, exactly one of --rate and
// --sweep, and cases the suite has.
void check_complete(const Parse& p) {
  if (!p.have_suite) throw UsageError("--suite is required (paper, smoke or full)");
  if (p.sweep == !p.o.rates.empty()) throw UsageError("give exactly one of --rate R and --sweep");
  if (p.o.cases.empty()) return;
  const Suite s = combined(p.o.suite);
  for (const auto& c : p.o.cases) {
    bool found = false;
    for (const auto& sc : s.cases) found |= sc.name == c;
    if (!found) throw UsageError("--case: suite " + p.o.suite + " has no case '" + c + "'");
  }
}

}  // namespace

Options parse_options(const std::vector<std::string>& args, bool& help) {
  Parse p(args);
  help = false;
  for (; p.i < args.size(); ++p.i) {
    p.read_name();
    if (!parse_argument(p)) {
      help = true;
      return p.o;
    }
  }
  check_complete(p);
  if (!p.progress_set) p.o.progress = ::isatty(2);
  for (std::size_t i = 0; i < p.cmd.size(); ++i) p.o.command_line += (i ? " " : "") + p.cmd[i];
  return p.o;
}

}  // namespace contour::cosim
