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

namespace contour::rtl {

// A block as interp_core takes it (see rtl/interp/blk_prep.v).
struct Block {
  bool arc = false, cw = false, sxn = false, syn = false;
  std::uint8_t q = 0, k = 0;
  std::uint64_t xs = 0, ys = 0, xe = 0, ye = 0;  // magnitudes
};

// The field offsets of interp_core's i_blk, as functions of W: the BLK_*
// of rtl/interp/interp_block.vh (keep the two in step; the regression
// and the gate-level run fail on a mismatch).
namespace blk {
constexpr unsigned kArc = 0, kCw = 1, kSxn = 2, kSyn = 3;
constexpr unsigned kQ = 4;  // 2 bits
constexpr unsigned kK = 6;  // 3 bits
constexpr unsigned xs(unsigned) { return 9; }  // W bits each
constexpr unsigned ys(unsigned w) { return xs(w) + w; }
constexpr unsigned xe(unsigned w) { return ys(w) + w; }
constexpr unsigned ye(unsigned w) { return xe(w) + w; }
constexpr unsigned bits(unsigned w) { return ye(w) + w; }
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
    b.xs = mag(m.xs);
    b.ys = mag(m.ys);
  } else {
    b.sxn = m.xe < 0;
    b.syn = m.ye < 0;
  }
  b.xe = mag(m.xe);
  b.ye = mag(m.ye);
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
  set_bits(port, blk::xs(w), w, b.xs);
  set_bits(port, blk::ys(w), w, b.ys);
  set_bits(port, blk::xe(w), w, b.xe);
  set_bits(port, blk::ye(w), w, b.ye);
}

}  // namespace contour::rtl
