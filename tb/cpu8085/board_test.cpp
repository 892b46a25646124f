// The board (rtl/board8085, docs/board8085.md) Verilated, in lockstep with
// the ISS running on a C++ model of the same memory map and ports, on
// programs/board_test.a80: command pulses on i_cmd (RST 7.5) produce step
// pulses, mailbox reports and the done flag. Every step compares the CPU
// state, T-states, writes and the step pulses; the host read port is checked
// against the model's mailbox all along.
#include <gtest/gtest.h>

#include <array>
#include <deque>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "Vboard8085.h"
#include "i8085/cpu.hpp"
#include "i8085/hex.hpp"
#include "i8085/machine.hpp"
#include "debug_ports.hpp"
#include "harness.hpp"
#include "lockstep.hpp"

#ifndef BOARD_TEST_HEX
#error "BOARD_TEST_HEX and BOARD_TEST_MEMH are set by tb/cpu8085/CMakeLists.txt"
#endif

namespace cpu8085::tb {
namespace {

struct Pulses {
  std::array<int, 3> pos{}, neg{};  // X Y Z
  friend bool operator==(const Pulses&, const Pulses&) = default;
};

// The board's map for the ISS: what docs/board8085.md says, written again.
class BoardModel : public i8085::Bus {
 public:
  std::uint8_t read(std::uint16_t a) override {
    if (a < 0x2000) return rom[a];
    if (a >= 0x2000 && a < 0x2800) return ram[a - 0x2000];
    if ((a >> 8) == 0x30) return mbx[a & 0xFF];
    return 0xFF;
  }
  void write(std::uint16_t a, std::uint8_t v) override {
    log.push_back({false, a, v});
    if (a >= 0x2000 && a < 0x2800) ram[a - 0x2000] = v;
    else if ((a >> 8) == 0x30) mbx[a & 0xFF] = v;
  }
  std::uint8_t in(std::uint8_t port) override { return port == 0x11 ? cmd_edges : 0xFF; }
  void out(std::uint8_t port, std::uint8_t v) override {
    log.push_back({true, port, v});
    if (port == 0x10) {
      for (int axis = 0; axis < 3; ++axis) {
        const bool neg = (v >> (2 * axis + 1)) & 1;
        dir[static_cast<std::size_t>(axis)] = neg;
        if ((v >> (2 * axis)) & 1) ++(neg ? pulses.neg : pulses.pos)[static_cast<std::size_t>(axis)];
      }
    } else if (port == 0x12) {
      done = v;
    } else if (port == 0x13) {
      debug = v;
    }
  }
  std::uint8_t inta() override { return 0xFF; }

  std::array<std::uint8_t, 0x2000> rom{};
  std::array<std::uint8_t, 0x800> ram{};
  std::array<std::uint8_t, 0x100> mbx{};
  std::uint8_t cmd_edges = 0, done = 0, debug = 0;
  std::array<bool, 3> dir{};
  Pulses pulses;
  std::vector<Access> log;
};

// The Verilated board on the harness base, stepped one CPU unit at a time;
// its ROM comes from the plusarg +rom= (the board's own loader).
class BoardSim : public contour::tb::Harness<Vboard8085> {
 public:
  explicit BoardSim(const std::string& memh) : Harness("", "board", {"+rom=" + memh}) {
    top().i_intr_vec = 0xFF;
    hold_reset(1);
  }

  // Runs one unit. A host write given here is applied in its first clock;
  // host_raddr is read in the first clock and returned in `host_rdata`.
  int step(bool host_we, std::uint8_t waddr, std::uint8_t wdata, std::uint8_t raddr) {
    log.clear();
    int t = 0;
    top().i_host_we = host_we;
    top().i_host_addr = host_we ? waddr : raddr;
    top().i_host_wdata = wdata;
    do {
      clock_low();
      record_write();
      clock_high();
      ++t;
      if (t == 1) {
        if (!host_we) host_rdata = top().o_host_rdata;
        top().i_host_we = 0;
      }
      count_steps();
    } while (!top().o_retire);
    tstates += static_cast<std::uint64_t>(t);
    return t;
  }

  i8085::Regs regs() const {
    return regs_of(top().o_dbg_regs, static_cast<std::uint16_t>(top().o_dbg_sp),
                   static_cast<std::uint16_t>(top().o_dbg_pc));
  }

  std::vector<Access> log;
  Pulses pulses;
  std::uint64_t tstates = 0;
  std::uint8_t host_rdata = 0;

 private:
  void record_write() {
    if (!top().o_cpu_wr) return;
    const bool io = top().o_cpu_io != 0;
    const auto addr = static_cast<std::uint16_t>(io ? top().o_cpu_addr & 0xFF : top().o_cpu_addr);
    log.push_back({io, addr, top().o_cpu_dout});
  }

  void count_steps() {
    const std::array<bool, 3> step = {top().o_step_x != 0, top().o_step_y != 0, top().o_step_z != 0};
    const std::array<bool, 3> neg = {top().o_dir_x != 0, top().o_dir_y != 0, top().o_dir_z != 0};
    for (std::size_t axis = 0; axis < 3; ++axis)
      if (step[axis]) ++(neg[axis] ? pulses.neg : pulses.pos)[axis];
  }
};

// The host's side of the test: the move's two mailbox writes, then reads
// of the report bytes; command pulses high for one step every ~400
// T-states until seven are sent.
struct HostScript {
  const std::vector<std::pair<std::uint8_t, std::uint8_t>> writes = {{0x00, 0x0D}, {0x01, 7}};
  std::size_t next_write = 0;
  bool cmd = false;
  int pulses_sent = 0;
  std::uint64_t next_pulse = 400;

  void next_command(std::uint64_t tstates, BoardModel& model) {
    if (cmd) {
      cmd = false;
    } else if (pulses_sent < 7 && tstates >= next_pulse) {
      cmd = true;
      ++pulses_sent;
      ++model.cmd_edges;
      next_pulse = tstates + 400;
    }
  }
};

// What differs between the ISS on the model and the board after a step
// ("" when nothing does).
std::string first_difference(const i8085::Machine& iss, const BoardModel& model, const BoardSim& rtl,
                             bool host_wrote, std::uint8_t expect_host) {
  auto sorted = [](std::vector<Access> v) {
    std::stable_sort(v.begin(), v.end());
    return v;
  };
  if (iss.tstates() != rtl.tstates) return "cumulative T-states";
  if (!(iss.regs() == rtl.regs())) return "registers";
  if (sorted(model.log) != sorted(rtl.log)) return "memory / port writes";
  if (!(model.pulses == rtl.pulses)) return "step pulses";
  if (!host_wrote && rtl.host_rdata != expect_host) return "host read of the mailbox";
  return "";
}

TEST(Board, CommandPulsesStepsMailboxAndDoneInLockstep) {
  BoardModel model;
  const i8085::HexImage img = i8085::read_hex_file(BOARD_TEST_HEX);
  std::array<std::uint8_t, 65536> image{};
  image.fill(0xFF);
  img.load_into(image);
  std::copy(image.begin(), image.begin() + 0x2000, model.rom.begin());
  auto iss = i8085::make_iss(model, i8085::Mode::i8085);
  BoardSim rtl(BOARD_TEST_MEMH);

  // The move: 7 pulses, each X+ step with Y- step (bits 0, 2, 3).
  HostScript host;
  std::deque<std::string> context;
  for (int n = 0; n < 20000 && !(model.done == 1 && host.pulses_sent == 7 && iss->halted()); ++n) {
    // Host: the move parameters, one write per step; a read otherwise.
    const bool we = host.next_write < host.writes.size();
    const auto [wa, wd] = we ? host.writes[host.next_write++] : std::pair<std::uint8_t, std::uint8_t>{0, 0};
    if (we) model.mbx[wa] = wd;
    const std::uint8_t ra = static_cast<std::uint8_t>(0x80 + n % 4);
    const std::uint8_t expect_host = model.mbx[ra];
    host.next_command(iss->tstates(), model);
    iss->set_rst75(host.cmd);
    rtl.top().i_cmd = host.cmd;

    model.log.clear();
    iss->step();
    rtl.step(we, wa, wd, ra);
    const std::string line = i8085::trace_line(iss->last(), iss->regs());
    const std::string what = first_difference(*iss, model, rtl, we, expect_host);
    if (!what.empty()) {
      std::string ctx;
      for (const auto& c : context) ctx += "    " + c + "\n";
      FAIL() << "board divergence at step " << n << ": " << what << "\n" << ctx << "  ISS: " << line
             << "\n  RTL: T=" << rtl.tstates << " PC=" << std::hex << rtl.regs().pc;
    }
    context.push_back(line);
    if (context.size() > 8) context.pop_front();
  }
  // What the program must have done, from its source and the board map.
  EXPECT_EQ(host.pulses_sent, 7);
  EXPECT_EQ(rtl.pulses.pos[0], 7);  // X+ every pulse
  EXPECT_EQ(rtl.pulses.neg[1], 7);  // Y- every pulse
  EXPECT_EQ(rtl.pulses.pos[1] + rtl.pulses.neg[0] + rtl.pulses.pos[2] + rtl.pulses.neg[2], 0);
  EXPECT_EQ(rtl.top().o_done, 1);
  EXPECT_EQ(rtl.top().o_debug, 7);
  EXPECT_EQ(rtl.top().o_dir_y, 1);
  EXPECT_EQ(rtl.top().o_dir_x, 0);
  EXPECT_EQ(model.mbx[0x80], 7);  // STATUS
  EXPECT_EQ(model.mbx[0x81], 7);  // EDGES: IN 11h counted every pulse
  EXPECT_EQ(model.mbx[0x82], image[0x0100]);  // the ROM ignored the write
  EXPECT_NE(model.mbx[0x82], 0x55);
  EXPECT_EQ(model.mbx[0x83], 0xFF);  // unmapped read
  EXPECT_EQ(rtl.top().o_host_overrun, 0);
}

}  // namespace
}  // namespace cpu8085::tb
