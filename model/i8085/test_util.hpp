// Helpers shared by the i8085 tests: a CPU on a RAM bus, and a compact
// notation for machine state ("A=12 F=D5 BC=1234 SP=F000 M2000=56").
#pragma once

#include <cstdint>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "i8085/cpu.hpp"
#include "i8085/system.hpp"

namespace i8085::test {

struct Rig {
  explicit Rig(Mode m) : cpu(bus, m) {}
  RamBus bus;
  Cpu cpu;
  // Places `code` at `at`, sets PC there.
  void load(const std::vector<std::uint8_t>& code, std::uint16_t at = 0x0100) {
    for (std::size_t i = 0; i < code.size(); ++i) bus.mem[(at + i) & 0xFFFF] = code[i];
    cpu.regs.pc = at;
  }
};

struct MemPoke {
  std::uint16_t addr;
  std::uint8_t value;
};

// Applies a state spec to regs and memory. Keys: A F B C D E H L (hex
// byte), BC DE HL SP PC (hex word), Mxxxx=yy (memory byte).
inline void apply(const std::string& spec, Regs& r, std::vector<MemPoke>* mem) {
  std::istringstream in(spec);
  std::string item;
  while (in >> item) {
    const auto eq = item.find('=');
    if (eq == std::string::npos) throw std::invalid_argument("bad spec item " + item);
    const std::string key = item.substr(0, eq);
    const unsigned v = static_cast<unsigned>(std::stoul(item.substr(eq + 1), nullptr, 16));
    auto b = static_cast<std::uint8_t>(v);
    auto w = static_cast<std::uint16_t>(v);
    if (key == "A") r.a = b;
    else if (key == "F") r.f = b;
    else if (key == "B") r.b = b;
    else if (key == "C") r.c = b;
    else if (key == "D") r.d = b;
    else if (key == "E") r.e = b;
    else if (key == "H") r.h = b;
    else if (key == "L") r.l = b;
    else if (key == "BC") { r.b = static_cast<std::uint8_t>(w >> 8); r.c = static_cast<std::uint8_t>(w); }
    else if (key == "DE") { r.d = static_cast<std::uint8_t>(w >> 8); r.e = static_cast<std::uint8_t>(w); }
    else if (key == "HL") { r.h = static_cast<std::uint8_t>(w >> 8); r.l = static_cast<std::uint8_t>(w); }
    else if (key == "SP") r.sp = w;
    else if (key == "PC") r.pc = w;
    else if (key.size() == 5 && key[0] == 'M') {
      if (!mem) throw std::invalid_argument("memory not allowed here: " + item);
      mem->push_back({static_cast<std::uint16_t>(std::stoul(key.substr(1), nullptr, 16)), b});
    } else {
      throw std::invalid_argument("bad spec key " + key);
    }
  }
}

inline std::string show(const Regs& r) {
  char buf[128];
  std::snprintf(buf, sizeof buf, "A=%02X F=%02X B=%02X C=%02X D=%02X E=%02X H=%02X L=%02X SP=%04X PC=%04X",
                r.a, r.f, r.b, r.c, r.d, r.e, r.h, r.l, r.sp, r.pc);
  return buf;
}

}  // namespace i8085::test
