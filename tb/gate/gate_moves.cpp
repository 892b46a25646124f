// gate_moves: the blocks of the gate-level simulation (tb/gate), as the
// host writes them into interp_core (i_blk, rtl/interp/interp_block.vh),
// one hexadecimal word per line for $readmemh.
//
//   gate_moves all 3 FILE           every move the host accepts at W = 3:
//                                   every line, every arc (both senses)
//   gate_moves random 24 N SEED FILE  N accepted moves at W = 24, seeded
//
// The host's rule decides acceptance (Circular<W>::validate, which also
// gives the start quadrant q and the crossings k). The W = 24 moves are
// kept short in pulses but not in bits: lines of at most 64 pulses, lines
// with one full-width coordinate (the testbench aborts them), arcs of a
// small radius, and arcs of a full-width radius that end a few pulses
// after their start (the end found by stepping the golden model).
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>

#include "interp/circular.hpp"
#include "interp/types.hpp"

using namespace contour;

namespace {

struct Word {
  std::uint64_t lo = 0, hi = 0;  // up to 128 bits
  void put(unsigned lsb, unsigned width, std::uint64_t v) {
    for (unsigned i = 0; i < width; ++i) {
      if (!((v >> i) & 1u)) continue;
      const unsigned b = lsb + i;
      if (b < 64) lo |= std::uint64_t{1} << b;
      else hi |= std::uint64_t{1} << (b - 64);
    }
  }
};

// The word in exactly ceil((9 + 4 W) / 4) hexadecimal digits.
void emit(FILE* f, unsigned w, const Word& b) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%016llx%016llx", (unsigned long long)b.hi, (unsigned long long)b.lo);
  const unsigned digits = (9 + 4 * w + 3) / 4;
  std::fprintf(f, "%s\n", buf + 32 - digits);
}

std::uint64_t mag(std::int64_t v) { return static_cast<std::uint64_t>(v < 0 ? -v : v); }

// BLK_* of interp_block.vh: ARC 0, CW 1, SXN 2, SYN 3, Q 4 (2), K 6 (3),
// then XS, YS, XE, YE, W bits each from bit 9.
void write_line(FILE* f, unsigned w, std::int64_t xe, std::int64_t ye) {
  Word b;
  b.put(2, 1, xe < 0);
  b.put(3, 1, ye < 0);
  b.put(9 + 2 * w, w, mag(xe));
  b.put(9 + 3 * w, w, mag(ye));
  emit(f, w, b);
}

template <unsigned W>
bool write_arc(FILE* f, std::int64_t xs, std::int64_t ys, std::int64_t xe, std::int64_t ye, Sense s) {
  typename Circular<W>::Plan p;
  try {
    p = Circular<W>::validate(xs, ys, xe, ye, s);
  } catch (const InputError&) {
    return false;
  }
  Word b;
  b.put(0, 1, 1);
  b.put(1, 1, s == Sense::CW);
  b.put(4, 2, static_cast<std::uint64_t>(p.q_start));
  b.put(6, 3, static_cast<std::uint64_t>(p.crossings));
  b.put(9, W, mag(xs));
  b.put(9 + W, W, mag(ys));
  b.put(9 + 2 * W, W, mag(xe));
  b.put(9 + 3 * W, W, mag(ye));
  emit(f, W, b);
  return true;
}

int all3(FILE* f) {
  constexpr unsigned W = 3;
  constexpr std::int64_t m = (1 << W) - 1;
  int lines = 0, arcs = 0;
  for (std::int64_t xe = -m; xe <= m; ++xe)
    for (std::int64_t ye = -m; ye <= m; ++ye) write_line(f, W, xe, ye), ++lines;
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
      write_line(f, W, sgn() * a, sgn() * b);
    } else if (kind == 1) {  // a full-width line, aborted by the testbench
      const std::int64_t a = uni(m / 2, m), b = uni(0, m);
      if (uni(0, 1)) write_line(f, W, sgn() * a, sgn() * b);
      else write_line(f, W, sgn() * b, sgn() * a);
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
