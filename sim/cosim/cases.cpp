#include "cases.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <stdexcept>

namespace contour::cosim {

namespace {

Case line_case(std::string name, std::string title, std::int64_t xe, std::int64_t ye) {
  return Case{std::move(name), std::move(title), {Move::line(xe, ye)}, {}};
}

Case arc_case(std::string name, std::string title, std::int64_t xs, std::int64_t ys, std::int64_t xe,
              std::int64_t ye, Sense s) {
  return Case{std::move(name), std::move(title), {Move::arc(xs, ys, xe, ye, s)}, {}};
}

// A rounded rectangle, 40 x 24 with corner radius 8, CCW: lines and
// quarter arcs chained, so that moves follow each other in the queues.
Case rounded_rectangle() {
  Case c{"slot", "rounded rectangle: 4 lines + 4 quarter arcs, back to back", {}, {}};
  const std::int64_t r = 8;
  c.moves = {
      Move::line(40, 0),  Move::arc(0, -r, r, 0, Sense::CCW),  Move::line(0, 24),
      Move::arc(r, 0, 0, r, Sense::CCW),  Move::line(-40, 0), Move::arc(0, r, -r, 0, Sense::CCW),
      Move::line(0, -24), Move::arc(-r, 0, 0, -r, Sense::CCW),
  };
  return c;
}

// Twenty short lines, back to back, turning through every direction: more
// moves than the core's queue of 16 holds, so that the host waits for room
// (the coverage bin "queue full") and pushes while the core runs.
Case many_moves() {
  Case c{"zigzag", "20 short lines back to back (more than the core's 16-block queue)", {}, {}};
  const std::int64_t d[8][2] = {{3, 1}, {1, 3}, {-1, 3}, {-3, 1}, {-3, -1}, {-1, -3}, {1, -3}, {3, -1}};
  for (int i = 0; i < 20; ++i) c.moves.push_back(Move::line(d[i % 8][0], d[i % 8][1]));
  return c;
}

std::map<std::string, Suite> build() {
  std::map<std::string, Suite> s;
  const Case fig2 = line_case("fig2", "paper A Fig. 2: line to (6, 5), 11 pulses", 6, 5);
  const Case fig5 = arc_case("fig5", "paper A Fig. 5: arc (6, 0) to (0, 6) CCW, 12 pulses", 6, 0, 0, 6, Sense::CCW);
  // Rates: fine around the 8085's limit (a few kpps), then decades to
  // paper A's 250 kpps; the core goes on to where its output stage refuses.
  const std::vector<double> paper_rates = {1e3,  2e3,  2.5e3, 3e3,   3.5e3, 4e3,   4.5e3, 5e3,   5.5e3, 6e3,
                                           7e3,  8e3,  9e3,   10e3,  11e3,  12e3,  14e3,  16e3,  20e3,  50e3,
                                           100e3, 250e3, 400e3, 500e3, 600e3, 700e3, 800e3, 1e6, 2e6};
  s["paper"] = Suite{"paper", "paper A's Fig. 2 (line) and Fig. 5 (arc)", {fig2, fig5}, paper_rates};

  const std::vector<Case> smoke_cases = {
      line_case("line-neg", "line to (-23, 31): X negative, Y positive", -23, 31),
      arc_case("arc-3q", "three-quarter arc (0, 12) to (12, 0) CCW through Q2, Q3, Q4", 0, 12, 12, 0, Sense::CCW),
      arc_case("circle-cw", "full circle R = 10 CW from (10, 0)", 10, 0, 10, 0, Sense::CW),
      rounded_rectangle(),
      // For the coverage bins (coverage.hpp) the cases above miss:
      // Inside Q1 (no crossing), ends off the integer circle: the end-point
      // rule hands a pulse outward (X arrived at 8 with D >= 0), then inward
      // (Y arrived at 9 with D < 0).
      arc_case("arc-k0", "arc (10, 0) to (8, 7) CCW inside Q1: no crossing; X arrives first", 10, 0, 8, 7, Sense::CCW),
      arc_case("arc-k0-y", "arc (10, 0) to (3, 9) CCW inside Q1: no crossing; Y arrives first", 10, 0, 3, 9,
               Sense::CCW),
      arc_case("arc-half", "half circle (10, 0) to (-10, 0) CW through Q4, Q3: two crossings", 10, 0, -10, 0, Sense::CW),
      line_case("line-q3", "line to (-17, -9): both axes negative", -17, -9),
      many_moves(),
  };
  s["smoke"] = Suite{"smoke", "signs, quadrant crossings, a full circle, chained moves", smoke_cases,
                     {1e3, 3e3, 4e3, 5e3, 5.5e3, 6e3, 8e3, 10e3, 11e3, 12e3, 50e3, 250e3, 500e3, 1e6}};

  std::vector<Case> full = {fig2, fig5};
  for (const auto& c : smoke_cases) full.push_back(c);
  full.push_back(line_case("line-long", "line to (300, -113)", 300, -113));
  // The worst pulses `contour table1` finds (sw8085/interp on the ISS):
  full.push_back(line_case("line-y", "pure Y line to (0, -300) (table1's worst linear pulse)", 0, -300));
  full.push_back(arc_case("circle-100", "full circle R = 100 CCW from (100, 0) (table1's worst circular pulse)", 100, 0,
                          100, 0, Sense::CCW));
  full.push_back(arc_case("circle-ccw", "full circle R = 50 CCW from (30, 40)", 30, 40, 30, 40, Sense::CCW));
  s["full"] = Suite{"full", "paper + smoke + long lines and larger circles", full,
                    {1e3, 2e3, 3e3, 4e3, 5e3, 5.5e3, 6e3, 7e3, 8e3, 9e3, 10e3, 11e3, 12e3, 50e3, 100e3, 250e3, 500e3,
                     1e6}};
  // The 8085's host runs a line of more than 65 536 P steps as segments,
  // one mailbox slot each (docs/sw8085.md): this one takes two. One rate,
  // above the program's ordinary line rate, so that segments run back to back.
  s["long"] = Suite{"long",
                    "a line of more than 65536 P steps (two segments on the 8085)",
                    {line_case("line-65540", "line to (65540, -3): 65 543 pulses, X counts 65 540 P steps", 65540, -3)},
                    {12e3}};
  return s;
}

const std::map<std::string, Suite>& suites() {
  static const std::map<std::string, Suite> s = build();
  return s;
}

}  // namespace

const Suite& suite(const std::string& name) {
  const auto& all = suites();
  const auto it = all.find(name);
  if (it == all.end()) {
    std::string known;
    for (const auto& n : suite_names()) known += (known.empty() ? "" : "|") + n;
    throw std::invalid_argument("unknown suite '" + name + "' (known: " + known + ")");
  }
  return it->second;
}

std::vector<std::string> suite_names() { return {"paper", "smoke", "full", "long"}; }

Suite combined(const std::string& names) {
  Suite out;
  std::size_t start = 0;
  while (start <= names.size()) {
    const auto comma = names.find(',', start);
    const std::string name = names.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    start = comma == std::string::npos ? names.size() + 1 : comma + 1;
    const Suite& s = suite(name);
    out.name += (out.name.empty() ? "" : ",") + s.name;
    out.summary += (out.summary.empty() ? "" : "; ") + s.summary;
    for (Case c : s.cases) {
      bool dup = false;
      for (const auto& have : out.cases) dup |= have.name == c.name;
      if (dup) continue;
      c.rates = s.rates;
      out.cases.push_back(std::move(c));
    }
    out.rates.insert(out.rates.end(), s.rates.begin(), s.rates.end());
  }
  std::sort(out.rates.begin(), out.rates.end());
  out.rates.erase(std::unique(out.rates.begin(), out.rates.end()), out.rates.end());
  return out;
}

double max_rate(const std::string& engine, double core_hz) {
  if (engine == "iss" || engine == "cpu") return kMaxRate8085;
  if (engine == "core") return core_hz / 2;
  return kMaxRate;
}

bool engine_runs_at(const std::string& engine, double rate_pps, double core_hz) {
  return rate_pps <= max_rate(engine, core_hz);
}

double core_carry_rate(double core_hz, std::uint32_t len, std::uint32_t space, std::uint32_t setup,
                       std::uint32_t hold) {
  return core_hz / (double(len) + double(space) + double(setup) + double(hold));
}

std::vector<Placed> place(const std::vector<Move>& moves) {
  std::vector<Placed> out;
  std::int64_t x = 0, y = 0;
  for (const auto& m : moves) {
    Placed p{m, x, y, x, y, x, y};
    if (m.is_arc()) {
      p.origin_x = x - m.xs;
      p.origin_y = y - m.ys;
    }
    p.end_x = p.origin_x + m.xe;
    p.end_y = p.origin_y + m.ye;
    x = p.end_x;
    y = p.end_y;
    out.push_back(p);
  }
  return out;
}

std::string rate_label_approx(double r) {
  if (r <= 0) return rate_label(r);
  const double unit = std::pow(10.0, std::floor(std::log10(r)) - 3);
  return rate_label(std::round(r / unit) * unit);
}

std::string rate_label(double r) {
  char buf[32];
  if (r >= 1e6) std::snprintf(buf, sizeof buf, "%gM", r / 1e6);
  else if (r >= 1e3) std::snprintf(buf, sizeof buf, "%gk", r / 1e3);
  else std::snprintf(buf, sizeof buf, "%g", r);
  return buf;
}

}  // namespace contour::cosim
