#include "board_sim.hpp"

#include "Vboard_top.h"
#include "harness.hpp"

namespace contour::board {

struct BoardSim::Impl : tb::Harness<Vboard_top> {
  explicit Impl(std::string fst) : tb::Harness<Vboard_top>(std::move(fst)) {}
};

std::array<std::int64_t, 3> pins_net(const std::vector<StepEvent>& steps, std::uint64_t clock) {
  std::array<std::int64_t, 3> n{};
  for (const StepEvent& e : steps) {
    if (e.clock >= clock) break;
    n[static_cast<int>(e.pulse.axis)] += e.pulse.sign;
  }
  return n;
}

bool pins_net_seen(const std::vector<StepEvent>& steps, int a, std::uint64_t c0, std::uint64_t c1, std::int64_t v) {
  std::int64_t n = pins_net(steps, c0 + 1)[a];
  if (n == v) return true;
  for (const StepEvent& e : steps) {
    if (e.clock <= c0 || static_cast<int>(e.pulse.axis) != a) continue;
    if (e.clock > c1) break;
    n += e.pulse.sign;
    if (n == v) return true;
  }
  return false;
}

std::vector<std::string> step_timing_faults(const std::vector<StepEvent>& steps, std::uint32_t len,
                                            std::uint32_t space, bool per_axis, std::size_t& count, std::size_t most) {
  const std::uint64_t high = len == 0 ? 1 : len, low = space == 0 ? 1 : space;
  std::vector<std::string> out;
  count = 0;
  std::array<const StepEvent*, 3> last_of{};  // per axis
  const StepEvent* last = nullptr;            // any axis
  for (std::size_t i = 0; i < steps.size(); ++i) {
    const StepEvent& e = steps[i];
    const auto a = static_cast<std::size_t>(e.pulse.axis);
    const StepEvent* before = per_axis ? last_of[a] : last;
    std::string what;
    if (e.high != high)
      what = "high for " + std::to_string(e.high) + " clocks (0: never fell)";
    else if (before != nullptr && e.clock < before->clock + before->high + low)
      what = "rises " + std::to_string(static_cast<std::int64_t>(e.clock - before->clock - before->high)) +
             " clocks after the last pulse" + (per_axis ? " of its axis" : "") + " fell";
    if (!what.empty() && ++count <= most)
      out.push_back("pulse " + std::to_string(i) + " (" + to_string(e.pulse) + ", clock " + std::to_string(e.clock) +
                    "): " + what + "; STEP_LEN " + std::to_string(high) + ", STEP_SPACE " + std::to_string(low));
    last_of[a] = &e;
    last = &e;
  }
  return out;
}

BoardSim::BoardSim(std::string fst_path, Faults faults)
    : impl_(std::make_unique<Impl>(std::move(fst_path))), faults_(faults) {
  impl_->top().i_rx = 1;
  impl_->hold_reset(4);
}

BoardSim::~BoardSim() = default;

void BoardSim::send(const Bytes& bytes) { tx_queue_.insert(tx_queue_.end(), bytes.begin(), bytes.end()); }

Bytes BoardSim::take_received() {
  Bytes out;
  out.swap(received_);
  return out;
}

bool BoardSim::line_idle() const { return tx_queue_.empty() && rx_bit_ < 0; }
std::uint64_t BoardSim::clocks() const { return impl_->clocks(); }
bool BoardSim::enable_pin() const { return impl_->top().o_enable; }

bool BoardSim::fault_drop(std::uint64_t n, bool to_board) {
  const double t = seconds();
  if (to_board && faults_.cut_at_s >= 0 && t >= faults_.cut_at_s && t < faults_.cut_at_s + faults_.cut_for_s)
    return true;
  return faults_.drop_every != 0 && n % faults_.drop_every == faults_.drop_every - 1;
}

std::uint8_t BoardSim::fault_flip(std::uint8_t c, std::uint64_t n) {
  if (faults_.flip_every == 0 || n % faults_.flip_every != faults_.flip_every / 2) return c;
  ++faults_done_;
  return static_cast<std::uint8_t>(c ^ (1u << (n % 8)));
}

// The host's UART: one character at a time on the RX pin, LSB first.
void BoardSim::clock_rx_pin() {
  auto& top = impl_->top();
  if (rx_bit_ < 0) {
    while (!tx_queue_.empty()) {
      const std::uint8_t c = tx_queue_.front();
      tx_queue_.pop_front();
      const std::uint64_t n = sent_++;
      if (fault_drop(n, true)) {
        ++faults_done_;
        continue;
      }
      rx_char_ = fault_flip(c, n);
      rx_bit_ = 0;
      rx_cnt_ = 0;
      break;
    }
  }
  if (rx_bit_ < 0) {
    top.i_rx = 1;
    return;
  }
  top.i_rx = rx_bit_ == 0 ? 0 : rx_bit_ == 9 ? 1 : (rx_char_ >> (rx_bit_ - 1)) & 1;
  if (++rx_cnt_ == kClksPerBit) {
    rx_cnt_ = 0;
    if (++rx_bit_ == 10) rx_bit_ = -1;
  }
}

// The host's receiver on the TX pin: a falling edge starts a character,
// each bit sampled at its middle.
void BoardSim::clock_tx_pin() {
  const bool line = impl_->top().o_tx;
  if (tx_bit_ < 0) {
    if (!line) {
      tx_bit_ = 0;
      tx_cnt_ = kClksPerBit / 2;
    }
    return;
  }
  if (--tx_cnt_ != 0) return;
  tx_cnt_ = kClksPerBit;
  if (tx_bit_ == 0) {
    tx_bit_ = line ? -1 : 1;  // a glitch is no start bit
    tx_char_ = 0;
    return;
  }
  if (tx_bit_ <= 8) {
    tx_char_ = static_cast<std::uint8_t>(tx_char_ | (line << (tx_bit_ - 1)));
    ++tx_bit_;
    return;
  }
  tx_bit_ = -1;
  const std::uint64_t n = recv_++;
  if (!line) return;  // a bad stop bit loses the character
  if (fault_drop(n, false)) {
    ++faults_done_;
    return;
  }
  received_.push_back(fault_flip(tx_char_, n));
}

void BoardSim::sample_steps() {
  const auto& top = impl_->top();
  const std::uint8_t step = top.o_step;
  const std::uint8_t rise = static_cast<std::uint8_t>(step & ~last_step_);
  const std::uint8_t fall = static_cast<std::uint8_t>(last_step_ & ~step);
  last_step_ = step;
  for (std::size_t a = 0; a < 3; ++a)
    if ((fall >> a) & 1) steps_[open_[a]].high = impl_->clocks() - steps_[open_[a]].clock;
  if (!rise) return;
  int n = 0;
  for (std::size_t a = 0; a < 3; ++a) {
    if (!((rise >> a) & 1)) continue;
    ++n;
    const bool neg = (top.o_dir >> a) & 1;
    open_[a] = steps_.size();
    steps_.push_back({impl_->clocks(), Pulse{static_cast<Axis>(a), static_cast<std::int8_t>(neg ? -1 : +1)}, 0});
  }
  if (n > 1) ++simultaneous_;
}

void BoardSim::run(std::uint64_t clocks) {
  for (std::uint64_t i = 0; i < clocks; ++i) {
    clock_rx_pin();
    impl_->tick();
    clock_tx_pin();
    sample_steps();
  }
}

}  // namespace contour::board
