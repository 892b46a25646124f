// The co-simulation's engines as SystemC modules. Each takes the command
// pulse train on `i_cmd` and hands every output pulse, time-stamped in
// SystemC time, to a Sink. The controller (top.cpp) calls begin_case()
// before a train and end_case() after it, from its own thread; both may
// wait() (bus accesses, reset).
//
//   model   ModelCosimEngine: the golden model (model/interp) in an
//           SC_MODULE, one step per rising edge
//   core    CoreCosimEngine: interp_top (rtl/interp) Verilated for SystemC,
//           50 MHz, command on its pin, moves pushed over Wishbone, step/dir
//           pins observed
//   iss     IssCosimEngine: the 8085 program (sw8085/interp) on the C++ ISS,
//           T-state timed at 3 MHz, command on RST 7.5 (sw8085::Host does the
//           board)
//   cpu     BoardCosimEngine: board8085 (rtl/board8085 + rtl/cpu8085)
//           Verilated for SystemC, 3 MHz, command on RST 7.5 (synchronised),
//           moves written through the mailbox port, step pins observed
#pragma once

#include <systemc>

#include <array>
#include <map>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "cases.hpp"
#include "scoreboard.hpp"
#include "sw8085/interp/mailbox.hpp"

class Vcosim_interp;
class Vcosim_board;
class VerilatedFstSc;

namespace contour::sw8085 {
class Host;
}  // namespace contour::sw8085

namespace contour::cosim {

// Receives an engine's output pulses.
class Sink {
 public:
  virtual ~Sink() = default;
  virtual void pulse(const Pulse& p, const std::string& state) = 0;
};

// Records pulses with their time since the case started.
class Recorder final : public Sink {
 public:
  void start(sc_core::sc_time t0) {
    t0_ = t0;
    out.clear();
  }
  void pulse(const Pulse& p, const std::string& state) override {
    out.push_back({(sc_core::sc_time_stamp() - t0_).to_seconds() * 1e6, p, state});
  }
  std::vector<OutPulse> out;

 private:
  sc_core::sc_time t0_;
};

// Test-only hook: corrupts an engine's output stream on its way to the
// scoreboard, to prove the scoreboard catches it. The pulse numbers are
// 1-based, counted per case.
struct Fault {
  enum class Kind { Drop, Swap, Flip };
  std::string engine;
  Kind kind = Kind::Drop;
  std::uint64_t at = 1;  // Drop: pulse `at` vanishes; Swap: `at` and `at+1`; Flip: sign of `at`
};
// "ENGINE:drop:N", "ENGINE:swap:N", "ENGINE:flip:N". Throws std::invalid_argument.
Fault parse_fault(const std::string& text);
// The same text back ("core:swap:3").
std::string to_string(const Fault& f);

class FaultInjector final : public Sink {
 public:
  FaultInjector(Fault f, Sink& next) : fault_(std::move(f)), next_(next) {}
  void reset() {
    n_ = 0;
    held_.reset();
  }
  void pulse(const Pulse& p, const std::string& state) override;

 private:
  Fault fault_;
  Sink& next_;
  std::uint64_t n_ = 0;
  std::optional<std::pair<Pulse, std::string>> held_;
};

class CosimEngine : public sc_core::sc_module {
 public:
  sc_core::sc_in<bool> i_cmd;
  explicit CosimEngine(sc_core::sc_module_name n) : sc_core::sc_module(n), i_cmd("i_cmd") {}
  virtual std::string engine() const = 0;
  virtual void begin_case(const Case& c) = 0;
  // Stops the engine's host activity and fills the run's counters and
  // position (the pulses are in the Recorder).
  virtual void end_case(EngineRun& run) = 0;
  virtual void open_trace(const std::string&) {}
  virtual void close_trace() {}
  void set_sink(Sink* s) { sink_ = s; }
  // Functional-coverage counters of the case (EngineRun::events); the
  // controller clears them before begin_case and copies them after end_case.
  std::map<std::string, std::uint64_t>& events() { return events_; }

 protected:
  std::map<std::string, std::uint64_t> events_;
  void emit(const Pulse& p, const std::string& state = "") {
    if (sink_) sink_->pulse(p, state);
  }
  Sink* sink_ = nullptr;
};

// --- model -----------------------------------------------------------------

class ModelCosimEngine final : public CosimEngine {
 public:
  SC_HAS_PROCESS(ModelCosimEngine);
  explicit ModelCosimEngine(sc_core::sc_module_name n);
  std::string engine() const override { return "model"; }
  void begin_case(const Case& c) override;
  void end_case(EngineRun& run) override;

 private:
  void on_cmd();
  bool start_next();
  std::vector<Placed> moves_;
  std::size_t next_ = 0;
  std::optional<Linear<24>> lin_;
  std::optional<Circular<24>> circ_;
  const Placed* cur_ = nullptr;
  bool active_ = false;
};

// --- the Verilated engines: step pins observed, an FST trace ------------------

// What the two Verilated engines (core, cpu) share: their step/dir pins,
// watched for rising step edges, and an FST trace of the Verilated model.
class VerilatedCosimEngine : public CosimEngine {
 public:
  SC_HAS_PROCESS(VerilatedCosimEngine);
  explicit VerilatedCosimEngine(sc_core::sc_module_name n);
  ~VerilatedCosimEngine() override;
  void open_trace(const std::string& path) override;
  void close_trace() override;

 protected:
  // Emits a pulse on each rising edge of a step pin (call from the constructor).
  void watch_step_pins();
  // Adds the Verilated model to `fst`.
  virtual void trace_model(VerilatedFstSc& fst) = 0;
  sc_core::sc_signal<bool> step_x_{"step_x"}, dir_x_{"dir_x"}, step_y_{"step_y"}, dir_y_{"dir_y"};

 private:
  void on_step();
  std::unique_ptr<VerilatedFstSc> trace_;
  bool last_x_ = false, last_y_ = false;
};

// --- core: interp_top ---------------------------------------------------------

// Output stage timing of interp_top, in core clocks (STEP_LEN etc.).
struct StepTiming {
  std::uint32_t len = 50, space = 50, setup = 10, hold = 10;  // 1 us / 1 us / 200 ns / 200 ns at 50 MHz
};

class CoreCosimEngine final : public VerilatedCosimEngine {
 public:
  SC_HAS_PROCESS(CoreCosimEngine);
  CoreCosimEngine(sc_core::sc_module_name n, double f_clk_hz, StepTiming timing, bool free_clock);
  ~CoreCosimEngine() override;
  std::string engine() const override { return "core"; }
  void begin_case(const Case& c) override;
  void end_case(EngineRun& run) override;
  std::uint64_t clocks() const { return clocks_; }

 private:
  void trace_model(VerilatedFstSc& fst) override;
  void clock_thread();
  void on_cmd();
  void keep_awake(std::uint64_t cycles);
  void exercise_abort();
  bool push_move(const Placed& p, bool probe_reject);
  void feeder_thread();
  void wb_write(std::uint32_t adr, std::uint32_t v);
  std::uint32_t wb_read(std::uint32_t adr);
  void wb_cycle(bool we, std::uint32_t adr, std::uint32_t v, std::uint32_t* out);

  sc_core::sc_time period_;
  StepTiming timing_;
  bool free_clock_;
  std::uint64_t awake_cycles_;
  sc_core::sc_time run_until_;
  sc_core::sc_event wake_;
  std::uint64_t clocks_ = 0;
  sc_core::sc_signal<bool> clk_{"clk"}, rst_{"rst"}, ack_{"ack"};
  // The bus is driven by the controller (begin_case, end_case) and by
  // feeder_thread, never at once (end_case waits for the feeder to stop).
  sc_core::sc_signal<bool, sc_core::SC_MANY_WRITERS> cyc_{"cyc"}, stb_{"stb"}, we_{"we"};
  sc_core::sc_signal<std::uint32_t, sc_core::SC_MANY_WRITERS> adr_{"adr"}, wdat_{"wdat"};
  sc_core::sc_signal<std::uint32_t> rdat_{"rdat"};
  sc_core::sc_signal<bool> pulse_{"pulse"}, pulse_y_{"pulse_y"}, pulse_neg_{"pulse_neg"}, busy_{"busy"};
  sc_core::sc_signal<bool> one_{"one", true};  // i_cmd_ce: no time scale here
  std::unique_ptr<Vcosim_interp> top_;
  std::vector<Placed> moves_;
  // Moves that did not fit the queue at begin_case: pushed by feeder_thread
  // as room appears, until end_case.
  std::size_t next_push_ = 0, waited_for_ = 0;
  bool feeding_ = false, feeder_busy_ = false;
  sc_core::sc_event feed_ev_, feeder_idle_;
  std::string error_;
};

// What the host of the 8085 engines wrote into the program's two mailbox
// slots: every write in order (a move, or one segment of a line of more
// than 65536 P steps or of an arc), the move each belongs to, and the write each slot
// holds now.
struct SlotLog {
  std::vector<sw8085::SlotMove> writes;
  std::vector<std::size_t> move_of;  // index into the case's moves, per write
  std::array<int, 2> in_slot{-1, -1};  // index into writes, per slot; -1: never written
  int next_slot = 0;                   // the slot the next write goes to
  void clear() { *this = SlotLog{}; }
  void push(const sw8085::SlotMove& sm, std::size_t move) {
    writes.push_back(sm);
    move_of.push_back(move);
    in_slot[next_slot] = static_cast<int>(writes.size() - 1);
    next_slot ^= 1;
  }
};

// --- iss: the program on the C++ ISS ----------------------------------------

class IssCosimEngine final : public CosimEngine {
 public:
  SC_HAS_PROCESS(IssCosimEngine);
  IssCosimEngine(sc_core::sc_module_name n, double f_clk_hz);
  ~IssCosimEngine() override;
  std::string engine() const override { return "iss"; }
  void begin_case(const Case& c) override;
  void end_case(EngineRun& run) override;

 private:
  void cpu_thread();
  void on_cmd();
  void feed();
  void collect();
  std::span<const std::uint8_t, 256> mailbox() const;
  sc_core::sc_time period_;
  std::unique_ptr<sw8085::Host> host_;
  std::vector<Placed> moves_;
  std::size_t next_move_ = 0;
  SlotLog slots_;
  std::uint64_t pulses_ = 0;
  std::vector<std::uint64_t> per_move_;  // output pulses of each move (all its segments)
  std::size_t waited_ = 0;               // moves that waited for a free slot (coverage)
  bool edge_ = false;
  bool active_ = false, parked_ = true;
  std::string error_;
  sc_core::sc_event rise_, started_, stop_, parked_ev_;
};

// --- cpu: board8085 ---------------------------------------------------------

class BoardCosimEngine final : public VerilatedCosimEngine {
 public:
  SC_HAS_PROCESS(BoardCosimEngine);
  BoardCosimEngine(sc_core::sc_module_name n, double f_clk_hz, const std::string& rom_memh);
  ~BoardCosimEngine() override;
  std::string engine() const override { return "cpu"; }
  void begin_case(const Case& c) override;
  void end_case(EngineRun& run) override;

 private:
  void trace_model(VerilatedFstSc& fst) override;
  void host_thread();
  void on_clk();
  void poke(std::uint8_t addr, std::uint8_t v);
  std::uint8_t peek(std::uint8_t addr);
  void queue_next();
  bool slot_free(int i);

  sc_core::sc_clock clk_;
  sc_core::sc_signal<bool> rst_{"rst"}, cmd_sync_{"cmd_sync"}, zero_{"zero"};
  sc_core::sc_signal<std::uint32_t> intr_vec_{"intr_vec"}, host_addr_{"host_addr"}, host_wdata_{"host_wdata"};
  sc_core::sc_signal<bool> host_we_{"host_we"};
  sc_core::sc_signal<bool> step_z_{"step_z"}, dir_z_{"dir_z"}, debug_we_{"debug_we"}, host_ovr_{"host_ovr"}, cpu_wr_{"cpu_wr"},
      cpu_io_{"cpu_io"}, retire_{"retire"}, halted_{"halted"}, ie_{"ie"}, sod_{"sod"};
  sc_core::sc_signal<std::uint32_t> done_{"done"}, debug_{"debug"}, host_rdata_{"host_rdata"}, cpu_dout_{"cpu_dout"},
      dbg_kind_{"dbg_kind"}, dbg_irq_{"dbg_irq"}, dbg_op_{"dbg_op"}, cpu_addr_{"cpu_addr"}, dbg_ipc_{"dbg_ipc"},
      dbg_pc_{"dbg_pc"}, dbg_sp_{"dbg_sp"};
  sc_core::sc_signal<std::uint64_t> dbg_regs_{"dbg_regs"};
  std::unique_ptr<Vcosim_board> top_;
  std::unique_ptr<sw8085::Codes> codes_;
  std::vector<Placed> moves_;
  std::size_t next_move_ = 0;
  std::optional<sw8085::Segmenter> segmenter_;  // of moves_[next_move_]: a long line and an arc run as segments
  SlotLog slots_;
  std::size_t waited_ = 0;  // moves that waited for a free slot (coverage)
  // Every host port access happens in host_thread; the controller asks.
  enum class Request { None, Begin, End };
  Request request_ = Request::None;
  sc_core::sc_event request_ev_, reply_;
  std::array<std::uint8_t, 256> final_mailbox_{};
  bool active_ = false;  // the host refills slots
  std::string error_;
};

// Writes the built-in program's ROM image as a $readmemh file (8192 lines).
void write_rom_memh(const std::string& path);

}  // namespace contour::cosim
