// sw8085_routines: every command pulse's routine length (T-states, RST 7.5
// acknowledge to the end of its RET, as `contour table1` measures it) over
// a set of arcs, as a histogram "T count": every accepted arc between points
// with coordinates <= 9 in both senses, full circles of R = 1..300, and
// 24-bit arcs near the axes and the diagonals (byte wraps, crossings with
// 24-bit values). With the argument `table1`: the 8 arcs of `contour
// table1`'s standard set instead (table1_moves.hpp). The figures of
// docs/sw8085.md's per-routine table.
#include <cstdio>
#include <map>
#include <string>

#include "interp/circular.hpp"
#include "interp/engine.hpp"
#include "sw8085/interp/host.hpp"
#include "sw8085/interp/table1_moves.hpp"

using namespace contour;

namespace {
bool accepted(const Move& m) {
  try {
    validate<24>(m);
    return true;
  } catch (const InputError&) {
    return false;
  }
}
}  // namespace

int main(int argc, char** argv) {
  std::vector<Move> moves;
  const std::int64_t big = (std::int64_t{1} << 24) - 1;
  if (argc > 1 && std::string(argv[1]) == "table1") {
    moves = sw8085::table1_arcs();
  } else {
  for (int xs = -9; xs <= 9; ++xs)
    for (int ys = -9; ys <= 9; ++ys)
      for (int xe = -10; xe <= 10; ++xe)
        for (int ye = -10; ye <= 10; ++ye)
          for (Sense s : {Sense::CCW, Sense::CW}) {
            const Move m = Move::arc(xs, ys, xe, ye, s);
            if (accepted(m)) moves.push_back(m);
          }
  for (int r = 2; r <= 300; ++r) moves.push_back(Move::arc(r, 0, r, 0, r % 2 ? Sense::CW : Sense::CCW));
  for (Sense s : {Sense::CCW, Sense::CW})
    for (auto [xs, ys] : {std::pair<std::int64_t, std::int64_t>{big, 0}, {0, big}, {-big, 3}, {5, -big},
                          {11863282, 11863282}, {-16777000, 2700}, {300, 16777000}, {-11863282, -11863282}})
      if (xs * xs + ys * ys <= big * big) moves.push_back(walked_arc(xs, ys, s, 3000));
  }
  std::map<int, std::uint64_t> hist;
  sw8085::Host host;
  for (const auto& m : moves) {
    std::vector<sw8085::CommandResult> cs;
    host.run(m, &cs);
    for (const auto& c : cs) ++hist[c.tstates];
  }
  std::printf("# %zu arcs\n", moves.size());
  for (const auto& [t, n] : hist) std::printf("%d %llu\n", t, static_cast<unsigned long long>(n));
}
