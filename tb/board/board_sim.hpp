// The Verilated board (rtl/board/board_top, 12 MHz, 1 Mbaud) with its
// UART at the bit level: host bytes are sent as 8N1 characters on the RX
// pin, the TX pin is decoded by a receiver of its own here (not the RTL's),
// and every rising edge of a STEP pin is recorded with the DIR pin as a
// pulse and its clock, and its high time once the pin falls. On the one
// harness base (tb/common/harness.hpp: FST on request).
//
// Faults on the wire, for the tests and `contour board-sim`: flip one bit
// of every Nth character, drop every Mth character (each way), or cut the
// host-to-board line for a while (characters sent then are lost).
#pragma once

#include <array>
#include <cstdint>
#include <deque>
#include <memory>
#include <string>
#include <vector>

#include "interp/types.hpp"
#include "link_proto.hpp"

namespace contour::board {

constexpr double kClockHz = 12e6;      // the iCEBreaker's clock
constexpr unsigned kClksPerBit = 12;   // 1 Mbaud (board_top's default)

struct StepEvent {
  std::uint64_t clock = 0;  // clock of the rising edge
  Pulse pulse;
  std::uint64_t high = 0;   // clocks the STEP pin stayed high (0: it has not fallen yet)
};

struct Faults {
  std::uint64_t flip_every = 0;   // flip a bit of every Nth character (0: none)
  std::uint64_t drop_every = 0;   // drop every Mth character (0: none)
  double cut_at_s = -1;           // host-to-board line dead from this simulated time ...
  double cut_for_s = 0;           // ... for this long
};

// The index of the step after the longest gap between two steps (where a
// hold brought the motion to rest); at least 1.
inline std::size_t after_longest_gap(const std::vector<StepEvent>& s) {
  std::size_t g = 1;
  for (std::size_t i = 1; i < s.size(); ++i)
    if (s[i].clock - s[i - 1].clock > s[g].clock - s[g - 1].clock) g = i;
  return g;
}

// The net steps per axis (X, Y, Z) the pins gave at clocks before `clock`.
std::array<std::int64_t, 3> pins_net(const std::vector<StepEvent>& steps, std::uint64_t clock = UINT64_MAX);
// Whether axis `a`'s net equals `v` at some clock in [c0, c1] (a reply's
// position, read on the board at a clock the host does not know exactly).
bool pins_net_seen(const std::vector<StepEvent>& steps, int a, std::uint64_t c0, std::uint64_t c1, std::int64_t v);

// The pulses off an output stage's timing (at most `most` described, the
// count of all in `count`): a pulse not high for exactly `len` clocks (0
// acts as 1; a pin that never fell counts), or rising less than `space`
// clocks (0 acts as 1) after the last pulse fell: of any axis (AXIS3's
// STEP_SPACE) or, with `per_axis`, of its own axis (INTERP's).
std::vector<std::string> step_timing_faults(const std::vector<StepEvent>& steps, std::uint32_t len,
                                            std::uint32_t space, bool per_axis, std::size_t& count,
                                            std::size_t most = 5);

class BoardSim {
 public:
  explicit BoardSim(std::string fst_path = "", Faults faults = {});
  ~BoardSim();
  BoardSim(const BoardSim&) = delete;
  BoardSim& operator=(const BoardSim&) = delete;

  void send(const Bytes& bytes);                 // queue host-to-board characters
  void run(std::uint64_t clocks);                // advance the board
  Bytes take_received();                         // board-to-host characters so far
  bool line_idle() const;                        // nothing queued or on the RX pin
  std::uint64_t clocks() const;
  double seconds() const { return static_cast<double>(clocks()) / kClockHz; }
  const std::vector<StepEvent>& steps() const { return steps_; }
  std::uint64_t simultaneous_steps() const { return simultaneous_; }  // two STEP edges in one clock
  bool enable_pin() const;
  std::uint64_t faults_done() const { return faults_done_; }

 private:
  struct Impl;
  void clock_rx_pin();
  void clock_tx_pin();
  void sample_steps();
  bool fault_drop(std::uint64_t n, bool to_board);
  std::uint8_t fault_flip(std::uint8_t c, std::uint64_t n);

  std::unique_ptr<Impl> impl_;
  Faults faults_;
  std::deque<std::uint8_t> tx_queue_;  // to the board
  std::uint64_t sent_ = 0, recv_ = 0, faults_done_ = 0;
  int rx_bit_ = -1;                    // bit being sent on RX (-1 idle, 0 start, 1..8 data, 9 stop)
  unsigned rx_cnt_ = 0;
  std::uint8_t rx_char_ = 0;
  int tx_bit_ = -1;                    // receiver of TX: -1 idle
  unsigned tx_cnt_ = 0;
  std::uint8_t tx_char_ = 0;
  Bytes received_;
  std::vector<StepEvent> steps_;
  std::uint8_t last_step_ = 0;
  std::array<std::size_t, 3> open_{};  // per axis: the index in steps_ of its pulse while its pin is high
  std::uint64_t simultaneous_ = 0;
};

}  // namespace contour::board
