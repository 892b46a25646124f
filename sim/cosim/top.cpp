#include "top.hpp"

#include <unistd.h>
#include <verilated.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <stdexcept>

#include "options.hpp"
#include "report.hpp"

using sc_core::sc_time;
using sc_core::SC_US;

namespace contour::cosim {

namespace {

struct Slot {
  std::unique_ptr<CosimEngine> engine;
  Recorder rec;
  std::unique_ptr<FaultInjector> fault;
};

// The SystemC module of the engine called `name` (model, core, iss, cpu).
std::unique_ptr<CosimEngine> make_engine(const std::string& name, const Options& opt, const std::string& rom) {
  if (name == "model") return std::make_unique<ModelCosimEngine>("model");
  if (name == "core") return std::make_unique<CoreCosimEngine>("core", opt.core_hz, opt.timing, opt.free_clock);
  if (name == "iss") return std::make_unique<IssCosimEngine>("iss", opt.cpu_hz);
  return std::make_unique<BoardCosimEngine>("board", opt.cpu_hz, rom);
}

class Top : public sc_core::sc_module {
 public:
  SC_HAS_PROCESS(Top);
  Top(sc_core::sc_module_name n, const Options& opt, const std::vector<Case>& cases,
      const std::vector<Expected>& exps, const std::vector<double>& rates, const std::string& rom)
      : sc_core::sc_module(n), opt_(opt), cases_(cases), exps_(exps), rates_(rates) {
    for (const auto& name : engine_names()) {
      if (!opt.engines.count(name)) continue;
      auto s = std::make_unique<Slot>();
      s->engine = make_engine(name, opt, rom);
      s->engine->i_cmd(cmd_);
      Sink* sink = &s->rec;
      for (const auto& f : opt.faults)
        if (f.engine == name) {
          s->fault = std::make_unique<FaultInjector>(f, s->rec);
          sink = s->fault.get();
        }
      s->engine->set_sink(sink);
      slots_.push_back(std::move(s));
    }
    SC_THREAD(control);
  }

  std::vector<std::unique_ptr<Slot>>& slots() { return slots_; }
  std::vector<Row> rows;
  Coverage coverage;

 private:
  void progress(std::size_t done, std::size_t total, const std::string& what) {
    if (!opt_.progress) return;
    const int width = 30;
    const int fill = static_cast<int>(width * done / std::max<std::size_t>(total, 1));
    std::fprintf(stderr, "\r[%s%s] %zu/%zu %-32s", std::string(fill, '#').c_str(),
                 std::string(width - fill, '.').c_str(), done, total, what.c_str());
    if (done == total) std::fprintf(stderr, "\n");
    std::fflush(stderr);
  }

  void control() {
    std::size_t total = 0, done = 0;
    auto runs = [](const Case& c, double r) { return std::find(c.rates.begin(), c.rates.end(), r) != c.rates.end(); };
    for (double r : rates_)
      for (const auto& c : cases_)
        for (const auto& s : slots_)
          if (runs(c, r) && engine_runs_at(s->engine->engine(), r, opt_.core_hz)) ++total;
    for (double rate : rates_) {
      for (std::size_t ci = 0; ci < cases_.size(); ++ci) {
        const Case& c = cases_[ci];
        if (!runs(c, rate)) continue;
        const Expected& exp = exps_[ci];
        std::vector<Slot*> act;
        std::map<Slot*, std::string> errors;
        for (auto& s : slots_) {
          const std::string e = s->engine->engine();
          if (engine_runs_at(e, rate, opt_.core_hz)) act.push_back(s.get());
          else rows.push_back(not_run(c, exp, e, rate, max_rate(e, opt_.core_hz)));
        }
        const auto wall0 = std::chrono::steady_clock::now();
        for (Slot* s : act) {
          if (s->fault) s->fault->reset();
          s->rec.start(sc_core::sc_time_stamp());
          s->engine->events().clear();
          try {
            s->engine->begin_case(c);
          } catch (const std::exception& e) {
            errors[s] = std::string("set-up: ") + e.what();
          }
        }
        const sc_time t0 = sc_core::sc_time_stamp();
        for (Slot* s : act) s->rec.start(t0);
        const sc_time period(1.0 / rate, sc_core::SC_SEC);
        const sc_time width = std::min(period / 2.0, sc_time(1, SC_US));
        std::vector<double> cmd_us;
        for (std::size_t i = 0; i < exp.pulses.size(); ++i) {
          const sc_time at = t0 + period * static_cast<double>(i + 1);
          sc_core::wait(at - sc_core::sc_time_stamp());
          cmd_.write(true);
          cmd_us.push_back((at - t0).to_seconds() * 1e6);
          sc_core::wait(width);
          cmd_.write(false);
        }
        // Let every engine finish what it was given: the slowest is the
        // 8085 routine behind a latched command (under 1 ms).
        sc_core::wait(std::max(sc_time(2000, SC_US), period * 4.0));
        for (Slot* s : act) {
          EngineRun run;
          run.engine = s->engine->engine();
          try {
            s->engine->end_case(run);
          } catch (const std::exception& e) {
            run.error += std::string(run.error.empty() ? "" : "; ") + "read-out: " + e.what();
          }
          if (errors.count(s)) run.error = errors[s] + (run.error.empty() ? "" : "; " + run.error);
          run.out = s->rec.out;
          run.events = s->engine->events();
          run.t0_us = t0.to_seconds() * 1e6;
          rows.push_back(judge(c, exp, rate, cmd_us, run, carry_));
          coverage.add(c, exp, run, rows.back());
          progress(++done, total, c.name + " " + run.engine + " @ " + rate_label(rate) + " pps");
        }
        const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
        for (std::size_t k = rows.size() - act.size(); k < rows.size(); ++k)
          rows[k].wall_seconds = wall / double(act.size());
      }
    }
    sc_core::sc_stop();
  }

  const Options& opt_;
  const std::vector<Case>& cases_;
  const std::vector<Expected>& exps_;
  const std::vector<double>& rates_;
  std::vector<std::unique_ptr<Slot>> slots_;
  sc_core::sc_signal<bool> cmd_{"cmd"};
  // What the core's programmed output stage carries (the keep-up rule).
  const double carry_ =
      core_carry_rate(opt_.core_hz, opt_.timing.len, opt_.timing.space, opt_.timing.setup, opt_.timing.hold);
};

bool g_ran = false;

// `make coverage`'s merged counts: $CONTOUR_RTL_COVERAGE, else
// coverage/merged.dat next to this program (build/).
std::string rtl_coverage_path() {
  if (const char* env = std::getenv("CONTOUR_RTL_COVERAGE"); env && *env) return env;
  std::error_code ec;
  const auto self = std::filesystem::read_symlink("/proc/self/exe", ec);
  return ec ? std::string() : (self.parent_path() / "coverage" / "merged.dat").string();
}

// Every rate within 1 .. kMaxRate, and none above what a chosen engine's
// input can carry (the core's pin); the 8085 engines' rows say NOT RUN.
void check_rates(const std::vector<double>& rates, const Options& opt) {
  for (double r : rates) {
    if (!(r >= 1 && r <= kMaxRate))
      throw UsageError("--rate " + rate_label(r) + " pps is outside 1 .. " + rate_label(kMaxRate));
    if (opt.engines.count("core") && r > max_rate("core", opt.core_hz))
      throw UsageError("--rate " + rate_label(r) + " pps: the core's command pin is sampled at " +
                       rate_label(opt.core_hz / 1e6) + " MHz, so it carries at most " +
                       rate_label(max_rate("core", opt.core_hz)) + " pps (leave out the core with --engines)");
  }
}

// The report directory, made if missing; a file in its place, or one that
// cannot be made, is bad input (UsageError).
void make_report_dir(const std::string& dir) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (fs::exists(dir, ec) && !fs::is_directory(dir, ec))
    throw UsageError("--report '" + dir + "' is a file, not a directory");
  fs::create_directories(dir, ec);
  if (ec) throw UsageError("--report '" + dir + "': cannot make the directory (" + ec.message() + ")");
}

}  // namespace

CosimOutcome run_cosim(const Options& opt) {
  if (g_ran) throw std::logic_error("run_cosim: one SystemC elaboration per process");
  g_ran = true;
  const auto wall0 = std::chrono::steady_clock::now();
  const Suite s = combined(opt.suite);
  std::vector<Case> cases;
  for (const auto& c : s.cases)
    if (opt.cases.empty() || std::find(opt.cases.begin(), opt.cases.end(), c.name) != opt.cases.end())
      cases.push_back(c);
  for (const auto& want : opt.cases) {
    bool found = false;
    for (const auto& c : s.cases) found |= c.name == want;
    if (!found) throw std::invalid_argument("suite " + s.name + " has no case '" + want + "'");
  }
  std::vector<Expected> exps;
  for (const auto& c : cases) exps.push_back(expect(c));
  // --rate: every case at those rates; --sweep: each case at its suite's.
  const std::vector<double> rates = opt.rates.empty() ? s.rates : opt.rates;
  if (!opt.rates.empty())
    for (auto& c : cases) c.rates = opt.rates;
  check_rates(rates, opt);

  const std::string dir = opt.report_dir.empty() ? "." : opt.report_dir;
  if (!opt.report_dir.empty() || opt.trace) make_report_dir(dir);
  const std::string rom = (std::filesystem::temp_directory_path() /
                           ("contour-cosim-rom-" + std::to_string(::getpid()) + ".memh")).string();
  if (opt.engines.count("cpu")) write_rom_memh(rom);
  if (opt.trace) Verilated::traceEverOn(true);
  // sc_stop ends every run: not news.
  sc_core::sc_report_handler::set_actions("/OSCI/SystemC", sc_core::SC_INFO, sc_core::SC_DO_NOTHING);

  CosimOutcome out;
  {
    Top top("top", opt, cases, exps, rates, rom);
    sc_core::sc_start(sc_core::SC_ZERO_TIME);
    if (opt.trace)
      for (auto& sl : top.slots()) {
        const std::string name = sl->engine->engine();
        if (name == "core" || name == "cpu") {
          const std::string path = dir + "/" + (name == "core" ? "core" : "board8085") + ".fst";
          sl->engine->open_trace(path);
          out.files.push_back(path);
        }
      }
    sc_core::sc_start();
    for (auto& sl : top.slots()) {
      sl->engine->close_trace();
      if (auto* core = dynamic_cast<CoreCosimEngine*>(sl->engine.get())) out.core_clocks = core->clocks();
    }
    out.sim_seconds = sc_core::sc_time_stamp().to_seconds();
    out.rows = std::move(top.rows);
    out.coverage = std::move(top.coverage);
  }
  if (opt.engines.count("cpu")) std::filesystem::remove(rom);
  for (const auto& r : out.rows) {
    if (r.acceptable()) ++out.passed;
    else if (r.ran()) ++out.failed;
    else ++out.not_run;
  }
  out.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  if (!opt.report_dir.empty()) {
    ReportInput in{s.name, cases, exps, rates, out.rows, opt.command_line, out.sim_seconds, out.wall_seconds, opt};
    in.traces = out.files;  // only the traces so far
    in.coverage = &out.coverage;
    in.rtl_coverage = read_rtl_coverage(rtl_coverage_path());
    for (const auto& f : write_reports(opt.report_dir, in)) out.files.push_back(f);
  }
  return out;
}

}  // namespace contour::cosim
