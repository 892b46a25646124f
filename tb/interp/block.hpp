// The host's block as interp_core takes it on i_blk, in C++ without
// Verilator: the fields, their offsets (the BLK_* of
// rtl/interp/interp_block.vh), what the host computes for a move
// (make_block) and the packing into a port or a word (pack_block). Used by
// the harness (core_harness.hpp) and the gate-level block writer
// (tb/gate/gate_moves.cpp).
#pragma once

#include <cstdint>
#include <type_traits>

#include "interp/circular.hpp"
#include "interp/engine.hpp"
#include "interp/hw_order.hpp"

namespace contour::rtl {

// A block as interp_core takes it (see rtl/interp/blk_prep.v).
struct Block {
  bool arc = false, cw = false, sxn = false, syn = false;
  std::uint8_t q = 0, k = 0;
  std::uint64_t ci = 0, co = 0, ti = 0, to = 0;  // magnitudes, inward/outward order (inout_order)
};

// The field offsets of interp_core's i_blk, as functions of W: the BLK_*
// of rtl/interp/interp_block.vh (keep the two in step; the regression
// and the gate-level run fail on a mismatch).
namespace blk {
constexpr unsigned kArc = 0, kCw = 1, kSxn = 2, kSyn = 3;
constexpr unsigned kQ = 4;  // 2 bits
constexpr unsigned kK = 6;  // 3 bits
constexpr unsigned ci(unsigned) { return 9; }  // W bits each
constexpr unsigned co(unsigned w) { return ci(w) + w; }
constexpr unsigned ti(unsigned w) { return co(w) + w; }
constexpr unsigned to(unsigned w) { return ti(w) + w; }
constexpr unsigned bits(unsigned w) { return to(w) + w; }
}  // namespace blk

// Sets bits [lsb, lsb + width) of a Verilated port to `value`: an integer
// port (up to 64 bits: CData .. QData) or a VlWide (32-bit words, LSW
// first).
template <class P>
void set_bits(P& port, unsigned lsb, unsigned width, std::uint64_t value) {
  for (unsigned i = 0; i < width; ++i) {
    const unsigned b = lsb + i;
    const bool one = (value >> i) & 1u;
    if constexpr (std::is_integral_v<P>) {
      const P m = static_cast<P>(P{1} << b);
      port = static_cast<P>(one ? (port | m) : (port & ~m));
    } else {
      const auto m = static_cast<std::uint32_t>(1u << (b % 32));
      port[b / 32] = one ? (port[b / 32] | m) : (port[b / 32] & ~m);
    }
  }
}

// What the host does before writing a block: validate at width W and
// derive the start quadrant and the crossings (Circular<W>::validate).
// Throws InputError for a move outside the accepted domain.
template <unsigned W>
Block make_block(const Move& m) {
  validate<W>(m);
  auto mag = [](std::int64_t v) { return static_cast<std::uint64_t>(v < 0 ? -v : v); };
  Block b;
  if (m.is_arc()) {
    const auto plan = Circular<W>::validate(m.xs, m.ys, m.xe, m.ye, m.sense);
    b.arc = true;
    b.cw = m.sense == Sense::CW;
    b.q = static_cast<std::uint8_t>(plan.q_start);
    b.k = static_cast<std::uint8_t>(plan.crossings);
  } else {
    b.sxn = m.xe < 0;
    b.syn = m.ye < 0;
  }
  const InOutMagnitudes io = inout_order(b.arc, m.sense, b.q, b.k, mag(m.xs), mag(m.ys), mag(m.xe), mag(m.ye));
  b.ci = io.ci;
  b.co = io.co;
  b.ti = io.ti;
  b.to = io.to;
  return b;
}

// The block into bits [0, blk::bits(w)) of `port`, every one of them written.
template <class P>
void pack_block(P& port, unsigned w, const Block& b) {
  set_bits(port, blk::kArc, 1, b.arc);
  set_bits(port, blk::kCw, 1, b.cw);
  set_bits(port, blk::kSxn, 1, b.sxn);
  set_bits(port, blk::kSyn, 1, b.syn);
  set_bits(port, blk::kQ, 2, b.q);
  set_bits(port, blk::kK, 3, b.k);
  set_bits(port, blk::ci(w), w, b.ci);
  set_bits(port, blk::co(w), w, b.co);
  set_bits(port, blk::ti(w), w, b.ti);
  set_bits(port, blk::to(w), w, b.to);
}

}  // namespace contour::rtl
