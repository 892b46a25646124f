#include "i8085/system.hpp"

#include "i8085/hex_text.hpp"

namespace i8085 {

namespace {

[[noreturn, gnu::cold, gnu::noinline]] void throw_undocumented(const Step& s) {
  throw RunError("undocumented 8085 opcode " + hex2(s.bytes[0]) + " (" + disassemble(s.bytes, s.mode) + ") at PC=" +
                 hex4(s.pc) + ": not implemented (docs/i8085.md)");
}

[[noreturn, gnu::cold, gnu::noinline]] void throw_limit(const Machine& m, const RunOptions& opt) {
  throw RunError("stopped after " + std::to_string(m.tstates()) + " T-states, past the limit " +
                 std::to_string(opt.max_tstates) + " (PC=" + hex4(m.regs().pc) + "): the program did not finish");
}

[[gnu::cold, gnu::noinline]] void stamp_and_trace(const Machine& m, RamBus& bus, const RunOptions& opt,
                                                  std::size_t outs_before) {
  const Step& s = m.last();
  for (std::size_t i = outs_before; i < bus.outs.size(); ++i) bus.outs[i].t = s.t_before;
  if (opt.trace) *opt.trace << trace_line(s, m.regs()) << '\n';
}

}  // namespace

// The runners' hot loop: what is rare (a port write, a trace, an error) is
// out of line.
void run_step(Machine& m, RamBus& bus, const RunOptions& opt, RunResult& res) {
  const std::size_t outs_before = bus.outs.size();
  m.step();
  ++res.steps;
  if (opt.trace || bus.outs.size() != outs_before) [[unlikely]]
    stamp_and_trace(m, bus, opt, outs_before);
  if (m.last().undocumented) [[unlikely]]
    throw_undocumented(m.last());
  if (opt.max_tstates != 0 && m.tstates() > opt.max_tstates) [[unlikely]]
    throw_limit(m, opt);
}

std::uint16_t load_program(RamBus& bus, const std::vector<std::uint8_t>& file, const std::string& name,
                           std::uint16_t raw_base) {
  std::size_t i = 0;
  while (i < file.size() && (file[i] == ' ' || file[i] == '\t' || file[i] == '\r' || file[i] == '\n')) ++i;
  if (i < file.size() && file[i] == ':') {
    const HexImage img = parse_hex(std::string(file.begin(), file.end()), name);
    if (img.size() == 0) throw RunError(name + ": the HEX file holds no data");
    img.load_into(bus.mem);
    return img.lowest();
  }
  if (file.empty()) throw RunError(name + ": empty file");
  if (file.size() + raw_base > 0x10000)
    throw RunError(name + ": " + std::to_string(file.size()) + " bytes do not fit above " + hex4(raw_base));
  for (std::size_t k = 0; k < file.size(); ++k) bus.mem[raw_base + k] = file[k];
  return raw_base;
}

RunResult run_bare(Machine& m, RamBus& bus, const RunOptions& opt) {
  RunResult res;
  const std::uint64_t t0 = m.tstates();
  while (!m.halted()) run_step(m, bus, opt, res);
  res.tstates = m.tstates() - t0;
  return res;
}

RunResult run_cpm(Machine& m, RamBus& bus, std::ostream& console, const RunOptions& opt) {
  bus.mem[0x0000] = 0xD3;  // OUT 0: end of run
  bus.mem[0x0001] = 0x00;
  bus.mem[0x0005] = 0xD3;  // OUT 1: BDOS call
  bus.mem[0x0006] = 0x01;
  bus.mem[0x0007] = 0xC9;  // RET
  m.reset();
  Regs r = m.regs();
  r.pc = 0x0100;
  r.sp = 0xFFFE;
  bus.mem[0xFFFE] = 0x00;  // return address 0x0000, as pushed by the CCP
  bus.mem[0xFFFF] = 0x00;
  m.set_regs(r);
  RunResult res;
  const std::uint64_t t0 = m.tstates();
  for (;;) {
    run_step(m, bus, opt, res);
    const Step& s = m.last();
    if (s.kind != StepKind::instruction || s.bytes[0] != 0xD3) continue;
    if (s.bytes[1] == 0x00) break;
    if (s.bytes[1] != 0x01) continue;
    const Regs q = m.regs();
    if (q.c == 2) {
      console.put(static_cast<char>(q.e));
    } else if (q.c == 9) {
      std::uint16_t a = q.de();
      for (std::uint32_t n = 0;; ++n, a = static_cast<std::uint16_t>(a + 1)) {
        if (n == 0x10000)
          throw RunError("BDOS 9 at PC=" + hex4(s.pc) + ": no '$' after DE=" + hex4(q.de()));
        if (bus.mem[a] == '$') break;
        console.put(static_cast<char>(bus.mem[a]));
      }
    } else {
      throw RunError("unsupported BDOS function C=" + hex2(q.c) + " (only 2 and 9 are served), return address " +
                     hex4(static_cast<unsigned>(bus.mem[q.sp] | bus.mem[(q.sp + 1) & 0xFFFF] << 8)));
    }
    if (q.e == '\n' || q.c == 9) console.flush();
  }
  res.tstates = m.tstates() - t0;
  return res;
}

}  // namespace i8085
