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
    int crossings = 0;    // the contract's k at the start, 0..4
  };

  // Throws InputError naming the value and the rule unless the arc is in
  // the accepted domain (docs/algorithm.md, "Accepted arcs").
  static Plan validate(std::int64_t xs, std::int64_t ys, std::int64_t xe, std::int64_t ye, Sense s) {
    check_coord(xs, "XS", W);
    check_coord(ys, "YS", W);
    check_coord(xe, "XE", W);
    check_coord(ye, "YE", W);
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
    k_ = p.crossings;
    mag_[0] = abs64(xs);
    mag_[1] = abs64(ys);
    end_[0] = abs64(xe);
    end_[1] = abs64(ye);
    enter_quadrant(p.q_start);
  }

  // Copies rebind the cached pointers into the copy's own registers.
  Circular(const Circular& o) { *this = o; }
  Circular& operator=(const Circular& o) {
    sense_ = o.sense_;
    r2_ = o.r2_;
    k_ = o.k_;
    mag_[0] = o.mag_[0];
    mag_[1] = o.mag_[1];
    end_[0] = o.end_[0];
    end_[1] = o.end_[1];
    d_ = o.d_;
    n_ = o.n_;
    enter_quadrant(o.q_);
    return *this;
  }

  // One command pulse. Returns the output pulse, or nothing once done.
  // The common case (k > 0: not yet in the end quadrant) is kept short; the
  // end quadrant, with its end-point rule, is step_end_quadrant().
  std::optional<Pulse> step() {
    if (k_ <= 0) [[unlikely]] return step_end_quadrant();
    return d_ >= 0 ? move_inward() : move_outward();
  }

  bool done() const { return k_ < 0; }
  std::int64_t r2() const { return r2_; }

  State state() const {
    State s;
    s.x = quadrant_sign_x(q_) * mag_[0];
    s.y = quadrant_sign_y(q_) * mag_[1];
    s.d = d_;
    s.quadrant = static_cast<std::uint8_t>(q_);
    s.crossings = static_cast<std::uint8_t>(k_ < 0 ? 0 : k_);
    s.pulses = n_;
    s.done = k_ < 0;
    return s;
  }

 private:
  static constexpr std::int64_t abs64(std::int64_t v) { return v < 0 ? -v : v; }

  static constexpr std::int64_t kDHalf = std::int64_t{1} << (kDBits - 1);  // D in [-kDHalf, kDHalf)

  // D >= 0 (on or outside the circle): the inward axis, D -= 2|c|new + 1.
  Pulse move_inward() {
    const std::int64_t c = *in_;
    d_ -= 2 * c - 1;
    *in_ = c - 1;
    const Pulse p = in_pulse_;
    ++n_;
    check_d();
    if (c == 1) [[unlikely]] {  // landed on an axis: the next quadrant
      if (k_ == 0) throw_overflow("circular: k (left the end quadrant)", state());
      --k_;
      enter_quadrant(sense_ == Sense::CCW ? (q_ + 1) & 3 : (q_ + 3) & 3);
      if (k_ == 0 && mag_[0] == end_[0] && mag_[1] == end_[1]) k_ = -1;  // entered on the end point
    }
    return p;
  }

  // D < 0 (inside): the outward axis, D += 2|c|old + 1.
  Pulse move_outward() {
    const std::int64_t c = *out_;
    d_ += 2 * c + 1;
    *out_ = c + 1;
    ++n_;
    check_d();
    if (c + 1 > kMax) [[unlikely]] throw_overflow("circular: |x| or |y|", state());
    return out_pulse_;
  }

  void check_d() const {
    if (static_cast<std::uint64_t>(d_ + kDHalf) >= 2 * static_cast<std::uint64_t>(kDHalf)) [[unlikely]]
      throw_overflow("circular: D", state());
  }

  // k == 0: the end quadrant. An axis with no distance left hands the pulse
  // to the other; done (k = -1) when both have arrived.
  std::optional<Pulse> step_end_quadrant() {
    if (k_ < 0) return std::nullopt;
    const int in = in_ == &mag_[0] ? 0 : 1;
    bool inward = d_ >= 0;
    if (inward && mag_[in] == end_[in]) inward = false;
    else if (!inward && mag_[in ^ 1] == end_[in ^ 1]) inward = true;
    const Pulse p = inward ? move_inward() : move_outward();
    if (mag_[0] == end_[0] && mag_[1] == end_[1]) k_ = -1;
    return p;
  }

  // The roles of the axes are fixed within a quadrant: cache them.
  void enter_quadrant(int q) {
    q_ = q;
    const int in = inward_is_x(q, sense_) ? 0 : 1;
    in_ = &mag_[in];
    out_ = &mag_[in ^ 1];
    const std::int8_t sx = quadrant_sign_x(q), sy = quadrant_sign_y(q);
    in_pulse_ = Pulse{static_cast<Axis>(in), static_cast<std::int8_t>(-(in == 0 ? sx : sy))};
    out_pulse_ = Pulse{static_cast<Axis>(in ^ 1), in == 0 ? sy : sx};
  }

  Sense sense_ = Sense::CCW;
  std::int64_t r2_ = 0;
  int q_ = 0;
  int k_ = 0;                     // crossings left; -1 once done
  std::int64_t mag_[2] = {0, 0};  // |x|, |y|
  std::int64_t end_[2] = {0, 0};  // |xe|, |ye|
  std::int64_t* in_ = &mag_[0];   // the inward axis' magnitude
  std::int64_t* out_ = &mag_[1];  // the outward axis' magnitude
  Pulse in_pulse_;                // the pulse an inward step emits here
  Pulse out_pulse_;               // the pulse an outward step emits here
  std::int64_t d_ = 0;
  std::uint64_t n_ = 0;
};

}  // namespace contour
