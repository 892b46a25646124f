// gate_moves: the blocks of the gate-level simulation (tb/gate), as the
// host writes them into interp_core (i_blk, rtl/interp/interp_block.vh),
// one hexadecimal word per line for $readmemh.
//
//   gate_moves all 3 FILE           every move the host accepts at W = 3:
//                                   every line, every arc (both senses)
//   gate_moves random 24 N SEED FILE  N accepted moves at W = 24, seeded
//
// The host's rule decides acceptance and gives the block (rtl::make_block
// of tb/interp/block.hpp: the start quadrant q and the crossings k from
// Circular<W>::validate, the layout of interp_block.vh). The W = 24 moves are
// kept short in pulses but not in bits: lines of at most 64 pulses, lines
// with one full-width coordinate (the testbench aborts them), arcs of a
// small radius, and arcs of a full-width radius that end a few pulses
// after their start (the end found by stepping the golden model).
#include <array>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>

#include "block.hpp"
#include "interp/circular.hpp"
#include "interp/types.hpp"

using namespace contour;

namespace {

// A block word of up to 128 bits, 32-bit words least significant first
// (as Verilator's wide ports, so pack_block writes it the same way).
using Word = std::array<std::uint32_t, 4>;

// The word in exactly ceil(blk::bits(W) / 4) hexadecimal digits.
void emit(FILE* f, unsigned w, const Word& b) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%08x%08x%08x%08x", b[3], b[2], b[1], b[0]);
  const unsigned digits = (rtl::blk::bits(w) + 3) / 4;
  std::fprintf(f, "%s\n", buf + 32 - digits);
}

// The move's block as the host makes it (rtl::make_block: the host's
// validation gives q and k); false when the host refuses the move.
template <unsigned W>
bool write_move(FILE* f, const Move& m) {
  rtl::Block blk;
  try {
    blk = rtl::make_block<W>(m);
  } catch (const InputError&) {
    return false;
  }
  Word word{};
  rtl::pack_block(word, W, blk);
  emit(f, W, word);
  return true;
}

template <unsigned W>
void write_line(FILE* f, std::int64_t xe, std::int64_t ye) {
  write_move<W>(f, Move::line(xe, ye));
}

template <unsigned W>
bool write_arc(FILE* f, std::int64_t xs, std::int64_t ys, std::int64_t xe, std::int64_t ye, Sense s) {
  return write_move<W>(f, Move::arc(xs, ys, xe, ye, s));
}

int all3(FILE* f) {
  constexpr unsigned W = 3;
  constexpr std::int64_t m = (1 << W) - 1;
  int lines = 0, arcs = 0;
  for (std::int64_t xe = -m; xe <= m; ++xe)
    for (std::int64_t ye = -m; ye <= m; ++ye) write_line<W>(f, xe, ye), ++lines;
  for (std::int64_t xs = -m; xs <= m; ++xs)
    for (std::int64_t ys = -m; ys <= m; ++ys)
      for (std::int64_t xe = -m; xe <= m; ++xe)
        for (std::int64_t ye = -m; ye <= m; ++ye)
          for (Sense s : {Sense::CCW, Sense::CW}) arcs += write_arc<W>(f, xs, ys, xe, ye, s);
  std::fprintf(stderr, "gate_moves: W = 3: %d lines, %d arcs\n", lines, arcs);
  return 0;
}

int random24(FILE* f, int n, unsigned seed) {
  constexpr unsigned W = 24;
  constexpr std::int64_t m = (std::int64_t{1} << W) - 1;
  std::mt19937_64 rng(seed);
  auto uni = [&](std::int64_t lo, std::int64_t hi) {
    return std::uniform_int_distribution<std::int64_t>(lo, hi)(rng);
  };
  auto sgn = [&] { return uni(0, 1) ? 1 : -1; };
  int made = 0, kinds[4] = {0, 0, 0, 0};
  while (made < n) {
    // 3 in 10 short lines, 1 in 10 full-width lines, 3 small arcs, 3 big.
    static constexpr int kKind[10] = {0, 0, 0, 1, 2, 2, 2, 3, 3, 3};
    const int kind = kKind[uni(0, 9)];
    if (kind == 0) {  // a short line
      const std::int64_t a = uni(0, 40), b = uni(0, 64 - a);
      write_line<W>(f, sgn() * a, sgn() * b);
    } else if (kind == 1) {  // a full-width line, aborted by the testbench
      const std::int64_t a = uni(m / 2, m), b = uni(0, m);
      if (uni(0, 1)) write_line<W>(f, sgn() * a, sgn() * b);
      else write_line<W>(f, sgn() * b, sgn() * a);
    } else {
      const Sense s = uni(0, 1) ? Sense::CW : Sense::CCW;
      std::int64_t xs, ys;
      if (kind == 2) {  // a small radius: whole quadrant crossings
        xs = uni(-12, 12), ys = uni(-12, 12);
      } else {  // a full-width radius, near the limit
        const std::int64_t big = uni(m / 2, m / 4 * 3), small = uni(0, m / 2);
        xs = sgn() * (uni(0, 1) ? big : small);
        ys = sgn() * (std::abs(xs) == big ? small : big);
      }
      if (xs * xs + ys * ys < 2) continue;
      // The end: the golden model stepped from the start, once round the
      // circle at most (k = 4 from start == end) for a few pulses.
      std::int64_t xe = xs, ye = ys;
      try {
        Circular<W> c(xs, ys, xs, ys, s);
        const std::int64_t steps = uni(1, kind == 2 ? 120 : 60);
        for (std::int64_t i = 0; i < steps && !c.done(); ++i) c.step();
        xe = c.state().x, ye = c.state().y;
      } catch (const InputError&) {
        continue;
      }
      if (!write_arc<W>(f, xs, ys, xe, ye, s)) continue;
    }
    ++kinds[kind];
    ++made;
  }
  std::fprintf(stderr, "gate_moves: W = 24, seed %u: %d short lines, %d full-width lines, %d small arcs, %d full-width arcs\n",
               seed, kinds[0], kinds[1], kinds[2], kinds[3]);
  return 0;
}

[[noreturn]] void usage() {
  std::fprintf(stderr, "usage: gate_moves all 3 FILE | gate_moves random 24 N SEED FILE\n");
  std::exit(2);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 4) usage();
  const std::string mode = argv[1], w = argv[2];
  const char* path = argv[argc - 1];
  if (!((mode == "all" && w == "3" && argc == 4) || (mode == "random" && w == "24" && argc == 6))) usage();
  FILE* f = std::fopen(path, "w");
  if (!f) {
    std::fprintf(stderr, "gate_moves: cannot write %s\n", path);
    return 1;
  }
  const int rc = mode == "all" ? all3(f) : random24(f, std::atoi(argv[3]), static_cast<unsigned>(std::strtoul(argv[4], nullptr, 10)));
  return std::fclose(f) == 0 ? rc : 1;
}
