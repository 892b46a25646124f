// Paper A's circular interpolator (algebraic method), generalised to every
// quadrant and both senses, bit-accurate.
//
// Contract: docs/algorithm.md, "Circular". Registers and widths:
//   |x|, |y|      W bits   magnitudes of the centre-relative position
//   q             2 bits   current quadrant (its signs give x, y)
//   k             3 bits   quadrant boundaries still to cross, 0..4
//   |xe|, |ye|    W bits   end point magnitudes
//   D             W+2 bits two's complement, D = x^2 + y^2 - R^2, D0 = 0
#pragma once

#include <cmath>
#include <cstdint>
#include <optional>
#include <string>

#include "interp/types.hpp"

namespace contour {

enum class Sense : std::uint8_t { CW, CCW };

// Integer ceil(sqrt(v)) for 0 <= v < 2^62.
constexpr std::int64_t isqrt_ceil(std::int64_t v) {
  if (v <= 0) return 0;
  auto r = static_cast<std::int64_t>(std::sqrt(static_cast<long double>(v)));
  while (r * r > v) --r;
  while (r * r < v) ++r;
  return r;
}

// Quadrant of a point for a sense of travel (docs/algorithm.md, table Q):
// points on an axis belong to the quadrant the motion enters. -1: origin.
constexpr int quadrant_of(std::int64_t x, std::int64_t y, Sense s) {
  if (s == Sense::CCW) {
    if (x > 0 && y >= 0) return 0;
    if (x <= 0 && y > 0) return 1;
    if (x < 0 && y <= 0) return 2;
    if (x >= 0 && y < 0) return 3;
  } else {
    if (x >= 0 && y > 0) return 0;
    if (x < 0 && y >= 0) return 1;
    if (x <= 0 && y < 0) return 2;
    if (x > 0 && y <= 0) return 3;
  }
  return -1;
}

// Signs of x and y in quadrant q (Q1..Q4 = 0..3).
constexpr std::int8_t quadrant_sign_x(int q) { return (q == 0 || q == 3) ? +1 : -1; }
constexpr std::int8_t quadrant_sign_y(int q) { return q < 2 ? +1 : -1; }
// The axis whose magnitude falls (moves towards the centre) in quadrant q.
constexpr bool inward_is_x(int q, Sense s) { return ((q & 1) == 0) != (s == Sense::CW); }

template <unsigned W = 24>
class Circular {
  static_assert(W >= 3 && W <= 30, "Circular: W must be 3..30");

 public:
  static constexpr unsigned kWidth = W;      // coordinate magnitudes
  static constexpr unsigned kDBits = W + 2;  // discriminant D
  static constexpr std::int64_t kMax = max_magnitude(W);

  // What validation derives from the inputs.
  struct Plan {
    std::int64_t r2 = 0;  // R^2 = xs^2 + ys^2
    int q_start = 0;
    int q_end = 0;
    int crossings = 0;    // k0, 0..4
  };

  // Throws InputError naming the value and the rule unless the arc is in
  // the accepted domain (docs/algorithm.md, "Accepted arcs").
  static Plan validate(std::int64_t xs, std::int64_t ys, std::int64_t xe, std::int64_t ye, Sense s) {
    check_coord(xs, "XS");
    check_coord(ys, "YS");
    check_coord(xe, "XE");
    check_coord(ye, "YE");
    Plan p;
    p.r2 = xs * xs + ys * ys;
    if (p.r2 == 0) throw InputError("zero radius: the start point (0, 0) is the centre");
    if (p.r2 < 2)
      throw InputError("radius too small: R^2 = XS^2 + YS^2 = " + std::to_string(p.r2) + ", must be >= 2");
    if (p.r2 > kMax * kMax)
      throw InputError("radius too large: R^2 = XS^2 + YS^2 = " + std::to_string(p.r2) + ", must be <= (2^" +
                       std::to_string(W) + " - 1)^2 = " + std::to_string(kMax * kMax));
    const std::int64_t de = xe * xe + ye * ye - p.r2;
    const std::int64_t band = abs64(xe) + abs64(ye);
    if (abs64(de) > band)
      throw InputError("end point (" + std::to_string(xe) + ", " + std::to_string(ye) +
                       ") is not on the circle: XE^2 + YE^2 - R^2 = " + std::to_string(de) +
                       ", allowed |XE^2 + YE^2 - R^2| <= |XE| + |YE| = " + std::to_string(band));
    p.q_start = quadrant_of(xs, ys, s);
    p.q_end = quadrant_of(xe, ye, s);
    const int fwd = s == Sense::CCW ? (p.q_end - p.q_start + 4) % 4 : (p.q_start - p.q_end + 4) % 4;
    const bool ix = inward_is_x(p.q_end, s);
    const std::int64_t in_e = abs64(ix ? xe : ye), out_e = abs64(ix ? ye : xe);
    if (fwd == 0) {
      const std::int64_t in_s = abs64(ix ? xs : ys), out_s = abs64(ix ? ys : xs);
      const bool same = xs == xe && ys == ye;
      p.crossings = (!same && in_s >= in_e && out_s <= out_e) ? 0 : 4;
    } else {
      p.crossings = fwd;
    }
    if (p.crossings > 0) {
      // The walk enters the end quadrant on an axis with an inward
      // coordinate of at least ceil(sqrt(R^2 - 1)); the end must not be
      // beyond that, or the inward axis could not reach it.
      const std::int64_t entry_min = isqrt_ceil(p.r2 - 1);
      if (in_e > entry_min)
        throw InputError("end point (" + std::to_string(xe) + ", " + std::to_string(ye) +
                         ") cannot be reached exactly: its " + (ix ? "|XE|" : "|YE|") + " = " +
                         std::to_string(in_e) + " exceeds ceil(sqrt(R^2 - 1)) = " + std::to_string(entry_min));
    }
    return p;
  }

  Circular(std::int64_t xs, std::int64_t ys, std::int64_t xe, std::int64_t ye, Sense s) : sense_(s) {
    const Plan p = validate(xs, ys, xe, ye, s);
    r2_ = p.r2;
    q_ = p.q_start;
    k_ = p.crossings;
    ax_ = abs64(xs);
    ay_ = abs64(ys);
    ex_ = abs64(xe);
    ey_ = abs64(ye);
  }

  // One command pulse. Returns the output pulse, or nothing once done.
  std::optional<Pulse> step() {
    if (done_) return std::nullopt;
    const bool ix = inward_is_x(q_, sense_);
    std::int64_t& in = ix ? ax_ : ay_;
    std::int64_t& out = ix ? ay_ : ax_;
    // Outside or on the circle (D >= 0) moves the inward axis, inside the
    // outward one. In the end quadrant an axis with no distance left hands
    // the pulse to the other.
    bool inward = d_ >= 0;
    if (k_ == 0) {
      if (inward && in == (ix ? ex_ : ey_)) inward = false;
      else if (!inward && out == (ix ? ey_ : ex_)) inward = true;
    }
    const Axis axis = (inward == ix) ? Axis::X : Axis::Y;
    const std::int8_t qs = axis == Axis::X ? quadrant_sign_x(q_) : quadrant_sign_y(q_);
    Pulse p{axis, static_cast<std::int8_t>(inward ? -qs : qs)};
    if (inward) {
      d_ -= 2 * in - 1;  // D - (2*|c|new + 1)
      --in;
      if (in == 0) {     // crossed onto the next quadrant
        q_ = sense_ == Sense::CCW ? (q_ + 1) & 3 : (q_ + 3) & 3;
        --k_;
      }
    } else {
      d_ += 2 * out + 1;  // D + (2*|c|old + 1)
      ++out;
    }
    ++n_;
    if (!fits_signed(d_, kDBits)) throw OverflowError("circular: D = " + std::to_string(d_) + " overflows");
    if (ax_ > kMax || ay_ > kMax || k_ < 0)
      throw OverflowError("circular: coordinate or crossing count out of range: " + to_string(state()));
    done_ = k_ == 0 && ax_ == ex_ && ay_ == ey_;
    return p;
  }

  bool done() const { return done_; }
  std::int64_t r2() const { return r2_; }

  State state() const {
    State s;
    s.x = quadrant_sign_x(q_) * ax_;
    s.y = quadrant_sign_y(q_) * ay_;
    s.d = d_;
    s.quadrant = static_cast<std::uint8_t>(q_);
    s.crossings_left = static_cast<std::uint8_t>(k_);
    s.pulses = n_;
    s.done = done_;
    return s;
  }

 private:
  static constexpr std::int64_t abs64(std::int64_t v) { return v < 0 ? -v : v; }
  static void check_coord(std::int64_t v, const char* name) {
    if (v > kMax || v < -kMax)
      throw InputError(std::string(name) + " = " + std::to_string(v) + " is out of range: |" + name +
                       "| must be <= 2^" + std::to_string(W) + " - 1 = " + std::to_string(kMax));
  }

  Sense sense_;
  std::int64_t r2_ = 0;
  int q_ = 0;
  int k_ = 0;
  std::int64_t ax_ = 0, ay_ = 0;  // |x|, |y|
  std::int64_t ex_ = 0, ey_ = 0;  // |xe|, |ye|
  std::int64_t d_ = 0;
  std::uint64_t n_ = 0;
  bool done_ = false;
};

}  // namespace contour
