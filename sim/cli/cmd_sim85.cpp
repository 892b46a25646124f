// `contour sim85 FILE`: runs an 8085/8080 program (Intel HEX or raw binary)
// on a machine from the i8085 registry (the ISS by default) and prints its
// port writes and T-states; `--cpm` runs a CP/M .COM-style diagnostic.
// docs/i8085.md describes the conventions.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <streambuf>
#include <iterator>
#include <string>
#include <vector>

#include "args.hpp"
#include "i8085/machine.hpp"
#include "i8085/system.hpp"
#include "numbers.hpp"
#include "progress.hpp"
#include "registry.hpp"

namespace contour::cli {
namespace {

constexpr const char* kUsage =
    "usage: contour sim85 FILE [--cpm] [--cpu 8080|8085] [--trace FILE] [--max-tstates N]\n"
    "                     [--engine %s] [--progress|--no-progress]\n"
    "Runs an 8085 program: FILE is Intel HEX (starts with ':') or a raw binary.\n"
    "  default  load (raw binaries at 0x0000), reset, run until HLT; prints each\n"
    "           OUT as `OUT <port> <value> T=<T-states before the OUT>`\n"
    "  --cpm    CP/M .COM diagnostic: loaded at 0x0100 (HEX must not go below),\n"
    "           OUT 0 at 0x0000 ends the run, BDOS at 0x0005 serves C=2 and C=9;\n"
    "           prints what the program prints\n"
    "  last line: `T-states: N` (every instruction, the final HLT / OUT 0 included)\n"
    "  --cpu          8085 (default) or 8080: T-states and flags of that CPU\n"
    "  --trace FILE   one line per instruction (format: docs/i8085.md)\n"
    "  --max-tstates  the run may use at most N T-states, else exit 1; default 2000000000\n"
    "                 (11 min of a 3 MHz 8085, a few seconds on the ISS); 0: no limit\n"
    "  --engine       machine that runs it (default iss)\n"
    "  --progress, --no-progress  T-states so far on stderr (default: when stderr is a terminal)\n"
    "  output is written as the program runs (OUT lines, console, trace)\n"
    "exit status: 0 finished, 1 run error (limit, undocumented opcode, BDOS), 2 bad input\n";

// The default T-state limit: a program that never halts (a text file run
// as a binary, a missing HLT) ends with exit 1 instead of running forever.
constexpr std::uint64_t kDefaultMaxTstates = 2'000'000'000ULL;

std::vector<std::uint8_t> read_file(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw UsageError("'" + path + "' is a directory, not a program file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw UsageError("cannot open '" + path + "'");
  std::vector<std::uint8_t> data{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  if (in.bad()) throw UsageError("cannot read '" + path + "'");
  return data;
}

// Forwards every call to the machine it wraps and reports the T-states
// after each step, for the progress line. With `drop_outs` (a CP/M run,
// whose port writes are not printed) the bus's log of port writes is
// emptied before each step, so that it does not grow with the run.
class WatchedMachine final : public i8085::Machine {
 public:
  WatchedMachine(i8085::Machine& m, Progress& p, std::uint64_t limit, i8085::RamBus* drop_outs)
      : m_(m), p_(p), limit_(limit), drop_outs_(drop_outs) {}
  i8085::Mode mode() const override { return m_.mode(); }
  void reset() override { m_.reset(); }
  int step() override {
    if (drop_outs_) drop_outs_->outs.clear();
    const int t = m_.step();
    p_.update(m_.tstates(), limit_);
    return t;
  }
  std::uint64_t tstates() const override { return m_.tstates(); }
  i8085::Regs regs() const override { return m_.regs(); }
  void set_regs(const i8085::Regs& r) override { m_.set_regs(r); }
  bool halted() const override { return m_.halted(); }
  bool ie() const override { return m_.ie(); }
  const i8085::Step& last() const override { return m_.last(); }
  void set_trap(bool v) override { m_.set_trap(v); }
  void set_rst75(bool v) override { m_.set_rst75(v); }
  void set_rst65(bool v) override { m_.set_rst65(v); }
  void set_rst55(bool v) override { m_.set_rst55(v); }
  void set_intr(bool v) override { m_.set_intr(v); }

 private:
  i8085::Machine& m_;
  Progress& p_;
  std::uint64_t limit_;
  i8085::RamBus* drop_outs_;
};

// A bare run (i8085::run_bare's loop) that prints each OUT as it happens and
// keeps none, so that memory does not grow with the run.
i8085::RunResult run_bare_streaming(i8085::Machine& m, i8085::RamBus& bus, const i8085::RunOptions& opt) {
  i8085::RunResult res;
  const std::uint64_t t0 = m.tstates();
  while (!m.halted()) {
    i8085::run_step(m, bus, opt, res);
    for (const auto& w : bus.outs)
      std::printf("OUT %02X %02X T=%llu\n", w.port, w.value, static_cast<unsigned long long>(w.t));
    bus.outs.clear();
  }
  res.tstates = m.tstates() - t0;
  return res;
}

// Forwards to stdout and remembers the last character, so that `T-states:`
// always starts a line of its own.
class ConsoleBuf : public std::streambuf {
 public:
  bool at_line_start() const { return last_ == '\n'; }

 protected:
  int_type overflow(int_type ch) override {
    if (ch == traits_type::eof()) return traits_type::not_eof(ch);
    last_ = static_cast<char>(ch);
    return std::fputc(ch, stdout) == EOF ? traits_type::eof() : ch;
  }
  int sync() override { return std::fflush(stdout) == 0 ? 0 : -1; }

 private:
  char last_ = '\n';
};

i8085::Mode parse_cpu(const Args& args) {
  const std::string cpu = args.option_or("cpu", "8085");
  if (cpu == "8085") return i8085::Mode::i8085;
  if (cpu == "8080") return i8085::Mode::i8080;
  throw UsageError("--cpu: '" + cpu + "' is not 8080 or 8085");
}

// --max-tstates N (0: no limit), else the default limit.
std::uint64_t parse_max_tstates(const Args& args) {
  const auto m = args.option("max-tstates");
  if (!m) return kDefaultMaxTstates;
  const std::int64_t n = parse_int(*m, "--max-tstates");
  if (n < 0) throw UsageError("--max-tstates: '" + *m + "' must be 0 (no limit) or positive");
  return static_cast<std::uint64_t>(n);
}

int cmd_sim85(const std::vector<std::string>& argv) {
  const Args args(argv, {"cpm", "progress", "no-progress"}, {"cpu", "trace", "max-tstates", "engine"});
  if (args.help()) {
    std::printf(kUsage, i8085::machine_names().c_str());
    return 0;
  }
  args.expect_positional({"FILE"});
  const std::string path = args.positional()[0];

  const i8085::Mode mode = parse_cpu(args);

  const std::string engine = args.option_or("engine", "iss");
  auto it = i8085::machines().find(engine);
  if (it == i8085::machines().end())
    throw UsageError(unknown_engine(engine, i8085::machine_names()));

  i8085::RunOptions opt;
  opt.max_tstates = parse_max_tstates(args);
  const ProgressMode show_progress = progress_wanted(args);
  std::ofstream trace;
  if (auto t = args.option("trace")) {
    trace.open(*t);
    if (!trace) throw UsageError("--trace: cannot write '" + *t + "'");
    opt.trace = &trace;
  }

  const bool cpm = args.flag("cpm");
  i8085::RamBus bus;
  const std::vector<std::uint8_t> file = read_file(path);
  std::uint16_t lowest;
  try {
    lowest = i8085::load_program(bus, file, path, cpm ? 0x0100 : 0x0000);
  } catch (const std::exception& e) {
    throw UsageError(e.what());
  }
  if (cpm && lowest < 0x0100) {
    char buf[8];
    std::snprintf(buf, sizeof buf, "%04X", lowest);
    throw UsageError(path + ": --cpm programs start at 0100, this one loads at " + buf);
  }

  std::unique_ptr<i8085::Machine> machine = it->second.make(bus, mode);
  Progress progress(show_progress, "sim85 " + path, "T-states");
  WatchedMachine watched(*machine, progress, opt.max_tstates, cpm ? &bus : nullptr);
  i8085::RunResult res;
  ConsoleBuf console_buf;
  std::ostream console(&console_buf);
  try {
    if (cpm) {
      res = i8085::run_cpm(watched, bus, console, opt);
    } else {
      watched.reset();
      res = run_bare_streaming(watched, bus, opt);
    }
  } catch (const i8085::RunError& e) {
    progress.finish();
    console.flush();
    if (!console_buf.at_line_start()) std::fputc('\n', stdout);
    std::fflush(stdout);
    std::fprintf(stderr, "contour sim85: %s: %s\n", path.c_str(), e.what());
    return 1;
  }
  progress.finish();
  if (cpm) {
    console.flush();
    if (!console_buf.at_line_start()) std::fputc('\n', stdout);
  }
  std::printf("T-states: %llu\n", static_cast<unsigned long long>(res.tstates));
  return 0;
}

const CommandRegistrar kSim85{{"sim85", "run an 8085/8080 program (HEX or binary, --cpm) on the ISS", cmd_sim85}};

}  // namespace
}  // namespace contour::cli
