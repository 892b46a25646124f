#include "mailbox.hpp"

#include <algorithm>
#include <stdexcept>

#include "interp/circular.hpp"

namespace contour::sw8085 {
namespace {

std::uint8_t at(std::uint8_t base, int off) { return static_cast<std::uint8_t>(base + off); }

void put24(std::span<std::uint8_t, 256> mb, std::uint8_t addr, std::uint32_t v) {
  for (int i = 0; i < 3; ++i) mb[static_cast<std::uint8_t>(addr + i)] = static_cast<std::uint8_t>(v >> (8 * i));
}

std::uint32_t get24(std::span<const std::uint8_t, 256> mb, std::uint8_t addr) {
  std::uint32_t v = 0;
  for (int i = 0; i < 3; ++i) v |= std::uint32_t{mb[static_cast<std::uint8_t>(addr + i)]} << (8 * i);
  return v;
}

std::uint8_t need(const std::map<std::string, std::uint16_t>& s, const char* name) {
  const auto it = s.find(name);
  if (it == s.end()) throw std::runtime_error(std::string("interp.lst: symbol ") + name + " is missing");
  return static_cast<std::uint8_t>(it->second);
}

std::int64_t abs64(std::int64_t v) { return v < 0 ? -v : v; }

}  // namespace

Codes Codes::from_symbols(const std::map<std::string, std::uint16_t>& s) {
  Codes c;
  c.idle = need(s, "C_IDLE");
  struct Family {
    const char* name;
    bool neg, done;
  };
  static constexpr Family kFamilies[] = {
      {"FINP", false, true}, {"FINN", true, true},  {"AIX", false, false}, {"AOY", true, false},
      {"AIY", false, false}, {"AOX", true, false},  {"FIXP", false, false}, {"FIXN", true, false},
      {"FOYP", false, false}, {"FOYN", true, false}, {"FIYP", false, false}, {"FIYN", true, false},
      {"FOXP", false, false}, {"FOXN", true, false}};
  for (const auto& f : kFamilies)
    for (int p = 0; p < 2; ++p) {
      const std::string sym = std::string("C_") + f.name + char('0' + p);
      const std::uint8_t code = need(s, sym.c_str());
      c.named[f.name][p] = code;
      if (!c.arc.emplace(code, ArcCode{f.neg, p, f.done}).second)
        throw std::runtime_error("interp.lst: code of " + sym + " is not unique");
    }
  c.fin_p = c.named["FINP"];
  c.fin_n = c.named["FINN"];
  return c;
}

std::uint8_t Codes::code(const std::string& name, int p) const {
  const auto it = named.find(name);
  if (it == named.end()) throw std::logic_error("sw8085: no MODE code " + name);
  return it->second[p];
}

std::optional<Pulse> decode_pattern(std::uint8_t v) {
  const bool x = v & 0x01, y = v & 0x04;
  if (x == y || (v & 0xF0) != 0) return std::nullopt;
  if (x) return Pulse{Axis::X, static_cast<std::int8_t>((v & 0x02) ? -1 : +1)};
  return Pulse{Axis::Y, static_cast<std::int8_t>((v & 0x08) ? -1 : +1)};
}

namespace {

// A line in the program's terms (mailbox.hpp): P, Q magnitudes and
// patterns, the P steps, and d0, the program's D at the start: the
// program's D is p*Qpos - q*Ppos + d0 at every point of the walk.
struct LineGeom {
  std::int64_t a, b, p, q, psteps, d0;
  bool swapped, one;
  std::int8_t sx, sy;
  std::uint8_t pat_p, pat_q;
};

LineGeom line_geom(const Move& m) {
  LineGeom g{};
  g.a = abs64(m.xe);
  g.b = abs64(m.ye);
  if (g.a == 0 && g.b == 0) throw std::logic_error("sw8085::encode: a line of length 0 is done at once, not queued");
  g.sx = m.xe < 0 ? -1 : +1;
  g.sy = m.ye < 0 ? -1 : +1;
  // P: the axis stepped when D >= 0 and the last one stepped (X iff
  // |YE| < |XE|: the walk reaches (A - 1, B) then, else (A, B - 1)).
  g.swapped = g.a > 0 && g.b > 0 && g.b >= g.a;
  g.one = g.a == 0 || g.b == 0;
  // One axis: P and Q are the same axis, |P| = |Q| = 1, D = 0 / -1 with
  // P stepping from D = 0: P's steps are every other pulse, the last one
  // P's, so a line of n pulses starts from D = -1 if n is even.
  const std::int64_t n = g.a + g.b;
  g.p = g.one ? 1 : g.swapped ? g.b : g.a;
  g.q = g.one ? 1 : g.swapped ? g.a : g.b;
  g.psteps = g.one ? (n + 1) / 2 : g.p;
  g.d0 = (g.one ? n % 2 == 0 : g.swapped) ? -1 : 0;
  g.pat_p = g.one ? (g.a == 0 ? pattern(Axis::Y, g.sy) : pattern(Axis::X, g.sx))
                  : g.swapped ? pattern(Axis::Y, g.sy) : pattern(Axis::X, g.sx);
  g.pat_q = g.one ? g.pat_p : g.swapped ? pattern(Axis::X, g.sx) : pattern(Axis::Y, g.sy);
  return g;
}

// The program's D right after the P step that brings P to `pp` (pp >= 1):
// Q steps come while D < 0 and stop as soon as D >= 0, so before that P
// step Q is the least Qpos with p*Qpos - q*(pp - 1) + d0 >= 0; for pp = 0
// the start, d0.
std::int64_t line_d_after_p(const LineGeom& g, std::int64_t pp) {
  if (pp == 0) return g.d0;
  const std::int64_t num = g.q * (pp - 1) - g.d0;  // >= 0
  const std::int64_t qpos = (num + g.p - 1) / g.p;
  return g.p * qpos - g.q * pp + g.d0;
}

}  // namespace

int segments(const Move& m) {
  if (m.is_arc()) throw std::logic_error("sw8085::segments: an arc's segments are known by walking it (Segmenter)");
  if (m.xe == 0 && m.ye == 0) return 1;
  const std::int64_t ps = line_geom(m).psteps;
  return static_cast<int>((ps + line::kSegment - 1) / line::kSegment);
}

SlotMove encode(const Move& m, std::uint8_t base, const Codes& codes, std::span<std::uint8_t, 256> mb) {
  if (m.is_arc()) {
    Segmenter seg(m);
    const SlotMove sm = seg.next(base, codes, mb);
    if (seg.more())
      throw std::logic_error("sw8085::encode: " + describe(m) + " runs as more than one segment (Segmenter)");
    return sm;
  }
  if (segments(m) != 1)
    throw std::logic_error("sw8085::encode: " + describe(m) + " has more than " + std::to_string(line::kSegment) +
                           " P steps: it runs as segments (encode_segment)");
  return encode_segment(m, 0, base, codes, mb);
}

SlotMove encode_segment(const Move& m, int segment, std::uint8_t base, const Codes& codes,
                        std::span<std::uint8_t, 256> mb) {
  SlotMove sm;
  sm.move = m;
  sm.base = base;
  sm.arc = m.is_arc();
  if (!sm.arc) {
    const LineGeom g = line_geom(m);
    sm.a = g.a;
    sm.b = g.b;
    sm.sx = g.sx;
    sm.sy = g.sy;
    sm.swapped = g.swapped;
    sm.psteps = g.psteps;
    sm.segments = segments(m);
    if (segment < 0 || segment >= sm.segments)
      throw std::logic_error("sw8085::encode_segment: " + describe(m) + " has no segment " + std::to_string(segment));
    sm.segment = segment;
    sm.last_segment = segment + 1 == sm.segments;
    sm.seg_first = line::kSegment * segment;
    sm.seg_len = std::min(line::kSegment, g.psteps - sm.seg_first);
    // The segment starts where the walk is after the P step that ends the
    // segment before it (the start of the line for the first one).
    const std::int64_t d = line_d_after_p(g, sm.seg_first);
    mb[at(base, kMode)] = d < 0 ? line::kModeNeg : line::kModeNonNeg;
    put24(mb, at(base, line::kD), static_cast<std::uint32_t>(d & 0xFFFFFF));
    mb[at(base, line::kC[0])] = static_cast<std::uint8_t>(((sm.seg_len - 1) & 0xFF) + 1);
    mb[at(base, line::kC[1])] = static_cast<std::uint8_t>(((sm.seg_len - 1) >> 8) + 1);  // 65536: 0, 0
    mb[at(base, line::kPatP)] = g.pat_p;
    mb[at(base, line::kPatE)] = g.pat_p;
    mb[at(base, line::kPatQ)] = g.pat_q;
    const auto nq = static_cast<std::uint32_t>(-g.q & 0xFFFFFF);
    for (int i = 0; i < 3; ++i) mb[at(base, line::kNegQ - i)] = static_cast<std::uint8_t>(nq >> (8 * i));
    put24(mb, at(base, line::kA), static_cast<std::uint32_t>(g.p));
    return sm;
  }
  // An arc: Segmenter's write number `segment`, walked from the start.
  Segmenter seg(m);
  std::array<std::uint8_t, 256> scratch{};
  for (int i = 0; i < segment; ++i) {
    if (!seg.more()) throw std::logic_error("sw8085::encode_segment: " + describe(m) + " has no segment " + std::to_string(segment));
    seg.next(base, codes, scratch);
  }
  if (!seg.more()) throw std::logic_error("sw8085::encode_segment: " + describe(m) + " has no segment " + std::to_string(segment));
  SlotMove r = seg.next(base, codes, mb);
  r.segment = segment;
  return r;
}

// ---- arcs: the host's walk and its segments ----------------------------------

namespace {
// Table Q's signs (docs/algorithm.md).
int sign_x(int q) { return q == 0 || q == 3 ? 1 : -1; }
int sign_y(int q) { return q < 2 ? 1 : -1; }
}  // namespace

int ArcWalk::family() const {
  if (k != 0 || done) return 0;
  const bool ix = in_x();
  if ((ix ? ay : ax) == (ix ? ey : ex)) return 1;  // the outward axis is at its end
  if ((ix ? ax : ay) == (ix ? ex : ey)) return 2;  // the inward one
  return 0;
}

State ArcWalk::state() const {
  State s;
  s.x = sign_x(q) * ax;
  s.y = sign_y(q) * ay;
  s.d = d;
  s.quadrant = static_cast<std::uint8_t>(q);
  s.crossings = static_cast<std::uint8_t>(k);
  s.done = done;
  return s;
}

ArcWalk::Step ArcWalk::step() {
  if (done) throw std::logic_error("sw8085::ArcWalk: stepped past the end");
  const bool ix = in_x();
  std::int64_t& cin = ix ? ax : ay;
  std::int64_t& cout = ix ? ay : ax;
  const std::int64_t ein = ix ? ex : ey, eout = ix ? ey : ex;
  bool inward = d >= 0;
  if (k == 0) {
    if (inward && cin == ein) inward = false;
    else if (!inward && cout == eout) inward = true;
  }
  Step st;
  if (inward) {
    st.before = cin;
    d -= 2 * cin - 1;
    --cin;
    st.after = cin;
    const int s = ix ? sign_x(q) : sign_y(q);
    st.pulse = Pulse{ix ? Axis::X : Axis::Y, static_cast<std::int8_t>(-s)};
    if (cin == 0) {
      q = (q + (cw ? 3 : 1)) & 3;
      --k;
    }
  } else {
    st.before = cout;
    d += 2 * cout + 1;
    ++cout;
    st.after = cout;
    const int s = ix ? sign_y(q) : sign_x(q);
    st.pulse = Pulse{ix ? Axis::Y : Axis::X, static_cast<std::int8_t>(s)};
  }
  done = k == 0 && ax == ex && ay == ey;
  return st;
}

Segmenter::Segmenter(const Move& m) : m_(m) {
  if (!m.is_arc()) return;
  const auto plan = Circular<24>::validate(m.xs, m.ys, m.xe, m.ye, m.sense);
  walk_.ax = abs64(m.xs);
  walk_.ay = abs64(m.ys);
  walk_.ex = abs64(m.xe);
  walk_.ey = abs64(m.ye);
  walk_.q = plan.q_start;
  walk_.k = plan.crossings;
  walk_.cw = m.sense == Sense::CW;
  walk_.done = walk_.k == 0 && walk_.ax == walk_.ex && walk_.ay == walk_.ey;
  if (walk_.done) throw std::logic_error("sw8085::Segmenter: an arc with k = 0 that starts at its end");
}

SlotMove Segmenter::next(std::uint8_t base, const Codes& codes, std::span<std::uint8_t, 256> mb) {
  if (!more_) throw std::logic_error("sw8085::Segmenter: " + describe(m_) + " has no segment left");
  if (!m_.is_arc()) {
    SlotMove sm = encode_segment(m_, segment_++, base, codes, mb);
    more_ = !sm.last();
    return sm;
  }
  SlotMove sm;
  sm.move = m_;
  sm.base = base;
  sm.arc = true;
  sm.segment = segment_++;
  sm.q = walk_.q;
  sm.k = walk_.k;
  // The segment's start: the family by the walk's state, the code by the
  // sign and parity of D (D = 2D' + p).
  const ArcWalk w0 = walk_;
  const bool ix = w0.in_x(), neg = w0.d < 0;
  const int fam = w0.family();
  const char* name = fam == 0   ? (neg ? (ix ? "AOY" : "AOX") : (ix ? "AIX" : "AIY"))
                     : fam == 1 ? (ix ? (neg ? "FIXN" : "FIXP") : (neg ? "FIYN" : "FIYP"))
                                : (ix ? (neg ? "FOYN" : "FOYP") : (neg ? "FOXN" : "FOXP"));
  const int p = static_cast<int>(w0.d & 1);
  const std::int64_t dp = (w0.d - p) / 2;
  mb[at(base, kMode)] = codes.code(name, p);
  put24(mb, at(base, arc::kD), static_cast<std::uint32_t>(dp & 0xFFFFFF));
  put24(mb, at(base, arc::kCx), static_cast<std::uint32_t>(w0.ax));
  put24(mb, at(base, arc::kCy), static_cast<std::uint32_t>(w0.ay));
  const Axis in = ix ? Axis::X : Axis::Y, out = ix ? Axis::Y : Axis::X;
  mb[at(base, arc::kPin)] = pattern(in, -(ix ? sign_x(w0.q) : sign_y(w0.q)));
  mb[at(base, arc::kPout)] = pattern(out, ix ? sign_y(w0.q) : sign_x(w0.q));
  // Walk to the segment's last pulse: the first that wraps a coordinate's
  // low byte, changes q, k or the family, or ends the move; at most
  // kSegmentPulses.
  int n = 0;
  ArcWalk::Step st;
  while (true) {
    st = walk_.step();
    ++n;
    if (walk_.done || n == arc::kSegmentPulses || (st.before >> 8) != (st.after >> 8) || walk_.q != w0.q ||
        walk_.k != w0.k || walk_.family() != fam)
      break;
  }
  mb[at(base, arc::kN)] = static_cast<std::uint8_t>(n & 0xFF);
  mb[at(base, arc::kPlast)] = pattern(st.pulse.axis, st.pulse.sign);
  sm.pulses = n;
  sm.end = walk_.state();
  more_ = !walk_.done;
  sm.last_segment = !more_;
  return sm;
}

namespace {

// A line's state from the program's D (dp) and P's steps left in the
// whole move: Q's position follows from D.
template <class Bad>
State decode_line_at(const SlotMove& sm, State s, std::int64_t dp, std::int64_t pleft, const Bad& bad) {
  const std::int64_t a = sm.a, b = sm.b;
  const bool one = a == 0 || b == 0;
  std::int64_t x, y;
  s.d = sm.swapped ? -dp - 1 : dp;
  if (one) {
    // D goes 0, -1, 0, ...: -1 when a Q pulse (the same axis) comes next.
    if (s.d != 0 && s.d != -1) throw bad("D is neither 0 nor -1 on a one-axis line");
    const std::int64_t left = 2 * pleft - (s.d == 0 ? 1 : 0);
    if (left > a + b) throw bad("distance left exceeds the move");
    x = a == 0 ? 0 : a - left;
    y = a == 0 ? b - left : 0;
    s.d = 0;
  } else {
    // D = a*y - b*x: the other coordinate follows, exactly or not at all.
    const std::int64_t pmag = sm.swapped ? b : a;
    if (pleft > pmag) throw bad("distance left exceeds the move");
    const std::int64_t pp = pmag - pleft;
    const std::int64_t num = sm.swapped ? a * pp - s.d : s.d + b * pp, den = pmag;
    if (num % den != 0 || num / den < 0 || num / den > (sm.swapped ? a : b))
      throw bad("D = " + std::to_string(s.d) + " is no point of the line at " + std::to_string(pp) + " on P");
    x = sm.swapped ? num / den : pp;
    y = sm.swapped ? pp : num / den;
  }
  s.x = sm.sx * x;
  s.y = sm.sy * y;
  return s;
}

// A line's state: D from MODE and its 3 bytes; the distance travelled on
// the counted axis (P, or the only one) from its counter; Q's from D.
template <class Bad>
State decode_line(const SlotMove& sm, std::span<const std::uint8_t, 256> mb, State s,
                  const Bad& bad) {
  const std::uint8_t base = sm.base;
  const std::uint8_t mode = mb[at(base, kMode)];
  bool neg = false;
  if (mode == line::kModeNonNeg) neg = false;
  else if (mode == line::kModeNeg) neg = true;
  else if (mode == line::done_code(base)) s.done = true;
  else throw bad("no line state has this MODE");
  if (s.done && !sm.last()) {
    // A finished segment (not the move's last): its last pulse skipped the
    // D update; the walk is right after the P step that ended it.
    s.done = false;
    const LineGeom g = line_geom(sm.move);
    const std::int64_t dp = line_d_after_p(g, sm.seg_first + sm.seg_len);
    return decode_line_at(sm, s, dp, g.psteps - sm.seg_first - sm.seg_len, bad);
  }
  if (s.done) {
    // A finished line is at its end point, where D = 0: its last pulse
    // skips the D update (the done code says it), so no byte is read.
    s.d = 0;
    s.x = sm.sx * sm.a;
    s.y = sm.sy * sm.b;
    return s;
  }
  {
    const std::int64_t d24 = get24(mb, at(base, line::kD));
    const std::int64_t dp = neg ? d24 - (std::int64_t{1} << 24) : d24;
    // P's steps left: c0, c1 as nested loops (0 counts as 256), and those
    // of the segments after this one.
    auto d = [](std::uint8_t v) { return std::int64_t{v == 0 ? 256 : v}; };
    const std::int64_t pleft = d(mb[at(base, line::kC[0])]) + 256 * (d(mb[at(base, line::kC[1])]) - 1);
    if (pleft > sm.seg_len) throw bad("distance left exceeds the segment");
    return decode_line_at(sm, s, dp, pleft + sm.psteps - sm.seg_first - sm.seg_len, bad);
  }
}

}  // namespace

State decode(const SlotMove& sm, std::span<const std::uint8_t, 256> mb, const Codes& codes, std::uint64_t pulses) {
  const std::uint8_t base = sm.base;
  const std::uint8_t mode = mb[at(base, kMode)];
  State s;
  s.pulses = pulses;
  auto bad = [&](const std::string& why) {
    return std::logic_error("sw8085: slot " + std::to_string(base) + " (" + describe(sm.move) + "): " + why +
                            ", MODE = " + std::to_string(mode));
  };
  if (!sm.arc) return decode_line(sm, mb, s, bad);
  const auto it = codes.arc.find(mode);
  if (it == codes.arc.end()) throw bad("no arc state has this MODE");
  if (it->second.done) {
    // A finished segment: its last pulse skipped the D' and coordinate
    // update (the done code says it); the walk is where the host's walk
    // found that pulse to end (the move's end for its last segment).
    State e = sm.end;
    e.pulses = pulses;
    e.done = sm.last();
    return e;
  }
  const std::int64_t d24 = get24(mb, at(base, arc::kD));
  const std::int64_t dp = it->second.neg ? d24 - (std::int64_t{1} << 24) : d24;
  s.d = 2 * dp + it->second.parity;
  // q and k are the segment's (a crossing ends a segment).
  s.crossings = static_cast<std::uint8_t>(sm.k);
  s.quadrant = static_cast<std::uint8_t>(sm.q);
  s.x = quadrant_sign_x(sm.q) * std::int64_t{get24(mb, at(base, arc::kCx))};
  s.y = quadrant_sign_y(sm.q) * std::int64_t{get24(mb, at(base, arc::kCy))};
  return s;
}

}  // namespace contour::sw8085
