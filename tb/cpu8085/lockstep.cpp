#include "lockstep.hpp"

#include <algorithm>
#include <cstdio>
#include <sstream>

#include "cpu_machine.hpp"

namespace cpu8085::tb {

namespace {

constexpr std::size_t kContextLines = 8;

std::string describe(const std::vector<Access>& log) {
  std::string s;
  char buf[32];
  for (const Access& a : log) {
    std::snprintf(buf, sizeof buf, "%s%s[%04X]=%02X", s.empty() ? "" : " ", a.io ? "OUT" : "MEM",
                  static_cast<unsigned>(a.addr), static_cast<unsigned>(a.value));
    s += buf;
  }
  return s.empty() ? "(none)" : s;
}

}  // namespace

Lockstep::Lockstep(const std::array<std::uint8_t, 65536>& image, const std::string& fst_path) {
  iss_bus_.mem = image;
  rtl_bus_.mem = image;
  iss_ = i8085::make_iss(iss_bus_, i8085::Mode::i8085);
  rtl_ = make_cpu_machine(rtl_bus_, i8085::Mode::i8085, fst_path);
}

void Lockstep::set_regs(const i8085::Regs& r) {
  iss_->set_regs(r);
  rtl_->set_regs(r);
}

void Lockstep::set_pins(const Pins& p) {
  for (i8085::Machine* m : {iss_.get(), rtl_.get()}) {
    m->set_trap(p.trap);
    m->set_rst75(p.rst75);
    m->set_rst65(p.rst65);
    m->set_rst55(p.rst55);
    m->set_intr(p.intr);
  }
}

void Lockstep::queue_inta(const std::vector<std::uint8_t>& bytes) {
  for (LogBus* b : {&iss_bus_, &rtl_bus_}) {
    b->inta_bytes.insert(b->inta_bytes.end(), bytes.begin(), bytes.end());
  }
}

void Lockstep::set_in_value(std::function<std::uint8_t(std::uint8_t, std::uint64_t)> f) {
  iss_bus_.in_value = f;
  rtl_bus_.in_value = f;
}

bool Lockstep::step() {
  iss_bus_.log.clear();
  rtl_bus_.log.clear();
  iss_->step();
  rtl_->step();
  ++steps_;
  const i8085::Step& a = iss_->last();
  const i8085::Step& b = rtl_->last();
  const i8085::Regs ra = iss_->regs();
  const i8085::Regs rb = rtl_->regs();
  std::vector<Access> wa = iss_bus_.log, wb = rtl_bus_.log;
  // The order of two writes inside one instruction is not architectural
  // (XTHL: the ISS writes L first, the RTL H first as the 8085 does).
  std::stable_sort(wa.begin(), wa.end());
  std::stable_sort(wb.begin(), wb.end());

  std::string what;
  if (a.kind != b.kind || a.irq != b.irq) what = "step kind (instruction / interrupt / idle)";
  else if (a.pc != b.pc) what = "PC at the start of the step";
  else if (a.tstates != b.tstates) what = "T-states of the step";
  else if (iss_->tstates() != rtl_->tstates()) what = "cumulative T-states";
  else if (a.kind != i8085::StepKind::idle && a.bytes[0] != b.bytes[0]) what = "opcode";
  else if (ra.pc != rb.pc) what = "PC after the step";
  else if (ra.sp != rb.sp) what = "SP";
  else if (ra.a != rb.a) what = "A";
  else if (ra.f != rb.f) what = "flags F";
  else if (!(ra == rb)) what = "B C D E H L";
  else if (iss_->halted() != rtl_->halted()) what = "HALT state";
  else if (iss_->ie() != rtl_->ie()) what = "IE (interrupt enable)";
  else if (wa != wb) what = "memory / port writes";

  const std::string line = i8085::trace_line(a, ra);
  if (what.empty()) {
    context_.push_back(line);
    if (context_.size() > kContextLines) context_.pop_front();
    return true;
  }
  std::ostringstream o;
  o << "divergence at step " << steps_ << ": " << what << " differs\n";
  o << "  context (ISS, preceding steps):\n";
  for (const std::string& c : context_) o << "      " << c << '\n';
  o << "  ISS: " << line << "\n       writes: " << describe(iss_bus_.log) << " halted=" << iss_->halted()
    << " ie=" << iss_->ie() << "\n";
  o << "  RTL: " << i8085::trace_line(b, rb) << "\n       writes: " << describe(rtl_bus_.log)
    << " halted=" << rtl_->halted() << " ie=" << rtl_->ie() << " T=" << rtl_->tstates() << "\n";
  report_ = o.str();
  return false;
}

}  // namespace cpu8085::tb
