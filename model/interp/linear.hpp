// Paper A's linear interpolator (algebraic method), bit-accurate.
//
// Contract: docs/algorithm.md, "Linear". Registers and widths:
//   A, B   W bits   |Xe|, |Ye| (magnitudes; SX, SY are the direction signs)
//   x, y   W bits   distance travelled on each axis, 0..A and 0..B
//   D      W+1 bits two's complement, D = A*y - B*x, always in [-B, A-1]
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "interp/types.hpp"

namespace contour {

template <unsigned W = 24>
class Linear {
  static_assert(W >= 2 && W <= 30, "Linear: W must be 2..30");

 public:
  static constexpr unsigned kWidth = W;          // coordinate magnitudes
  static constexpr unsigned kDBits = W + 1;      // discriminant D
  static constexpr std::int64_t kMax = max_magnitude(W);

  // Throws InputError unless |xe|, |ye| <= 2^W - 1.
  static void validate(std::int64_t xe, std::int64_t ye) {
    check_coord(xe, "XE", W);
    check_coord(ye, "YE", W);
  }

  Linear(std::int64_t xe, std::int64_t ye) {
    validate(xe, ye);
    a_ = xe < 0 ? -xe : xe;
    b_ = ye < 0 ? -ye : ye;
    sx_ = xe < 0 ? -1 : +1;
    sy_ = ye < 0 ? -1 : +1;
    done_ = a_ == 0 && b_ == 0;
  }

  // One command pulse. Returns the output pulse, or nothing once done.
  std::optional<Pulse> step() {
    if (done_) return std::nullopt;
    // Sign of D chooses the axis (tie D = 0 moves X); an axis with no
    // distance left hands the pulse to the other one.
    bool move_x = d_ >= 0;
    if (move_x && x_ == a_) move_x = false;
    else if (!move_x && y_ == b_) move_x = true;
    Pulse p;
    if (move_x) {
      ++x_;
      d_ -= b_;
      p = Pulse{Axis::X, sx_};
    } else {
      ++y_;
      d_ += a_;
      p = Pulse{Axis::Y, sy_};
    }
    ++n_;
    if (!fits_signed(d_, kDBits)) [[unlikely]] throw_overflow("linear: D", state());
    done_ = x_ == a_ && y_ == b_;
    return p;
  }

  bool done() const { return done_; }
  std::uint64_t total_pulses() const { return static_cast<std::uint64_t>(a_ + b_); }

  State state() const {
    State s;
    s.x = sx_ * x_;
    s.y = sy_ * y_;
    s.d = d_;
    s.pulses = n_;
    s.done = done_;
    return s;
  }

 private:
  std::int64_t a_ = 0, b_ = 0;  // |Xe|, |Ye|
  std::int8_t sx_ = 1, sy_ = 1;
  std::int64_t x_ = 0, y_ = 0;  // distance travelled
  std::int64_t d_ = 0;          // discriminant
  std::uint64_t n_ = 0;
  bool done_ = false;
};

}  // namespace contour
