// The 8085 behind `contour sim85`: an abstract machine, so that the ISS
// (engine "iss") and the Verilated CPU (engine "cpu", registered by
// sim/cli/machine_cpu.cpp) run the same programs through the same runner and
// trace.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string>

#include "i8085/cpu.hpp"

namespace i8085 {

class Machine {
 public:
  virtual ~Machine();
  virtual Mode mode() const = 0;
  // RESET IN (see Cpu::reset). Does not touch memory or the T-state count.
  virtual void reset() = 0;
  // One instruction, interrupt acknowledge or halted idle unit (Cpu::step).
  virtual int step() = 0;
  virtual std::uint64_t tstates() const = 0;
  virtual Regs regs() const = 0;
  // Loads registers without spending T-states (used to start at 0x0100).
  virtual void set_regs(const Regs& r) = 0;
  virtual bool halted() const = 0;
  virtual bool ie() const = 0;
  // The record of the last step(), for the trace.
  virtual const Step& last() const = 0;
  virtual void set_trap(bool level) = 0;
  virtual void set_rst75(bool level) = 0;
  virtual void set_rst65(bool level) = 0;
  virtual void set_rst55(bool level) = 0;
  virtual void set_intr(bool level) = 0;
};

using MachineFactory = std::function<std::unique_ptr<Machine>(Bus& bus, Mode mode)>;

struct MachineInfo {
  std::string name;
  std::string summary;
  MachineFactory make;
};

// Registered machines by name; "iss" is always there.
std::map<std::string, MachineInfo>& machines();

struct MachineRegistrar {
  explicit MachineRegistrar(MachineInfo m) { machines().emplace(m.name, std::move(m)); }
};

// "iss|rtl|..." for help texts.
std::string machine_names();

// The ISS as a Machine.
std::unique_ptr<Machine> make_iss(Bus& bus, Mode mode);

}  // namespace i8085
