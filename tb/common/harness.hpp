// The one base of every Verilator harness of the project (in the spirit of
// ZipCPU's TESTB and Verilator's own examples): it owns the context and the
// model, clocks `i_clk`, holds `i_rst`, and writes an FST waveform only
// when asked for, closing it before a failing check so that the waveform
// ends at the bug.
//
// A waveform is asked for by a file name given to the constructor, or by
// the environment variable CONTOUR_FST=FILE (every harness; with several
// harnesses in one run, the last one's waveform is what the file holds).
// One clock is two trace samples, so the FST's time is half-clocks.
//
// Coverage (models Verilated with --coverage-line/--coverage-toggle, where
// Verilator defines VM_COVERAGE): with CONTOUR_COVERAGE=FILE each harness
// writes its context's counts at destruction to FILE.N (N = 0, 1, ... in
// the order the harnesses end; one process: `make coverage` merges them
// with verilator_coverage). Without VM_COVERAGE the variable is ignored.
//
// A harness that serves a bus between the two edges (the 8085 machines)
// calls clock_low() and clock_high() itself; others call tick(). A
// derived harness that samples outputs every clock overrides after_clock().
#pragma once

#include <verilated.h>
#include <verilated_fst_c.h>

#include <stdexcept>
#if VM_COVERAGE
#include <verilated_cov.h>

#include <atomic>
#endif

#include <cstdint>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

namespace contour::tb {

// The waveform file asked for: `path` if not empty, else $CONTOUR_FST.
inline std::string fst_request(std::string path) {
  if (path.empty()) {
    if (const char* env = std::getenv("CONTOUR_FST"); env != nullptr) path = env;
  }
  return path;
}

#if VM_COVERAGE
// The next coverage file of this process: $CONTOUR_COVERAGE.N, or "" if the
// variable is unset.
inline std::string coverage_request() {
  static std::atomic<unsigned> next{0};
  const char* env = std::getenv("CONTOUR_COVERAGE");
  if (env == nullptr || *env == '\0') return {};
  return std::string(env) + "." + std::to_string(next++);
}
#endif

template <class V>
class Harness {
 public:
  // `instance` names the model's scope in the waveform; `plusargs` are what
  // the model's $value$plusargs sees (none from the process's command line).
  explicit Harness(std::string fst_path = "", const char* instance = "TOP",
                   const std::vector<std::string>& plusargs = {})
      : ctx_(std::make_unique<VerilatedContext>()) {
    std::vector<const char*> argv = {"contour-tb"};
    for (const std::string& a : plusargs) argv.push_back(a.c_str());
    ctx_->commandArgs(static_cast<int>(argv.size()), argv.data());
    fst_path = fst_request(std::move(fst_path));
    if (!fst_path.empty()) ctx_->traceEverOn(true);
    top_ = std::make_unique<V>(ctx_.get(), instance);
    if (!fst_path.empty()) {
      trace_ = std::make_unique<VerilatedFstC>();
      top_->trace(trace_.get(), 99);
      trace_->open(fst_path.c_str());
      // A waveform asked for and not written is bad input, not silence.
      if (!trace_->isOpen()) throw std::runtime_error("cannot write the waveform file '" + fst_path + "' (CONTOUR_FST or --trace)");
    }
    top_->i_clk = 0;
    top_->eval();
  }

  virtual ~Harness() {
    close_trace();
    top_->final();
#if VM_COVERAGE
    if (const std::string cov = coverage_request(); !cov.empty()) {
      ctx_->coveragep()->write(cov.c_str());
    }
#endif
  }
  Harness(const Harness&) = delete;
  Harness& operator=(const Harness&) = delete;

  V& top() { return *top_; }
  const V& top() const { return *top_; }
  // Rising edges since construction.
  std::uint64_t clocks() const { return clocks_; }

  // The clock low: combinational outputs settle for the coming edge.
  void clock_low() {
    top_->i_clk = 0;
    top_->eval();
    dump();
  }
  // The rising edge: the inputs set by the caller are sampled.
  void clock_high() {
    top_->i_clk = 1;
    top_->eval();
    dump();
    ++clocks_;
    after_clock();
  }
  void tick() {
    clock_low();
    clock_high();
  }

  // `i_rst` high for `n` clocks (synchronous, active high), then low.
  void hold_reset(unsigned n = 1) {
    top_->i_rst = 1;
    for (unsigned i = 0; i < n; ++i) tick();
    top_->i_rst = 0;
  }

  // Ends the waveform here (a checker calls it at the first mismatch).
  void close_trace() {
    if (trace_) {
      dump();
      trace_->close();
      trace_.reset();
    }
  }

 protected:
  // Called after every rising edge, e.g. to sample step outputs.
  virtual void after_clock() {}

 private:
  void dump() {
    if (trace_) trace_->dump(static_cast<std::uint64_t>(ctx_->time()));
    ctx_->timeInc(1);
  }

  std::unique_ptr<VerilatedContext> ctx_;
  std::unique_ptr<V> top_;
  std::unique_ptr<VerilatedFstC> trace_;
  std::uint64_t clocks_ = 0;
};

}  // namespace contour::tb
