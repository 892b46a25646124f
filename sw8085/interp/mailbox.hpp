// The mailbox of sw8085/interp/interp.a80: 256 bytes of RAM at 0x3000 that
// the host and the 8085 share (docs/sw8085.md is the prose version; the
// offsets here must equal the EQUs of interp.a80, which a test checks
// against the assembler's listing).
//
// The host writes a move into one of two slots in the program's working
// format (magnitudes, signs as OUT patterns, q, k, the distance counters and
// D = 0), then marks the slot queued; the program starts it on the next
// command pulse and works on it in place, so the slot IS the published
// state after every pulse. The MODE byte at the slot's base is both the
// program's dispatch code and the sign of D.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <span>
#include <string>

#include "interp/engine.hpp"
#include "interp/types.hpp"

namespace contour::sw8085 {

// Board map (docs/board8085.md).
inline constexpr std::uint16_t kRomEnd = 0x2000;
inline constexpr std::uint16_t kRamBase = 0x2000, kRamEnd = 0x2800;
inline constexpr std::uint16_t kMailbox = 0x3000, kMailboxEnd = 0x3100;
inline constexpr std::uint8_t kPortStep = 0x10;   // OUT: bit0 X step, bit1 X dir, bit2 Y step, bit3 Y dir
inline constexpr std::uint8_t kPortEdges = 0x11;  // IN: rising edges of the command input, mod 256
inline constexpr std::uint8_t kPortDone = 0x12;   // OUT: a move finished (the slot base)

// Header (offsets in the mailbox).
inline constexpr std::uint8_t kIdleMode = 0x00;   // MODE of the idle pseudo-slot
inline constexpr std::uint8_t kNext = 0x01;       // base of the slot the program starts next
inline constexpr std::uint8_t kActive = 0x02;     // base of the slot in use (0: idle, none)
inline constexpr std::uint8_t kPend = 0x03;       // base of the slot armed to start next, 0: none
inline constexpr std::uint8_t kOverruns = 0x04;   // 3 bytes, little endian: command pulses lost
inline constexpr std::uint8_t kReady = 0x07;      // kReadyMagic once initialised
inline constexpr std::uint8_t kIdleCount = 0x08;  // 2 bytes: command pulses served with no move
inline constexpr std::uint8_t kLayout = 0x0A;     // kLayoutVersion
inline constexpr std::uint8_t kStubs = 0x0B;      // the program's dispatch stubs (JMPs), up to the slots
inline constexpr std::uint8_t kReadyMagic = 0x5A;
inline constexpr std::uint8_t kLayoutVersion = 8;
// The routine that ends a move reads PEND and writes ACTIVE with one DCR L.
static_assert(kActive + 1 == kPend, "interp.a80 FINISH: MB_ACTIVE must be MB_PEND - 1");

// Slots: a slot spans base+kSlotLow .. base+kStatus.
inline constexpr std::array<std::uint8_t, 2> kSlots = {0x80, 0xC0};
inline constexpr int kSlotLow = -6;
inline constexpr int kMode = 0x00;
inline constexpr int kStatus = 0x38;  // host: kQueued; program: kStarted
inline constexpr std::uint8_t kQueued = 0x01, kStarted = 0x02;

// Line slot: offsets from the base. A line with both axes moving is stored
// with its axes ordered: P is the axis the program steps when D >= 0 and
// the one whose last step ends the move (X when |YE| < |XE|), Q the other.
// If P is Y the axes are swapped and the program's D is -D - 1 (so that
// D >= 0, the tie included, still steps X). Only P has a distance counter;
// Q's position follows from D: D = |XE|*|y| - |YE|*|x|. A line with one
// axis moving is stored as a line whose P and Q are that axis (the same
// pattern, |P| = |Q| = 1): the program's D goes 0, -1, 0, ... and P counts
// every other pulse (the contract's D stays 0).
namespace line {
// P's distance counter in the slot: two bytes c0 c1 counting down like
// nested loops (a stored 0 counts as 256): left = c0 + 256*(c1 - 1), at most
// kSegment, 0 when both bytes are 0 (the last pulse of the slot's move). A
// line of more than kSegment P steps runs as segments of at most kSegment
// P steps, each queued as a move of its own in the next slot and started
// from the contract's D and position where it begins (encode_segment).
inline constexpr std::array<int, 2> kC = {-1, -2};
inline constexpr std::int64_t kSegment = 65536;
inline constexpr int kNegQ = -3;    // 3 bytes DOWNWARDS (-3, -4, -5): -|Q| mod 2^24
inline constexpr int kPatP = -6;    // P's pattern
inline constexpr int kD = 0x01;     // 3 bytes; sign in MODE (0xFF: D >= 0, 0x00: D < 0)
inline constexpr int kPatQ = 0x04;  // Q's pattern
inline constexpr int kPatE = 0x0C;  // P's pattern, for the slot's last pulse
inline constexpr int kA = 0x10;     // 3 bytes: |P|
inline constexpr std::uint8_t kModeNonNeg = 0xFF, kModeNeg = 0x00;
// A finished line's MODE: its slot's base + 1 (the OUT 12h byte; no arc
// code has bit 7 set).
constexpr std::uint8_t done_code(std::uint8_t base) { return static_cast<std::uint8_t>(base + 1); }
}  // namespace line

// Arc slot: one segment of an arc. The host runs every arc as segments
// (Segmenter): a segment ends on the pulse where a coordinate's low byte
// would wrap, an inward coordinate land on 0 (a quadrant crossing), an
// axis arrive at its end in the end quadrant (the switch to a forced
// family), the move end, or after kSegmentPulses pulses; that last pulse
// goes out from kPlast with no update, and the next segment starts from
// the contract's state after it. Inside a segment the quadrant, k and the
// family are fixed and a step changes byte 0 of its coordinate only.
namespace arc {
inline constexpr int kN = -1;                 // pulses left in the segment (0: 256), counted by the dispatch
inline constexpr int kPin = -2, kPout = -3;   // the quadrant's OUT patterns
inline constexpr int kPlast = -4;             // the segment's last pulse
inline constexpr int kD = 0x01;    // D', 3 bytes; its sign and p (D = 2*D' + p) from MODE
inline constexpr int kCx = 0x07, kCy = 0x0D;  // 3 bytes each
inline constexpr int kSegmentPulses = 256;
}  // namespace arc

// The MODE codes: assigned by the assembler (C_xxx in interp.a80), read from
// its listing. Arc codes come in two blocks, for p = 0 and p = 1 (D = 2*D' + p).
struct Codes {
  struct ArcCode {
    bool neg = false;  // D < 0
    int parity = 0;    // p
    bool done = false;
  };
  std::uint8_t idle = 0;
  std::array<std::uint8_t, 2> fin_p{}, fin_n{};
  std::map<std::string, std::array<std::uint8_t, 2>> named;  // "AIX" -> {C_AIX0, C_AIX1}, ...
  std::map<std::uint8_t, ArcCode> arc;                        // every arc code (FIN included)
  // The code of an arc mode ("AIX", "FOYP", ...) for parity p.
  std::uint8_t code(const std::string& name, int p) const;
  bool is_done(std::uint8_t mode) const {
    return mode == fin_p[0] || mode == fin_p[1] || mode == fin_n[0] || mode == fin_n[1] ||
           mode == line::done_code(kSlots[0]) || mode == line::done_code(kSlots[1]);
  }
  // From the listing's symbol table; throws std::runtime_error naming a
  // missing symbol.
  static Codes from_symbols(const std::map<std::string, std::uint16_t>& symbols);
};

// OUT 10h pattern of a pulse on an axis in a direction.
constexpr std::uint8_t pattern(Axis a, int sign) {
  return a == Axis::X ? std::uint8_t(0x01 | (sign < 0 ? 0x02 : 0)) : std::uint8_t(0x04 | (sign < 0 ? 0x08 : 0));
}

// The pulse an OUT 10h value stands for; nothing if it is not exactly one
// step bit.
std::optional<Pulse> decode_pattern(std::uint8_t v);

// What the host keeps about a queued move to decode its published state.
struct SlotMove {
  Move move;
  std::uint8_t base = 0;
  bool arc = false;
  std::int8_t sx = 1, sy = 1;  // line: signs
  std::int64_t a = 0, b = 0;   // line: |XE|, |YE|
  bool swapped = false;        // line: P is Y (the program's D is -D - 1)
  // line: the P steps of the whole move, and the segment of them this slot
  // runs (the whole move unless it has more than line::kSegment).
  std::int64_t psteps = 0, seg_first = 0, seg_len = 0;
  int segment = 0, segments = 1;  // segments: a line's (an arc's count is not known ahead)
  bool last_segment = true;
  // arc: the segment's quadrant and crossings left (fixed in a segment), its
  // pulses, and the state after its last pulse (the host's walk).
  int q = 0, k = 0, pulses = 0;
  State end{};
  bool last() const { return last_segment; }
};

// How many slots a line takes: a line of more than line::kSegment P steps
// runs as ceil(P steps / kSegment) segments, a shorter one as one. An arc
// runs as segments too (Segmenter), how many is known only by walking it:
// throws std::logic_error for an arc.
int segments(const Move& m);

// The host's own walk of an arc (the contract's step rule, docs/algorithm.md,
// written again here: the model is the tests' oracle), from which it cuts
// the arc into segments.
struct ArcWalk {
  std::int64_t ax = 0, ay = 0, ex = 0, ey = 0, d = 0;
  int q = 0, k = 0;
  bool cw = false, done = false;
  bool in_x() const { return ((q & 1) == 0) != cw; }
  // 0: the sign rule; 1: only inward (the outward axis at its end); 2: only outward.
  int family() const;
  State state() const;
  struct Step {
    Pulse pulse;
    std::int64_t before = 0, after = 0;  // the stepped magnitude
  };
  Step step();
};

// The slot writes a move runs as, in order: a line's segments
// (encode_segment), or an arc's, cut from the host's walk.
class Segmenter {
 public:
  explicit Segmenter(const Move& m);  // validated, not done at once
  bool more() const { return more_; }
  const Move& next_move() const { return m_; }
  // Writes the next segment into the slot at `base`, status not yet queued.
  SlotMove next(std::uint8_t base, const Codes& codes, std::span<std::uint8_t, 256> mb);

 private:
  Move m_;
  int segment_ = 0;
  bool more_ = true;
  ArcWalk walk_;
};

// Writes `m` (already validated, not done at once) into the slot at `base`
// of the mailbox, status not yet queued. Returns what decode() needs.
// Throws std::logic_error for a move of more than one segment (every arc
// of more than one: use Segmenter).
SlotMove encode(const Move& m, std::uint8_t base, const Codes& codes, std::span<std::uint8_t, 256> mb);
// The same for segment `segment` (0 .. segments(m) - 1) of a line `m`: a
// line's segment starts from the D and the position the contract's walk has
// after the last P step of the segments before it (computed in closed
// form). For an arc, Segmenter's write number `segment` (walked from the start).
SlotMove encode_segment(const Move& m, int segment, std::uint8_t base, const Codes& codes,
                        std::span<std::uint8_t, 256> mb);

// The contract's observable state of the move in the slot, from the
// mailbox bytes; `pulses` is the count the host observed. A finished
// segment that is not the move's last is the state after its last pulse,
// not done. Throws
// std::logic_error if the slot holds something no state maps to.
State decode(const SlotMove& sm, std::span<const std::uint8_t, 256> mb, const Codes& codes, std::uint64_t pulses);

}  // namespace contour::sw8085
