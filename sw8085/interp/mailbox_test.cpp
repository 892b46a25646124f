// mailbox.hpp against the program: every offset and constant equals the
// EQU of interp.a80 (read from the assembler's listing), and the encodings
// round-trip.
#include <gtest/gtest.h>

#include "interp/circular.hpp"
#include "interp/linear.hpp"

#include <cctype>
#include <fstream>
#include <set>
#include <sstream>

#include "sw8085/interp/host.hpp"
#include "sw8085/interp/mailbox.hpp"

namespace contour::sw8085 {
namespace {

int sym(const std::string& name) {
  // asm80 lists a negative EQU as its 16-bit two's complement.
  return static_cast<std::int16_t>(Program::builtin().symbol(name));
}

TEST(Mailbox, OffsetsAreTheProgramsEqus) {
  struct Equ {
    const char* name;
    int value;
  };
  // Grouped as the program defines them: the mailbox header and its magic
  // values, a slot, the ports, a line's block, an arc's block.
  const Equ equs[] = {
      {"MB_IDLE", kIdleMode}, {"MB_NEXT", kNext}, {"MB_ACTIVE", kActive}, {"MB_OVR", kOverruns},
      {"MB_READY", kReady}, {"MB_PEND", kPend}, {"MB_IDLECNT", kIdleCount}, {"MB_LAYOUT", kLayout},
      {"MB_STUBS", kStubs},
      {"READY_MAGIC", kReadyMagic}, {"LAYOUT_VERSION", kLayoutVersion},
      {"SLOT0", kSlots[0]}, {"SLOT1", kSlots[1]}, {"S_MODE", kMode}, {"S_STATUS", kStatus},
      {"ST_QUEUED", kQueued}, {"ST_STARTED", kStarted},
      {"PSTEP", kPortStep}, {"PEDGES", kPortEdges}, {"PDONE", kPortDone},
      {"L_D0", line::kD}, {"L_C0", line::kC[0]}, {"L_C1", line::kC[1]},
      {"L_NQ", line::kNegQ}, {"L_PATP", line::kPatP}, {"L_PATQ", line::kPatQ}, {"L_PATE", line::kPatE},
      {"L_A", line::kA},
      {"A_D0", arc::kD}, {"A_CX", arc::kCx}, {"A_CY", arc::kCy},
      {"A_N", arc::kN}, {"A_PLAST", arc::kPlast},
      {"A_PIN", arc::kPin}, {"A_POUT", arc::kPout},
  };
  for (const Equ& e : equs) EXPECT_EQ(sym(e.name), e.value) << e.name;
}

// asm80 lets a later definition replace an earlier one whose name differs
// only in case (labels are case-insensitive): that must never happen.
TEST(Mailbox, NoSymbolIsDefinedTwice) {
  std::ifstream src(std::string(SW8085_SOURCE_DIR) + "/interp.a80");
  ASSERT_TRUE(src.good());
  std::set<std::string> seen;
  std::string line;
  int n = 0;
  while (std::getline(src, line)) {
    ++n;
    if (line.empty() || line[0] == ';' || std::isspace(static_cast<unsigned char>(line[0]))) continue;
    std::string name;
    for (char c : line) {
      if (c == ':' || std::isspace(static_cast<unsigned char>(c))) break;
      name += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    }
    EXPECT_TRUE(seen.insert(name).second) << "interp.a80:" << n << ": " << name << " is defined again";
  }
  EXPECT_GT(seen.size(), 100u);
}

TEST(Mailbox, CodesAreDistinctAndDispatchable) {
  const Codes c = Codes::from_symbols(Program::builtin().symbols);
  std::set<std::uint8_t> all = {c.idle};
  for (const auto& [code, info] : c.arc) {
    EXPECT_TRUE(all.insert(code).second) << "code " << int(code) << " twice";
    EXPECT_GE(code, 1);
    EXPECT_LT(code, 0x80);  // 01h..7Fh: the dispatch's JP
  }
  EXPECT_EQ(all.size(), 1u + 2 * 14);
  // A family's code for D < 0 is its code for D >= 0 plus 3, the done codes
  // too (the program writes FIN codes as immediates with that rule).
  for (int p = 0; p < 2; ++p) EXPECT_EQ(c.fin_n[p], c.fin_p[p] + 3);
  // The stubs the program copies to kStubs end below the first slot.
  EXPECT_LE(sym("S_END") - sym("STUBS") + sym("MB_STUBS"), kSlots[0] + kSlotLow);
  EXPECT_GT(c.idle, kLayout);
}

// Distance counters across their byte boundaries: a line (v, -v) queued
// and decoded at once has x = 0, i.e. the distance left decodes back to v;
// a line of more than 65536 P steps runs as segments, and segment k
// starts at P = 65536 k (the line (v, -v) steps X first: x = -y there).
TEST(Mailbox, DistanceCountersRoundTrip) {
  const Codes c = Codes::from_symbols(Program::builtin().symbols);
  std::array<std::uint8_t, 256> mb{};
  const std::int64_t max = (std::int64_t{1} << 24) - 1;
  for (std::int64_t v : {std::int64_t{1}, std::int64_t{2}, std::int64_t{255}, std::int64_t{256}, std::int64_t{257},
                         std::int64_t{65535}, std::int64_t{65536}, std::int64_t{65537}, std::int64_t{16711680},
                         std::int64_t{16711681}, max - 1, max}) {
    const Move m = Move::line(v, -v);
    const int n = segments(m);
    EXPECT_EQ(n, (v + 65535) / 65536) << v;
    if (n > 1) {
      EXPECT_THROW(encode(m, kSlots[1], c, mb), std::logic_error) << v;
    }
    for (int k : {0, 1, n - 2, n - 1}) {
      if (k < 0 || k >= n) continue;
      const SlotMove sm = encode_segment(m, k, kSlots[1], c, mb);
      EXPECT_EQ(sm.last(), k == n - 1) << v;
      const State s = decode(sm, mb, c, 0);
      EXPECT_EQ(s.x, 65536 * k) << v << " segment " << k;
      EXPECT_EQ(s.y, -65536 * k) << v << " segment " << k;
      EXPECT_EQ(s.d, 0) << v;
      EXPECT_FALSE(s.done) << v;
    }
  }
}

// Where a line's segment starts (the D and position the host computes in
// closed form) and where the segment before it ends (its done code: the
// program skips the D update of its last pulse) are states of the model's
// walk (Linear<24>), in order; the last segment's end is the move's.
TEST(Mailbox, LineSegmentsStartOnTheModelsWalk) {
  const Codes c = Codes::from_symbols(Program::builtin().symbols);
  for (const Move& m : {Move::line(200001, -77777), Move::line(-77777, 200001), Move::line(150000, 149999),
                        Move::line(-131073, 131073), Move::line(0, -262147), Move::line(131075, 0),
                        Move::line(196608, 65536)}) {
    const int n = segments(m);
    ASSERT_GT(n, 1) << describe(m);
    Linear<24> walk(m.xe, m.ye);
    std::uint64_t pulses = 0;
    for (int k = 0; k < n; ++k) {
      std::array<std::uint8_t, 256> mb{};
      const SlotMove sm = encode_segment(m, k, kSlots[k % 2], c, mb);
      State start = decode(sm, mb, c, 0);
      // The model walks on until it is where the segment starts.
      while (!walk.done() && !(walk.state().x == start.x && walk.state().y == start.y)) walk.step(), ++pulses;
      start.pulses = pulses;
      ASSERT_EQ(start, walk.state()) << describe(m) << " segment " << k << ": got " << to_string(start);
      // That segment's own end: the slot says done.
      mb[kSlots[k % 2]] = line::done_code(kSlots[k % 2]);
      const State end = decode(sm, mb, c, 0);
      Linear<24> ahead = walk;
      std::uint64_t more = 0;
      while (!ahead.done() && !(ahead.state().x == end.x && ahead.state().y == end.y)) ahead.step(), ++more;
      State want = ahead.state();
      want.pulses = 0;
      ASSERT_EQ(end, want) << describe(m) << " end of segment " << k << ": got " << to_string(end);
      EXPECT_EQ(end.done, k == n - 1) << describe(m);
    }
  }
}

// An arc runs as segments cut from the host's own walk: each segment's
// start (decoded from its slot) is the state of the model's walk
// (Circular<24>) after the pulses of the segments before it, its last-pulse
// pattern is the model's pulse there, its end (a finished segment's
// decoding) the model's state after it, and inside a segment no pulse but
// the last one wraps a coordinate's low byte or changes q or k (what the
// program does not handle: docs/sw8085.md).
TEST(Mailbox, ArcSegmentsStartOnTheModelsWalk) {
  const Codes c = Codes::from_symbols(Program::builtin().symbols);
  const std::int64_t big = (std::int64_t{1} << 24) - 1;
  int total = 0;
  for (const Move& m : {Move::arc(300, 0, 300, 0, Sense::CCW), Move::arc(-256, 1, 1, 256, Sense::CW),
                        Move::arc(1000, 0, 0, 1000, Sense::CCW), walked_arc(big, 0, Sense::CCW, 3000),
                        walked_arc(5, -16777200, Sense::CW, 3000),
                        Move::arc(6, 0, 0, 6, Sense::CCW), Move::arc(3, 4, -4, -3, Sense::CCW)}) {
    Circular<24> walk(m.xs, m.ys, m.xe, m.ye, m.sense);
    Segmenter seg(m);
    std::uint64_t pulses = 0;
    int n = 0;
    while (seg.more()) {
      std::array<std::uint8_t, 256> mb{};
      const std::uint8_t base = kSlots[n % 2];
      const SlotMove sm = seg.next(base, c, mb);
      State start = decode(sm, mb, c, pulses);
      ASSERT_EQ(start, walk.state()) << describe(m) << " segment " << n << ": got " << to_string(start);
      const int len = mb[static_cast<std::uint8_t>(base + arc::kN)] == 0 ? 256 : mb[static_cast<std::uint8_t>(base + arc::kN)];
      ASSERT_EQ(len, sm.pulses) << describe(m);
      for (int i = 1; i <= len; ++i) {
        const State before = walk.state();
        const Pulse p = *walk.step();
        ++pulses;
        const State after = walk.state();
        if (i < len) {
          ASSERT_EQ(before.quadrant, after.quadrant) << describe(m) << " segment " << n << " pulse " << i;
          ASSERT_EQ(before.crossings, after.crossings) << describe(m) << " segment " << n << " pulse " << i;
          const auto hi = [](std::int64_t v) { return (v < 0 ? -v : v) >> 8; };
          ASSERT_EQ(hi(before.x), hi(after.x)) << describe(m) << " segment " << n << " pulse " << i;
          ASSERT_EQ(hi(before.y), hi(after.y)) << describe(m) << " segment " << n << " pulse " << i;
        } else {
          EXPECT_EQ(decode_pattern(mb[static_cast<std::uint8_t>(base + arc::kPlast)]), p) << describe(m);
        }
      }
      mb[base] = c.fin_p[0];  // the program's done code after the last pulse
      ASSERT_EQ(decode(sm, mb, c, pulses), walk.state()) << describe(m) << " end of segment " << n;
      EXPECT_EQ(sm.last(), walk.done()) << describe(m);
      ++n;
    }
    EXPECT_TRUE(walk.done()) << describe(m);
    total += n;
  }
  EXPECT_GT(total, 40);  // byte wraps, crossings, arrivals and the 256-pulse cap cut them
}

// A line's Q coordinate is read from D (D = |XE|*|y| - |YE|*|x|): a D that
// is no point of the line, at P's position, is an error, not a position.
TEST(Mailbox, LineDThatIsNoPointIsAnError) {
  const Codes c = Codes::from_symbols(Program::builtin().symbols);
  for (const Move& m : {Move::line(9, -7), Move::line(7, -9)}) {  // P = X; P = Y (axes swapped)
    std::array<std::uint8_t, 256> mb{};
    const SlotMove sm = encode(m, kSlots[0], c, mb);
    EXPECT_EQ(sm.swapped, m.ye == -9);
    const State s = decode(sm, mb, c, 0);
    EXPECT_EQ(s.x, 0);
    EXPECT_EQ(s.y, 0);
    EXPECT_EQ(s.d, 0);
    mb[kSlots[0] + line::kD] ^= 1;  // D off by one
    EXPECT_THROW(decode(sm, mb, c, 0), std::logic_error) << describe(m);
  }
}

TEST(Mailbox, PatternsDecode) {
  EXPECT_EQ(decode_pattern(pattern(Axis::X, -1)), (Pulse{Axis::X, -1}));
  EXPECT_EQ(decode_pattern(pattern(Axis::Y, +1)), (Pulse{Axis::Y, +1}));
  EXPECT_FALSE(decode_pattern(0x05).has_value());  // two step bits
  EXPECT_FALSE(decode_pattern(0x02).has_value());  // no step bit
}

}  // namespace
}  // namespace contour::sw8085
