#include "i8085/machine.hpp"

namespace i8085 {

Machine::~Machine() = default;

std::map<std::string, MachineInfo>& machines() {
  static std::map<std::string, MachineInfo> table;
  return table;
}

std::string machine_names() {
  std::string names;
  for (const auto& [name, info] : machines()) names += (names.empty() ? "" : "|") + name;
  return names;
}

namespace {

class IssMachine final : public Machine {
 public:
  IssMachine(Bus& bus, Mode mode) : cpu_(bus, mode) {}
  Mode mode() const override { return cpu_.mode(); }
  void reset() override { cpu_.reset(); }
  int step() override { return cpu_.step(); }
  std::uint64_t tstates() const override { return cpu_.tstates(); }
  Regs regs() const override { return cpu_.regs; }
  void set_regs(const Regs& r) override { cpu_.regs = r; }
  bool halted() const override { return cpu_.halted(); }
  bool ie() const override { return cpu_.ie(); }
  const Step& last() const override { return cpu_.last(); }
  void set_trap(bool level) override { cpu_.set_trap(level); }
  void set_rst75(bool level) override { cpu_.set_rst75(level); }
  void set_rst65(bool level) override { cpu_.set_rst65(level); }
  void set_rst55(bool level) override { cpu_.set_rst55(level); }
  void set_intr(bool level) override { cpu_.set_intr(level); }

 private:
  Cpu cpu_;
};

const MachineRegistrar kIss{{"iss", "the C++ instruction-set simulator (model/i8085)", make_iss}};

}  // namespace

std::unique_ptr<Machine> make_iss(Bus& bus, Mode mode) { return std::make_unique<IssMachine>(bus, mode); }

}  // namespace i8085
