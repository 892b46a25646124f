// Paper A's linear interpolator extended to three axes (X, Y, Z), bit-accurate.
//
// Contract: docs/algorithm.md, "Linear on three axes". One command pulse gives exactly one
// output pulse on one axis; after |Xe| + |Ye| + |Ze| pulses the end point is
// reached exactly, and every point is within sqrt(3)/2 pulse of the segment.
//
// Paper A's rule (sign of D = Xe*y - Ye*x) moves the axis whose progress
// x/A or y/B is behind. On three axes that rule lets both minor axes step
// early and the path strays up to 1.23 pulses from the segment (measured),
// so linear3 compares the mid-points of the next steps, (2x+1)/A, (2y+1)/B,
// (2z+1)/C, and moves the axis whose next step is due first. Three
// discriminants, each kept by additions only:
//
//   Exy = A*(2y+1) - B*(2x+1)   >= 0: X is due no later than Y (tie: X first)
//   Exz = A*(2z+1) - C*(2x+1)   >= 0: X is due no later than Z (tie: X first)
//   Eyz = B*(2z+1) - C*(2y+1)   >= 0: Y is due no later than Z (tie: Y first)
//   initially Exy = A - B, Exz = A - C, Eyz = B - C
//
// Selection, with rX = (x < A), rY = (y < B), rZ = (z < C) ("distance left"):
//   X  if rX and (not rY or Exy >= 0) and (not rZ or Exz >= 0)
//   Y  else if rY and (not rZ or Eyz >= 0)
//   Z  otherwise
// An axis with no distance left never moves (the paper's "other axis" rule).
// Updates: X: x+1, Exy -= 2B, Exz -= 2C;  Y: y+1, Exy += 2A, Eyz -= 2C;
//          Z: z+1, Exz += 2A, Eyz += 2B.
//
// Registers and widths:
//   A, B, C        W bits   |Xe|, |Ye|, |Ze| (SX, SY, SZ are the signs)
//   x, y, z        W bits   distance travelled, 0..A, 0..B, 0..C
//   Exy, Exz, Eyz  W+2 bits two's complement; Exy in [-2B, 2A] and likewise
//                  (Exz in [-2C, 2A], Eyz in [-2C, 2B]). Checked every step.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "interp/types.hpp"

namespace contour {

// Observable state of the 3-axis interpolator after a command pulse.
struct State3 {
  std::int64_t x = 0, y = 0, z = 0;       // signed distance travelled
  std::int64_t dxy = 0, dxz = 0, dyz = 0;  // discriminants Exy, Exz, Eyz
  std::uint64_t pulses = 0;
  bool done = false;
  friend bool operator==(const State3&, const State3&) = default;
};

template <unsigned W = 24>
class Linear3 {
  static_assert(W >= 2 && W <= 30, "Linear3: W must be 2..30");

 public:
  static constexpr unsigned kWidth = W;
  static constexpr unsigned kDBits = W + 2;
  static constexpr std::int64_t kMax = max_magnitude(W);

  // Throws InputError unless |xe|, |ye|, |ze| <= 2^W - 1.
  static void validate(std::int64_t xe, std::int64_t ye, std::int64_t ze) {
    check_coord(xe, "XE", W);
    check_coord(ye, "YE", W);
    check_coord(ze, "ZE", W);
  }

  Linear3(std::int64_t xe, std::int64_t ye, std::int64_t ze) {
    validate(xe, ye, ze);
    a_ = xe < 0 ? -xe : xe;
    b_ = ye < 0 ? -ye : ye;
    c_ = ze < 0 ? -ze : ze;
    sx_ = xe < 0 ? -1 : +1;
    sy_ = ye < 0 ? -1 : +1;
    sz_ = ze < 0 ? -1 : +1;
    dxy_ = a_ - b_;
    dxz_ = a_ - c_;
    dyz_ = b_ - c_;
    done_ = a_ == 0 && b_ == 0 && c_ == 0;
  }

  // The axis the next command pulse moves (valid while !done()).
  Axis select() const {
    const bool rx = x_ < a_, ry = y_ < b_, rz = z_ < c_;
    if (rx && (!ry || dxy_ >= 0) && (!rz || dxz_ >= 0)) return Axis::X;
    if (ry && (!rz || dyz_ >= 0)) return Axis::Y;
    return Axis::Z;
  }

  // One command pulse. Returns the output pulse, or nothing once done.
  std::optional<Pulse> step() {
    if (done_) return std::nullopt;
    Pulse p;
    switch (select()) {
      case Axis::X: p = advance(x_, Pulse{Axis::X, sx_}, dxy_, -2 * b_, dxz_, -2 * c_); break;
      case Axis::Y: p = advance(y_, Pulse{Axis::Y, sy_}, dxy_, 2 * a_, dyz_, -2 * c_); break;
      case Axis::Z: p = advance(z_, Pulse{Axis::Z, sz_}, dxz_, 2 * a_, dyz_, 2 * b_); break;
    }
    ++n_;
    check_d(dxy_, "Dxy");
    check_d(dxz_, "Dxz");
    check_d(dyz_, "Dyz");
    if (x_ > a_ || y_ > b_ || z_ > c_) throw OverflowError("linear3: an axis passed its end");
    done_ = x_ == a_ && y_ == b_ && z_ == c_;
    return p;
  }

  bool done() const { return done_; }
  std::uint64_t total_pulses() const { return static_cast<std::uint64_t>(a_ + b_ + c_); }

  State3 state() const {
    State3 s;
    s.x = sx_ * x_;
    s.y = sy_ * y_;
    s.z = sz_ * z_;
    s.dxy = dxy_;
    s.dxz = dxz_;
    s.dyz = dyz_;
    s.pulses = n_;
    s.done = done_;
    return s;
  }

 private:
  // One step of an axis: its distance travelled + 1, the two discriminants
  // that involve it updated (the "Updates" above).
  static Pulse advance(std::int64_t& travelled, Pulse p, std::int64_t& d1, std::int64_t step1, std::int64_t& d2,
                       std::int64_t step2) {
    ++travelled;
    d1 += step1;
    d2 += step2;
    return p;
  }
  static void check_d(std::int64_t d, const char* name) {
    if (!fits_signed(d, kDBits))
      throw OverflowError(std::string("linear3: ") + name + " = " + std::to_string(d) + " overflows " +
                          std::to_string(kDBits) + " bits");
  }

  std::int64_t a_ = 0, b_ = 0, c_ = 0;
  std::int8_t sx_ = 1, sy_ = 1, sz_ = 1;
  std::int64_t x_ = 0, y_ = 0, z_ = 0;
  std::int64_t dxy_ = 0, dxz_ = 0, dyz_ = 0;
  std::uint64_t n_ = 0;
  bool done_ = false;
};

}  // namespace contour
