// The simulated board as a Transport, in process: writes go onto its RX
// line, a read runs the board until characters come back (or the timeout,
// in simulated seconds, passes). Its clock is the board's.
#pragma once

#include "board_sim.hpp"
#include "link_client.hpp"

namespace contour::board {

class SimTransport : public Transport {
 public:
  explicit SimTransport(BoardSim& sim) : sim_(sim) {}
  void write(const Bytes& bytes) override { sim_.send(bytes); }
  Bytes read(double timeout_s) override {
    const double until = sim_.seconds() + timeout_s;
    Bytes got;
    do {
      sim_.run(kClksPerBit * 10);
      got = sim_.take_received();
    } while (got.empty() && sim_.seconds() < until);
    return got;
  }
  double now_s() override { return sim_.seconds(); }

 private:
  BoardSim& sim_;
};

}  // namespace contour::board
