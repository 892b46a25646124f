// The host side of sw8085/interp/interp.a80: a board around an 8085 machine
// (the ISS, or the Verilated CPU), moves queued through the mailbox, command
// pulses on RST 7.5, step pulses read from OUT 10h, state read back from the
// mailbox after every pulse.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "i8085/cpu.hpp"
#include "i8085/machine.hpp"
#include "interp/engine.hpp"
#include "mailbox.hpp"

namespace contour::sw8085 {

// The assembled program: its memory image and the listing's symbols.
struct Program {
  std::array<std::uint8_t, 65536> image{};
  std::map<std::string, std::uint16_t> symbols;  // upper case, as asm80 lists them

  // Throws std::runtime_error naming the file if it cannot be read or parsed.
  static Program load(const std::string& hex_path, const std::string& lst_path);
  // The same from the files' text; the names are for messages.
  static Program from_text(const std::string& hex_text, const std::string& lst_text, const std::string& hex_name,
                           const std::string& lst_name);
  // sw8085/interp/interp.hex and .lst as assembled by the build, embedded in
  // the binary (no file is read: an installed `contour` needs no build tree).
  static const Program& builtin();
  std::uint16_t symbol(const std::string& name) const;
};

// The board map of docs/board8085.md, in C++: ROM, RAM, mailbox, the edge
// counter on IN 11h, OUT 10h/12h logged. Any other access is a fault, kept
// (the first one) for the host to report.
class BoardBus final : public i8085::Bus {
 public:
  explicit BoardBus(const Program& p);
  std::uint8_t read(std::uint16_t addr) override;
  void write(std::uint16_t addr, std::uint8_t v) override;
  std::uint8_t in(std::uint8_t port) override;
  void out(std::uint8_t port, std::uint8_t v) override;

  std::span<std::uint8_t, 256> mailbox() { return std::span<std::uint8_t, 256>(mem.data() + kMailbox, 256); }

  std::array<std::uint8_t, 65536> mem{};
  std::uint8_t edges = 0;  // rising edges of the command input, mod 256
  struct Write {
    std::uint8_t port, value;
  };
  std::vector<Write> outs;  // since the host last cleared it
  std::string fault;
};

// T-states and output of one command pulse.
struct CommandResult {
  std::optional<Pulse> pulse;
  int tstates = 0;  // acknowledge to the end of the RET, both included
  int instructions = 0;  // instructions executed (the acknowledge is not one)
  bool move_ended = false;
};

class Host {
 public:
  // `factory` builds the 8085 (i8085::make_iss, or the Verilated CPU).
  explicit Host(const Program& p = Program::builtin(), const i8085::MachineFactory& factory = i8085::make_iss);

  // Queues a move (validated at W = 24: throws InputError) in the next slot.
  // Throws std::logic_error if that slot still holds a move not finished
  // (or a move's segments still wait: !can_queue()). A move that is done at
  // once (a line to (0, 0)) is not queued. A line of more than
  // line::kSegment P steps and an arc run as segments (Segmenter): the
  // first one is queued and returned, the others wait for pump().
  SlotMove queue(const Move& m);
  // Writes the waiting segments into the slots as they become free (in
  // order); returns those written.
  std::vector<SlotMove> pump();
  bool can_queue() const;

  // One command pulse: a rising edge on RST 7.5, then the CPU runs until its
  // interrupt routine has returned. Throws std::runtime_error on a bus fault
  // or a routine that does not return.
  CommandResult command();

  // The observable state of a queued move, from the mailbox.
  State state(const SlotMove& sm, std::uint64_t pulses) const;
  bool done(const SlotMove& sm) const;
  // Whether queue() may write slot i (0 or 1) now.
  bool slot_free(int i) const;

  // Runs a move to its end, one command pulse at a time (the Engine seam);
  // `commands` gets the T-states and instructions of each.
  // A run longer than `max_pulses` (0: a bound from the move's size) throws.
  // With `on_step` each step goes there and none is kept in the result.
  RunResult run(const Move& m, std::vector<CommandResult>* commands = nullptr, std::uint64_t max_pulses = 0,
                const StepFn& on_step = {});

  // Command pulses every `period` T-states (the first one `period` after
  // the call) until `moves` are all done, the host queueing each as soon as
  // a slot is free. Returns what the mailbox counted.
  struct Timed {
    std::uint64_t commands = 0, pulses = 0, overruns = 0, idle_commands = 0;
    bool all_done = false;
  };
  Timed drive(const std::vector<Move>& moves, double period, std::vector<Pulse>* pulses = nullptr);

  std::uint32_t overruns() const;
  std::uint16_t idle_commands() const;
  // Runs the CPU until it halts in its idle loop with nothing pending.
  void settle();
  i8085::Machine& machine() { return *machine_; }
  BoardBus& bus() { return bus_; }
  const Codes& codes() const { return codes_; }

 private:
  void boot();
  void edge();
  void step_checked();

  BoardBus bus_;
  std::unique_ptr<i8085::Machine> machine_;
  Codes codes_;
  std::uint16_t sp_idle_ = 0;
  int next_slot_ = 0;
  std::array<std::optional<SlotMove>, 2> slots_;
  std::optional<Segmenter> pending_;  // the last move's segments not yet written
  SlotMove write(Segmenter& seg);
};

// The program as a contour Engine ("iss": on the ISS; "cpu": on the
// Verilog board, bound in sim/cli/engine_cpu.cpp).
class ProgramEngine final : public Engine {
 public:
  ProgramEngine(std::string name, i8085::MachineFactory factory) : name_(std::move(name)), factory_(std::move(factory)) {}
  std::string name() const override { return name_; }
  RunResult run(const Move& m) override;
  RunResult stream(const Move& m, const StepFn& on_step) override;

 private:
  std::string name_;
  i8085::MachineFactory factory_;
};

}  // namespace contour::sw8085
