// A small system around a Machine: 64 KiB of RAM, input/output ports, and
// the two ways `contour sim85` runs a program: bare (from reset until HLT)
// and CP/M-style (a .COM diagnostic at 0x0100 with BDOS functions 2 and 9).
#pragma once

#include <array>
#include <cstdint>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "i8085/cpu.hpp"
#include "i8085/hex.hpp"
#include "i8085/machine.hpp"

namespace i8085 {

struct PortWrite {
  std::uint64_t t = 0;  // T-states before the OUT instruction
  std::uint8_t port = 0;
  std::uint8_t value = 0;
  friend bool operator==(const PortWrite&, const PortWrite&) = default;
};

// RAM everywhere; IN returns inputs[port] (0xFF unless set); OUT is logged.
// The Cpu reads and writes `mem` directly (memory()): read and write are
// final, so that no derived bus can give them side effects it would miss.
class RamBus : public Bus {
 public:
  RamBus() { inputs.fill(0xFF); }
  std::uint8_t read(std::uint16_t addr) final { return mem[addr]; }
  void write(std::uint16_t addr, std::uint8_t v) final { mem[addr] = v; }
  std::uint8_t* memory() final { return mem.data(); }
  std::uint8_t in(std::uint8_t port) override { return inputs[port]; }
  void out(std::uint8_t port, std::uint8_t v) override { outs.push_back({0, port, v}); }

  std::array<std::uint8_t, 65536> mem{};
  std::array<std::uint8_t, 256> inputs{};
  std::vector<PortWrite> outs;
};

// A run that cannot go on: undocumented opcode, unsupported BDOS call, a
// T-state limit reached. The message says what and where.
class RunError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct RunOptions {
  std::uint64_t max_tstates = 0;   // the run may use at most this many; 0: no limit
  std::ostream* trace = nullptr;   // one trace_line per step when set
};

struct RunResult {
  std::uint64_t tstates = 0;  // T-states used by the run, last instruction included
  std::uint64_t steps = 0;
};

// One step of a run, for loops that drive interrupts themselves: steps the
// machine, writes the trace line, stamps new port writes with the step's
// starting T-state, counts the step in `res`; throws RunError on an
// undocumented 8085 opcode or when the machine's T-state count passes
// opt.max_tstates.
void run_step(Machine& m, RamBus& bus, const RunOptions& opt, RunResult& res);

// Loads a program: Intel HEX (by content: first non-blank character ':')
// or a raw binary placed at `raw_base`. Returns the lowest address loaded.
// Throws HexError / RunError.
std::uint16_t load_program(RamBus& bus, const std::vector<std::uint8_t>& file, const std::string& name,
                           std::uint16_t raw_base);

// Bare run: from the machine's current state until it halts (the HLT
// instruction included). Port writes are stamped in bus.outs.
RunResult run_bare(Machine& m, RamBus& bus, const RunOptions& opt);

// CP/M-style run. Before: memory holds the program at 0x0100 (nothing below
// 0x0100 may be loaded). Places OUT 0 at 0x0000 and OUT 1; RET at 0x0005,
// resets the machine, sets PC = 0x0100 and SP = 0xFFFE with a return address
// of 0x0000 on the stack (as CP/M's CCP does), runs until OUT 0 executes.
// BDOS (on OUT 1): C = 2 writes E, C = 9 writes from (DE) up to '$'; the
// characters go to `console`. Any other C is a RunError.
RunResult run_cpm(Machine& m, RamBus& bus, std::ostream& console, const RunOptions& opt);

}  // namespace i8085
