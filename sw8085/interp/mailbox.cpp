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

// A distance counter: nested-loop bytes (see mailbox.hpp).
std::array<std::uint8_t, 3> to_counter(std::int64_t v) {
  if (v == 0) return {0, 0, 0};
  const std::int64_t w = v - 1;
  return {static_cast<std::uint8_t>((w & 0xFF) + 1), static_cast<std::uint8_t>(((w >> 8) & 0xFF) + 1),
          static_cast<std::uint8_t>((w >> 16) + 1)};
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
      {"AIY", false, false}, {"AOX", true, false},  {"EIX", false, false}, {"EOY", true, false},
      {"EIY", false, false}, {"EOX", true, false},  {"FIXP", false, false}, {"FIXN", true, false},
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
  if (m.is_arc() || (m.xe == 0 && m.ye == 0)) return 1;
  const std::int64_t ps = line_geom(m).psteps;
  return static_cast<int>((ps + line::kSegment - 1) / line::kSegment);
}

SlotMove encode(const Move& m, std::uint8_t base, const Codes& codes, std::span<std::uint8_t, 256> mb) {
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
  if (segment != 0) throw std::logic_error("sw8085::encode_segment: an arc has one segment");
  const auto plan = Circular<24>::validate(m.xs, m.ys, m.xe, m.ye, m.sense);
  const int q = plan.q_start;
  const bool ix = inward_is_x(q, m.sense);
  const std::int64_t cx = abs64(m.xs), cy = abs64(m.ys), ex = abs64(m.xe), ey = abs64(m.ye);
  std::string mode;
  if (plan.crossings > 0) {
    mode = ix ? "AIX" : "AIY";
  } else {
    const bool in_done = ix ? cx == ex : cy == ey;
    const bool out_done = ix ? cy == ey : cx == ex;
    if (in_done && out_done) throw std::logic_error("sw8085::encode: an arc with k = 0 that starts at its end");
    if (in_done) mode = ix ? "FOYP" : "FOXP";
    else if (out_done) mode = ix ? "FIXP" : "FIYP";
    else mode = ix ? "EIX" : "EIY";
  }
  mb[at(base, kMode)] = codes.code(mode, 0);  // D = 0: D >= 0, p = 0
  put24(mb, at(base, arc::kD), 0);
  put24(mb, at(base, arc::kCx), static_cast<std::uint32_t>(cx));
  put24(mb, at(base, arc::kCy), static_cast<std::uint32_t>(cy));
  // The distances to the end in the end quadrant: from the start if the
  // arc starts there, else from where it enters it (the outward axis at 0,
  // the inward one at ceil(sqrt(R^2 - 1)): docs/sw8085.md, "Crossings").
  std::int64_t rx = abs64(cx - ex), ry = abs64(cy - ey);
  if (plan.crossings > 0) {
    const std::int64_t entry = isqrt_ceil(plan.r2 - 1);
    const bool eix = inward_is_x(plan.q_end, m.sense);
    rx = eix ? entry - ex : ex;
    ry = eix ? ey : entry - ey;
  }
  const auto crx = to_counter(rx), cry = to_counter(ry);
  for (int i = 0; i < 3; ++i) {
    mb[at(base, arc::kRx[i])] = crx[i];
    mb[at(base, arc::kRy[i])] = cry[i];
  }
  mb[at(base, arc::kK)] = at(base, arc::kTable + 4 * plan.crossings);
  auto patterns = [&](int qq) {
    const bool qix = inward_is_x(qq, m.sense);
    const Axis in = qix ? Axis::X : Axis::Y, out = qix ? Axis::Y : Axis::X;
    const int sin = in == Axis::X ? quadrant_sign_x(qq) : quadrant_sign_y(qq);
    const int sout = out == Axis::X ? quadrant_sign_x(qq) : quadrant_sign_y(qq);
    return std::pair<std::uint8_t, std::uint8_t>{pattern(in, -sin), pattern(out, sout)};
  };
  mb[at(base, arc::kPin)] = patterns(q).first;
  mb[at(base, arc::kPout)] = patterns(q).second;
  // The crossing table: the quadrant entered when k becomes k', and the
  // start quadrant at the start's k (its code is not used).
  const int step = m.sense == Sense::CCW ? 1 : 3;
  {
    const std::uint8_t e = at(base, arc::kTable + 4 * plan.crossings);
    mb[static_cast<std::uint8_t>(e + 1)] = patterns(q).first;
    mb[static_cast<std::uint8_t>(e + 2)] = patterns(q).second;
    mb[static_cast<std::uint8_t>(e + arc::kEntryQ)] = static_cast<std::uint8_t>(q);
  }
  for (int kn = plan.crossings - 1; kn >= 0; --kn) {
    const int qn = (q + step * (plan.crossings - kn)) & 3;
    const bool nix = inward_is_x(qn, m.sense);
    std::uint8_t code;
    if (kn > 0) {
      code = codes.code(nix ? "AIX" : "AIY", 0);
    } else {
      // The end quadrant: the new outward axis is at 0, the new inward one
      // enters at ceil(sqrt(R^2 - 1)) (docs/sw8085.md, "Crossings"), so
      // which axes are at their end is known now.
      const std::int64_t entry = isqrt_ceil(plan.r2 - 1);
      const bool out_done = (nix ? ey : ex) == 0;
      const bool in_done = (nix ? ex : ey) == entry;
      if (in_done && out_done) code = codes.fin_p[0] | 0x80;  // the move ends on entering
      else if (in_done) code = codes.code(nix ? "FOYP" : "FOXP", 0);
      else if (out_done) code = codes.code(nix ? "FIXP" : "FIYP", 0);
      else code = codes.code(nix ? "EIX" : "EIY", 0);
    }
    const std::uint8_t e = at(base, arc::kTable + 4 * kn);
    mb[e] = code;
    mb[static_cast<std::uint8_t>(e + 1)] = patterns(qn).first;
    mb[static_cast<std::uint8_t>(e + 2)] = patterns(qn).second;
    mb[static_cast<std::uint8_t>(e + arc::kEntryQ)] = static_cast<std::uint8_t>(qn);
  }
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
  s.done = it->second.done;
  const std::int64_t d24 = get24(mb, at(base, arc::kD));
  const std::int64_t dp = it->second.neg ? d24 - (std::int64_t{1} << 24) : d24;
  s.d = 2 * dp + it->second.parity;
  const int k4 = static_cast<std::uint8_t>(mb[at(base, arc::kK)] - base - arc::kTable);
  if (k4 % 4 != 0 || k4 > 16) throw bad("k pointer " + std::to_string(mb[at(base, arc::kK)]) + " is no table entry");
  s.crossings = static_cast<std::uint8_t>(k4 / 4);
  // q is the q of k's table entry: the program moves the pointer.
  const int q = mb[static_cast<std::uint8_t>(mb[at(base, arc::kK)] + arc::kEntryQ)];
  if (q > 3) throw bad("quadrant " + std::to_string(q) + " out of range");
  s.quadrant = static_cast<std::uint8_t>(q);
  if (s.done) {
    // A finished arc is at its end point: its last pulse skips the D' and
    // coordinate update (the done code says it), so those bytes are not read.
    const Move& m = sm.move;
    s.x = m.xe;
    s.y = m.ye;
    s.d = m.xe * m.xe + m.ye * m.ye - (m.xs * m.xs + m.ys * m.ys);
    return s;
  }
  s.x = quadrant_sign_x(q) * std::int64_t{get24(mb, at(base, arc::kCx))};
  s.y = quadrant_sign_y(q) * std::int64_t{get24(mb, at(base, arc::kCy))};
  return s;
}

}  // namespace contour::sw8085
