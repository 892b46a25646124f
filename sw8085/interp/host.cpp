#include "host.hpp"

#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "i8085/hex.hpp"

namespace contour::sw8085 {

Program Program::from_text(const std::string& hex_text, const std::string& lst_text, const std::string& hex_name,
                           const std::string& lst_name) {
  Program p;
  i8085::parse_hex(hex_text, hex_name).load_into(p.image);
  std::istringstream lst(lst_text);
  // Symbol table lines: "NAME:<spaces>HHHH DEFINED AT LINE n".
  std::string line;
  while (std::getline(lst, line)) {
    const auto colon = line.find(':');
    const auto def = line.find(" DEFINED AT LINE");
    if (colon == std::string::npos || def == std::string::npos || colon == 0 || def < 4) continue;
    const std::string name = line.substr(0, colon);
    if (name.find(' ') != std::string::npos) continue;
    const std::string hex = line.substr(def - 4, 4);
    // asm80 prints a negative value as the hex of its magnitude after a
    // minus, padded to 4 characters ("00-1" is -1): keep 16-bit two's complement.
    const auto minus = hex.find('-');
    const long v = minus == std::string::npos ? static_cast<long>(std::stoul(hex, nullptr, 16))
                                              : -static_cast<long>(std::stoul(hex.substr(minus + 1), nullptr, 16));
    p.symbols[name] = static_cast<std::uint16_t>(v);
  }
  if (p.symbols.empty()) throw std::runtime_error(lst_name + ": no symbol table in the listing");
  return p;
}

Program Program::load(const std::string& hex_path, const std::string& lst_path) {
  auto slurp = [](const std::string& path, const char* what) {
    std::ifstream f(path);
    if (!f) throw std::runtime_error(path + ": cannot read the " + what);
    std::stringstream s;
    s << f.rdbuf();
    return s.str();
  };
  return from_text(slurp(hex_path, "program"), slurp(lst_path, "listing"), hex_path, lst_path);
}

// The text of interp.hex and interp.lst, embedded at build time
// (sw8085/interp/embed_image.cmake).
extern const char* const kEmbeddedHex;
extern const char* const kEmbeddedLst;

const Program& Program::builtin() {
  static const Program p = from_text(kEmbeddedHex, kEmbeddedLst, "interp.hex (embedded)", "interp.lst (embedded)");
  return p;
}

std::uint16_t Program::symbol(const std::string& name) const {
  const auto it = symbols.find(name);
  if (it == symbols.end()) throw std::runtime_error("interp.lst: symbol " + name + " is missing");
  return it->second;
}

BoardBus::BoardBus(const Program& p) {
  std::copy(p.image.begin(), p.image.begin() + kRomEnd, mem.begin());
}

std::uint8_t BoardBus::read(std::uint16_t addr) {
  if (addr < kRomEnd || (addr >= kRamBase && addr < kRamEnd) || (addr >= kMailbox && addr < kMailboxEnd))
    return mem[addr];
  if (fault.empty()) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "read of unmapped address %04X", addr);
    fault = buf;
  }
  return 0xFF;
}

void BoardBus::write(std::uint16_t addr, std::uint8_t v) {
  if ((addr >= kRamBase && addr < kRamEnd) || (addr >= kMailbox && addr < kMailboxEnd)) {
    mem[addr] = v;
    return;
  }
  if (fault.empty()) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "write of %02X to %s address %04X", v, addr < kRomEnd ? "ROM" : "unmapped", addr);
    fault = buf;
  }
}

std::uint8_t BoardBus::in(std::uint8_t port) {
  if (port == kPortEdges) return edges;
  if (fault.empty()) fault = "IN from unmapped port " + std::to_string(port);
  return 0xFF;
}

void BoardBus::out(std::uint8_t port, std::uint8_t v) {
  if (port == kPortStep || port == kPortDone || port == 0x13) {
    outs.push_back({port, v});
    return;
  }
  if (fault.empty()) fault = "OUT to unmapped port " + std::to_string(port);
}

Host::Host(const Program& p, const i8085::MachineFactory& factory)
    : bus_(p), machine_(factory(bus_, i8085::Mode::i8085)), codes_(Codes::from_symbols(p.symbols)) {
  boot();
}

void Host::step_checked() {
  machine_->step();
  if (!bus_.fault.empty()) {
    char buf[32];
    std::snprintf(buf, sizeof buf, " (PC was %04X)", machine_->last().pc);
    throw std::runtime_error("sw8085: " + bus_.fault + buf);
  }
  if (machine_->last().undocumented) throw std::runtime_error("sw8085: undocumented opcode executed");
}

void Host::boot() {
  machine_->reset();
  auto mb = bus_.mailbox();
  for (int n = 0; mb[kReady] != kReadyMagic; ++n) {
    if (n > 100000) throw std::runtime_error("sw8085: the program did not become ready");
    step_checked();
  }
  if (mb[kLayout] != kLayoutVersion) throw std::runtime_error("sw8085: mailbox layout version mismatch");
  sp_idle_ = machine_->regs().sp;
  settle();
  bus_.outs.clear();
}

SlotMove Host::write(Segmenter& seg) {
  const std::uint8_t base = kSlots[next_slot_];
  auto mb = bus_.mailbox();
  SlotMove sm = seg.next(base, codes_, mb);
  mb[static_cast<std::uint8_t>(base + kStatus)] = kQueued;
  slots_[next_slot_] = sm;
  next_slot_ ^= 1;
  return sm;
}

SlotMove Host::queue(const Move& m) {
  validate<24>(m);
  const std::uint8_t base = kSlots[next_slot_];
  if (pending_)
    throw std::logic_error("sw8085: segments of " + describe(pending_->next_move()) + " still wait for a slot");
  if (!slot_free(next_slot_))
    throw std::logic_error("sw8085: slot " + std::to_string(base) + " still holds " + describe(slots_[next_slot_]->move));
  Segmenter seg(m);
  const SlotMove sm = write(seg);
  if (seg.more()) pending_.emplace(std::move(seg));
  return sm;
}

std::vector<SlotMove> Host::pump() {
  std::vector<SlotMove> w;
  while (pending_ && slot_free(next_slot_)) {
    w.push_back(write(*pending_));
    if (!pending_->more()) pending_.reset();
  }
  return w;
}

bool Host::can_queue() const { return !pending_ && slot_free(next_slot_); }

CommandResult Host::command() {
  CommandResult r;
  bus_.outs.clear();
  machine_->set_rst75(true);
  ++bus_.edges;
  bool raised = true, acked = false;
  std::uint64_t t0 = 0;
  for (int n = 0;; ++n) {
    if (n > 100000) throw std::runtime_error("sw8085: the interrupt routine did not return");
    const std::uint64_t before = machine_->tstates();
    step_checked();
    if (raised) {
      machine_->set_rst75(false);
      raised = false;
    }
    if (!acked && machine_->last().kind == i8085::StepKind::interrupt) {
      acked = true;
      t0 = before;
    } else if (acked && machine_->last().kind == i8085::StepKind::instruction) {
      ++r.instructions;
    }
    if (acked && machine_->regs().sp == sp_idle_) break;
  }
  r.tstates = static_cast<int>(machine_->tstates() - t0);
  for (const auto& w : bus_.outs) {
    if (w.port == kPortDone) r.move_ended = true;
    if (w.port != kPortStep) continue;
    if (r.pulse) throw std::runtime_error("sw8085: two step pulses for one command pulse");
    r.pulse = decode_pattern(w.value);
    if (!r.pulse) throw std::runtime_error("sw8085: OUT 10h with a bad step pattern " + std::to_string(w.value));
  }
  return r;
}

State Host::state(const SlotMove& sm, std::uint64_t pulses) const {
  auto& self = const_cast<Host&>(*this);
  return decode(sm, self.bus_.mailbox(), codes_, pulses);
}

bool Host::slot_free(int i) const {
  // A finished slot is free once the program has left it: it started the
  // other slot, or went idle (MB_ACTIVE = 0).
  const auto& held = slots_[i];
  return !held || (done(*held) && bus_.mem[kMailbox + kActive] != held->base);
}

bool Host::done(const SlotMove& sm) const {
  return codes_.is_done(bus_.mem[kMailbox + sm.base]);
}

std::uint32_t Host::overruns() const {
  const auto* mb = bus_.mem.data() + kMailbox;
  return mb[kOverruns] | mb[kOverruns + 1] << 8 | mb[kOverruns + 2] << 16;
}

std::uint16_t Host::idle_commands() const {
  const auto* mb = bus_.mem.data() + kMailbox;
  return static_cast<std::uint16_t>(mb[kIdleCount] | mb[kIdleCount + 1] << 8);
}

namespace {

// An upper bound of the pulses of a move: a line has |XE| + |YE|; an arc
// travels at most |dx| + |dy| <= 2R per quadrant, 5 quadrants.
std::uint64_t pulse_bound(const Move& m) {
  auto a = [](std::int64_t v) { return static_cast<std::uint64_t>(v < 0 ? -v : v); };
  if (!m.is_arc()) return a(m.xe) + a(m.ye);
  return 10 * (a(m.xs) + a(m.ys)) + 16;
}

}  // namespace

RunResult Host::run(const Move& m, std::vector<CommandResult>* commands, std::uint64_t max_pulses,
                    const StepFn& on_step) {
  validate<24>(m);
  RunResult r;
  if (!m.is_arc() && m.xe == 0 && m.ye == 0) {
    r.initial_state.done = true;
    r.final_state = r.initial_state;
    return r;
  }
  // A line of more than line::kSegment P steps runs as segments, queued one
  // after the other (the next one always waits in the other slot, armed by
  // the main loop: settle()); the state after a pulse is the running
  // segment's, in the whole move's terms.
  std::vector<SlotMove> segs{queue(m)};
  for (const auto& s : pump()) segs.push_back(s);
  settle();  // the main loop starts the move before the first command pulse
  r.initial_state = state(segs[0], 0);
  const std::uint64_t bound = max_pulses ? max_pulses : pulse_bound(m);
  std::uint64_t n = 0;
  for (std::size_t cur = 0; !done(segs[cur]);) {
    const CommandResult c = command();
    if (!c.pulse)
      throw std::logic_error("sw8085: command pulse " + std::to_string(n + 1) + " of " + describe(m) +
                             " gave no output pulse");
    ++n;
    r.final_state = state(segs[cur], n);
    if (on_step) on_step({*c.pulse, r.final_state});
    else r.steps.push_back({*c.pulse, r.final_state});
    if (commands) commands->push_back(c);
    if (n > bound) throw std::logic_error("sw8085: " + describe(m) + " did not end after " + std::to_string(n) + " pulses");
    // A segment that ended hands over to the next one (already waiting in
    // the other slot); its own slot is free for the one after.
    if (done(segs[cur]) && !segs[cur].last() && ++cur >= segs.size())
      throw std::logic_error("sw8085: the next segment of " + describe(m) + " was not queued");
    const auto w = pump();
    if (!w.empty()) {
      segs.insert(segs.end(), w.begin(), w.end());
      settle();  // the main loop arms it
    }
  }
  if (n == 0) r.final_state = r.initial_state;
  return r;
}

Host::Timed Host::drive(const std::vector<Move>& moves, double period, std::vector<Pulse>* pulses) {
  Timed res;
  const std::uint32_t ovr0 = overruns();
  const std::uint16_t idle0 = idle_commands();
  std::size_t next = 0;
  std::optional<SlotMove> last;
  std::uint64_t bound = 0;
  for (const auto& m : moves) bound += pulse_bound(m);
  auto feed = [&] {
    for (const auto& s : pump()) last = s;
    while (next < moves.size() && can_queue()) {
      const Move& m = moves[next++];
      if (!m.is_arc() && m.xe == 0 && m.ye == 0) continue;
      last = queue(m);
      for (const auto& s : pump()) last = s;
    }
  };
  auto count = [&] {
    for (const auto& w : bus_.outs)
      if (w.port == kPortStep) {
        ++res.pulses;
        if (pulses) {
          const auto p = decode_pattern(w.value);
          if (!p) throw std::runtime_error("sw8085: OUT 10h with a bad step pattern " + std::to_string(w.value));
          pulses->push_back(*p);
        }
      }
    bus_.outs.clear();
  };
  feed();
  double next_t = static_cast<double>(machine_->tstates()) + period;
  bool raised = false;
  bus_.outs.clear();
  while (true) {
    feed();
    if (next == moves.size() && !pending_ && (!last || done(*last))) {
      res.all_done = true;
      break;
    }
    if (res.commands > 4 * bound + 1000) break;
    if (static_cast<double>(machine_->tstates()) >= next_t) {
      machine_->set_rst75(true);
      ++bus_.edges;
      ++res.commands;
      raised = true;
      next_t += period;
    }
    step_checked();
    if (raised) {
      machine_->set_rst75(false);
      raised = false;
    }
    count();
  }
  // The last routine finishes (its MODE says done before its OUT), and a
  // command still in the latch is served.
  settle();
  count();
  res.overruns = overruns() - ovr0;
  res.idle_commands = static_cast<std::uint16_t>(idle_commands() - idle0);
  return res;
}

void Host::settle() {
  // The main loop has no HLT: settled means back in it, with no interrupt
  // taken for a while (long enough for it to start a queued move).
  std::uint64_t quiet_since = machine_->tstates();
  for (int n = 0;; ++n) {
    if (n > 1000000) throw std::runtime_error("sw8085: the program does not settle in its main loop");
    step_checked();
    if (machine_->last().kind == i8085::StepKind::interrupt || machine_->regs().sp != sp_idle_)
      quiet_since = machine_->tstates();
    else if (machine_->tstates() - quiet_since >= 400)
      return;
  }
}

RunResult ProgramEngine::run(const Move& m) { return stream(m, {}); }

RunResult ProgramEngine::stream(const Move& m, const StepFn& on_step) {
  validate<24>(m);
  Host host(Program::builtin(), factory_);
  return host.run(m, nullptr, 0, on_step);
}

}  // namespace contour::sw8085
