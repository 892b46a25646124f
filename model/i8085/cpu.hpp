// A T-state-exact Intel 8085 (and 8080) instruction-set simulator.
//
// docs/i8085.md is the contract: the T-state table and its source, the
// flags, the interrupt system, the choices where sources disagree, and the
// trace format that the Verilog CPU is compared against line by line.
#pragma once

#include <array>
#include <cstdint>
#include <string>

namespace i8085 {

enum class Mode : std::uint8_t { i8080, i8085 };

// Bits of the flag register F.
namespace flag {
constexpr std::uint8_t S = 0x80;
constexpr std::uint8_t Z = 0x40;
constexpr std::uint8_t AC = 0x10;
constexpr std::uint8_t P = 0x04;
constexpr std::uint8_t CY = 0x01;
// Bit 1 reads 1 on the 8080. On the 8085 bits 1 and 5 (the undocumented V
// and K flags) read 0 here: the undocumented instructions are not
// implemented (docs/i8085.md), so nothing could observe V or K.
constexpr std::uint8_t k8080Fixed = 0x02;
// Bits that instructions can change: S Z AC P CY.
constexpr std::uint8_t kDefined = 0xD5;
}  // namespace flag

// Fixed bits of F in a mode: what POP PSW forces and every flag update sets.
constexpr std::uint8_t fixed_flags(Mode m) { return m == Mode::i8080 ? flag::k8080Fixed : 0x00; }

struct Regs {
  std::uint8_t a, f, b, c, d, e, h, l;
  std::uint16_t sp, pc;

  std::uint16_t bc() const { return static_cast<std::uint16_t>(b << 8 | c); }
  std::uint16_t de() const { return static_cast<std::uint16_t>(d << 8 | e); }
  std::uint16_t hl() const { return static_cast<std::uint16_t>(h << 8 | l); }
  friend bool operator==(const Regs&, const Regs&) = default;
};

// Memory, I/O and interrupt acknowledge, supplied by the system around the
// CPU. inta() supplies the instruction bytes of an INTR acknowledge, one call
// per byte (a single-byte RST n, or CALL and its two address bytes).
class Bus {
 public:
  virtual ~Bus();
  virtual std::uint8_t read(std::uint16_t addr) = 0;
  virtual void write(std::uint16_t addr, std::uint8_t v) = 0;
  virtual std::uint8_t in(std::uint8_t port) = 0;
  virtual void out(std::uint8_t port, std::uint8_t v) = 0;
  virtual std::uint8_t inta() { return 0xFF; }  // RST 7
  // 64 KiB that read() and write() read and write with no side effect, or
  // nullptr. When there is one, the Cpu reads and writes it directly: no
  // virtual call per memory cycle (the hot loop of docs/i8085.md, "Speed").
  virtual std::uint8_t* memory() { return nullptr; }
};

// What one step() did.
enum class StepKind : std::uint8_t { instruction, interrupt, idle };
enum class Interrupt : std::uint8_t { none, trap, rst75, rst65, rst55, intr };

// Vector addresses of the 8085's internal restarts.
constexpr std::uint16_t kTrapVector = 0x0024;
constexpr std::uint16_t kRst75Vector = 0x003C;
constexpr std::uint16_t kRst65Vector = 0x0034;
constexpr std::uint16_t kRst55Vector = 0x002C;

// T-states of the acknowledge of TRAP, RST 7.5, RST 6.5 and RST 5.5: a 6-state
// bus-idle opcode cycle (as the M1 of the RST instruction, which decrements
// SP) and two 3-state memory writes of PC. docs/i8085.md explains 12, not 11.
constexpr int kVectoredAckTStates = 12;
// T-states one step() consumes while the CPU is halted and nothing wakes it.
constexpr int kHaltIdleTStates = 1;

struct Step {
  std::uint64_t t_before = 0;  // cumulative T-states before this step
  std::uint16_t pc = 0;        // PC before this step
  std::array<std::uint8_t, 3> bytes{};  // instruction bytes as fetched
  std::uint8_t length = 0;     // number of valid bytes (0: none fetched)
  StepKind kind = StepKind::instruction;
  Interrupt irq = Interrupt::none;
  Mode mode = Mode::i8085;
  bool undocumented = false;   // an 8085 undocumented opcode, run as NOP
  int tstates = 0;             // T-states of this step
};

class Cpu {
 public:
  explicit Cpu(Bus& bus, Mode mode = Mode::i8085);

  // RESET IN: PC = 0, IE = 0, RST 7.5/6.5/5.5 masked, RST 7.5 and TRAP
  // latches cleared, SOD = 0, not halted. The other registers become 0 (the
  // hardware leaves them undefined). The T-state counter is not changed.
  void reset();

  // Executes exactly one instruction, or one interrupt acknowledge, or one
  // halted idle unit of kHaltIdleTStates. Returns its T-states.
  int step();

  std::uint64_t tstates() const { return t_; }
  Mode mode() const { return mode_; }
  bool halted() const { return halted_; }
  const Step& last() const { return last_; }

  // Interrupt inputs (levels). RST 7.5 and TRAP latch on a rising edge.
  // On the 8080 only INTR exists; asserting the others throws logic_error.
  void set_trap(bool level);
  void set_rst75(bool level);
  void set_rst65(bool level);
  void set_rst55(bool level);
  void set_intr(bool level);

  // What RIM would load into A now. SID (bit 7) reads 0: the model has no
  // serial input.
  std::uint8_t rim_value() const;
  bool ie() const { return ie_; }
  bool sod() const { return sod_; }
  // Bits M7.5 M6.5 M5.5 of the interrupt mask (2..0).
  std::uint8_t masks() const { return masks_; }
  bool rst75_latched() const { return rst75_latch_; }

  Regs regs{};

 private:
  // The hot loop (cpu.cpp): one instruction with nothing pending, per mode,
  // memory direct (D) or through the Bus. `attention_` says that the next
  // step must take the slow path: halted, EI delay, an interrupt that may be
  // pending; update_attention() recomputes it after every change of those.
  template <Mode M, bool D> int fast_step();
  template <Mode M, bool D> int dispatch(std::uint8_t op);
  template <Mode M, bool D, int OP> int exec();
  template <Mode M, bool D, int OP> int quarter0();
  template <Mode M, bool D, int OP> int quarter3();
  template <Mode M, bool D, int OP> int load_store();
  template <Mode M, bool D, int OP> int rotate();
  template <Mode M, bool D, int OP> int pop_ret();
  template <Mode M, bool D, int OP> int jmp_io_misc();
  template <Mode M, bool D, int OP> int push_call();
  template <bool D> std::uint8_t rd(std::uint16_t a) { return D ? mem_[a] : bus_.read(a); }
  template <bool D> void wr(std::uint16_t a, std::uint8_t v);
  template <bool D> std::uint8_t imm8();
  template <bool D> std::uint16_t imm16();
  template <bool D> void push(std::uint16_t v);
  template <bool D> std::uint16_t pop();
  template <bool D, int R> std::uint8_t get_r();
  template <bool D, int R> void set_r(std::uint8_t v);
  template <int RP> std::uint16_t get_rp() const;
  template <int RP> void set_rp(std::uint16_t v);
  template <int CC> bool condition() const;
  template <Mode M, int OP> void alu(std::uint8_t v);
  template <Mode M> void daa();
  void set_carry(bool c) { regs.f = static_cast<std::uint8_t>((regs.f & ~flag::CY) | (c ? flag::CY : 0)); }
  int undocumented();
  void rim();
  void sim();
  void update_attention();
  // The slow path: interrupts, halted idle units, the EI delay, INTR.
  int step_slow();
  int execute(std::uint8_t op);
  Interrupt pending(bool maskable_allowed) const;
  int acknowledge(Interrupt irq);

  Bus& bus_;
  std::uint8_t* mem_;          // bus_.memory()
  Mode mode_;
  bool attention_ = true;
  std::uint64_t t_ = 0;
  Step last_{};
  bool halted_ = false;
  bool ie_ = false;
  bool ei_delay_ = false;      // EI just executed: no maskable interrupt before the next instruction
  bool from_inta_ = false;     // fetches come from bus.inta() (INTR acknowledge)
  std::uint8_t masks_ = 0x07;
  bool trap_level_ = false, trap_latch_ = false;
  bool rst75_level_ = false, rst75_latch_ = false;
  bool rst65_level_ = false, rst55_level_ = false, intr_level_ = false;
  bool sod_ = false;
  bool rim_after_trap_ = false, ie_before_trap_ = false;
};

// Instruction length in bytes (1..3) of an opcode in a mode.
int instruction_length(std::uint8_t op, Mode mode);

// The ten opcodes the 8085 data sheet leaves undocumented (08 10 18 28 38
// CB D9 DD ED FD), which this ISS runs as 4-T NOPs and flags
// (Step::undocumented; docs/i8085.md).
bool is_undocumented_8085(std::uint8_t op);

// "MVI A,12", "LXI H,1234", "RST 7": upper case, hex operands without suffix.
std::string disassemble(const std::array<std::uint8_t, 3>& bytes, Mode mode);

// One trace line (docs/i8085.md, "Trace format"), without a newline:
// T=<t_before, 10 wide> PC=<pc> OP=<op|--> <mnemonic, 14 wide> A=.. F=..
// B=.. C=.. D=.. E=.. H=.. L=.. SP=.... +<tstates>, registers after the step.
std::string trace_line(const Step& step, const Regs& after);

}  // namespace i8085
