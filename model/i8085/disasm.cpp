// Disassembler and trace lines (docs/i8085.md, "Trace format").
#include <cstdio>

#include "i8085/cpu.hpp"
#include "i8085/hex_text.hpp"

namespace i8085 {

namespace {

constexpr const char* kReg[8] = {"B", "C", "D", "E", "H", "L", "M", "A"};
constexpr const char* kRp[4] = {"B", "D", "H", "SP"};
constexpr const char* kRpPsw[4] = {"B", "D", "H", "PSW"};
constexpr const char* kCc[8] = {"NZ", "Z", "NC", "C", "PO", "PE", "P", "M"};
constexpr const char* kAlu[8] = {"ADD", "ADC", "SUB", "SBB", "ANA", "XRA", "ORA", "CMP"};
constexpr const char* kAluImm[8] = {"ADI", "ACI", "SUI", "SBI", "ANI", "XRI", "ORI", "CPI"};
constexpr const char* kRot[8] = {"RLC", "RRC", "RAL", "RAR", "DAA", "CMA", "STC", "CMC"};

const char* undocumented_name(std::uint8_t op) {
  switch (op) {
    case 0x08: return "DSUB";
    case 0x10: return "ARHL";
    case 0x18: return "RDEL";
    case 0x28: return "LDHI";
    case 0x38: return "LDSI";
    case 0xCB: return "RSTV";
    case 0xD9: return "SHLX";
    case 0xDD: return "JNX5";
    case 0xED: return "LHLX";
    case 0xFD: return "JK";
    default: return nullptr;
  }
}

}  // namespace

std::string disassemble(const std::array<std::uint8_t, 3>& bytes, Mode mode) {
  const std::uint8_t op = bytes[0];
  const std::string d8 = hex2(bytes[1]);
  const std::string d16 = hex4(static_cast<unsigned>(bytes[2] << 8 | bytes[1]));
  const int x = op >> 6, y = (op >> 3) & 7, z = op & 7, rp = y >> 1;
  if (mode == Mode::i8085) {
    if (const char* u = undocumented_name(op)) return std::string("UNDOC ") + u;
    if (op == 0x20) return "RIM";
    if (op == 0x30) return "SIM";
  }
  if (x == 1) {
    if (op == 0x76) return "HLT";
    return std::string("MOV ") + kReg[y] + "," + kReg[z];
  }
  if (x == 2) return std::string(kAlu[y]) + " " + kReg[z];
  if (x == 0) {
    switch (z) {
      case 0: return "NOP";
      case 1: return (y & 1) ? std::string("DAD ") + kRp[rp] : std::string("LXI ") + kRp[rp] + "," + d16;
      case 2: {
        static constexpr const char* kNames[8] = {"STAX B", "LDAX B", "STAX D", "LDAX D",
                                                  "SHLD ", "LHLD ", "STA ", "LDA "};
        return y >= 4 ? kNames[y] + d16 : kNames[y];
      }
      case 3: return std::string((y & 1) ? "DCX " : "INX ") + kRp[rp];
      case 4: return std::string("INR ") + kReg[y];
      case 5: return std::string("DCR ") + kReg[y];
      case 6: return std::string("MVI ") + kReg[y] + "," + d8;
      default: return kRot[y];
    }
  }
  switch (z) {
    case 0: return std::string("R") + kCc[y];
    case 1:
      if ((y & 1) == 0) return std::string("POP ") + kRpPsw[rp];
      switch (rp) {
        case 0: case 1: return "RET";
        case 2: return "PCHL";
        default: return "SPHL";
      }
    case 2: return std::string("J") + kCc[y] + " " + d16;
    case 3:
      switch (y) {
        case 0: case 1: return "JMP " + d16;
        case 2: return "OUT " + d8;
        case 3: return "IN " + d8;
        case 4: return "XTHL";
        case 5: return "XCHG";
        case 6: return "DI";
        default: return "EI";
      }
    case 4: return std::string("C") + kCc[y] + " " + d16;
    case 5:
      if ((y & 1) == 0) return std::string("PUSH ") + kRpPsw[rp];
      return "CALL " + d16;
    case 6: return std::string(kAluImm[y]) + " " + d8;
    default: return "RST " + std::to_string(y);
  }
}

std::string trace_line(const Step& s, const Regs& r) {
  std::string mnemonic;
  std::string op = "--";
  switch (s.kind) {
    case StepKind::instruction:
      mnemonic = disassemble(s.bytes, s.mode);
      op = hex2(s.bytes[0]);
      break;
    case StepKind::idle:
      mnemonic = "IDLE";
      break;
    case StepKind::interrupt:
      switch (s.irq) {
        case Interrupt::trap: mnemonic = "INT TRAP"; break;
        case Interrupt::rst75: mnemonic = "INT RST7.5"; break;
        case Interrupt::rst65: mnemonic = "INT RST6.5"; break;
        case Interrupt::rst55: mnemonic = "INT RST5.5"; break;
        default:
          mnemonic = "INTA " + disassemble(s.bytes, s.mode);
          op = hex2(s.bytes[0]);
          break;
      }
      break;
  }
  char buf[200];
  std::snprintf(buf, sizeof buf,
                "T=%10llu PC=%04X OP=%s %-14s A=%02X F=%02X B=%02X C=%02X D=%02X E=%02X H=%02X "
                "L=%02X SP=%04X +%d",
                static_cast<unsigned long long>(s.t_before), s.pc, op.c_str(), mnemonic.c_str(), r.a,
                r.f, r.b, r.c, r.d, r.e, r.h, r.l, r.sp, s.tstates);
  return buf;
}

}  // namespace i8085
