#include "scoreboard.hpp"

#include <algorithm>
#include <cstdio>
#include <sstream>

namespace contour::cosim {

Expected expect(const Case& c) {
  Expected e;
  const auto placed = place(c.moves);
  e.pos.push_back({0, 0});
  for (std::size_t i = 0; i < placed.size(); ++i) {
    const Placed& p = placed[i];
    const RunResult r = run_model<24>(p.move);
    for (const auto& s : r.steps) {
      e.pulses.push_back(s.pulse);
      e.states.push_back(to_string(s.state));
      e.move_of.push_back(i);
      e.pos.push_back({p.origin_x + s.state.x, p.origin_y + s.state.y});
    }
  }
  return e;
}

double keep_up_rate(const std::string& engine, double core_carry_pps) {
  if (engine == "model") return kMaxRate;
  if (engine == "core") return std::min(kCoreRequiredRate, core_carry_pps);
  return kRequiredRate8085;
}

bool loss_forbidden(const std::string& engine, double rate_pps, double core_carry_pps) {
  return rate_pps <= keep_up_rate(engine, core_carry_pps);
}

namespace {

std::string fmt_us(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3f", v);
  return buf;
}

std::string pos_text(std::int64_t x, std::int64_t y) {
  return "(" + std::to_string(x) + ", " + std::to_string(y) + ")";
}

Divergence make_divergence(const std::string& engine, const Expected& exp, const EngineRun& run, std::size_t k) {
  // k: 0-based index of the first differing pulse.
  Divergence d;
  d.index = k + 1;
  auto side = [](const std::optional<Pulse>& p) { return p ? to_string(*p) : std::string("(none)"); };
  const std::optional<Pulse> mp = k < exp.pulses.size() ? std::optional<Pulse>(exp.pulses[k]) : std::nullopt;
  const std::optional<Pulse> ep = k < run.out.size() ? std::optional<Pulse>(run.out[k].pulse) : std::nullopt;
  d.summary = "pulse " + std::to_string(k + 1) + ": model " + side(mp) + ", " + engine + " " + side(ep);
  if (ep && !mp) d.summary += " (an extra pulse after the end)";
  if (ep) d.t_us = run.out[k].t_us;
  // Positions of the engine, from its own pulses.
  std::vector<std::pair<std::int64_t, std::int64_t>> epos{{0, 0}};
  for (const auto& o : run.out) {
    auto [x, y] = epos.back();
    (o.pulse.axis == Axis::X ? x : y) += o.pulse.sign;
    epos.push_back({x, y});
  }
  std::ostringstream o;
  const std::size_t lo = k >= 3 ? k - 3 : 0;
  const std::size_t hi = k + 3;
  for (std::size_t i = lo; i <= hi; ++i) {
    const bool has_m = i < exp.pulses.size(), has_e = i < run.out.size();
    if (!has_m && !has_e) break;
    o << (i == k ? "> " : "  ") << "#" << (i + 1) << "\n";
    auto label = [](const std::string& who) { return who + ":" + std::string(who.size() < 7 ? 7 - who.size() : 1, ' '); };
    o << "    " << label("model");
    if (has_m)
      o << to_string(exp.pulses[i]) << "  at " << pos_text(exp.pos[i + 1].first, exp.pos[i + 1].second) << "  "
        << exp.states[i];
    else
      o << "(no pulse)";
    o << "\n    " << label(engine);
    if (has_e) {
      const auto& e = run.out[i];
      o << to_string(e.pulse) << "  at " << pos_text(epos[i + 1].first, epos[i + 1].second) << "  t = "
        << fmt_us(e.t_us) << " us (SystemC " << fmt_us(run.t0_us + e.t_us) << " us)";
      if (!e.state.empty()) o << "  " << e.state;
    } else {
      o << "(no pulse)";
    }
    o << "\n";
  }
  d.context = o.str();
  return d;
}

// A row naming the run, with its counts and no verdict yet.
Row row_of(const Case& c, const Expected& exp, double rate_pps, std::size_t commands, const EngineRun& run,
           double core_carry_pps) {
  Row r;
  r.case_name = c.name;
  r.engine = run.engine;
  r.rate_pps = rate_pps;
  r.commands = commands;
  r.expected = exp.pulses.size();
  r.pulses = run.out.size();
  r.required = loss_forbidden(run.engine, rate_pps, core_carry_pps);
  r.case_start_us = run.t0_us;
  return r;
}

// Pulse by pulse: axis, sign and order; pulses after the model's last count
// as mismatches. Returns the 0-based index of the first differing pulse.
std::optional<std::size_t> count_mismatches(const Expected& exp, const EngineRun& run, Row& r) {
  std::optional<std::size_t> first;
  const std::size_t common = std::min(run.out.size(), exp.pulses.size());
  for (std::size_t i = 0; i < common; ++i)
    if (!(run.out[i].pulse == exp.pulses[i])) {
      ++r.mismatches;
      if (!first) first = i;
    }
  if (run.out.size() > exp.pulses.size()) {
    r.mismatches += run.out.size() - exp.pulses.size();
    if (!first) first = exp.pulses.size();
  }
  return first;
}

// Keeps the first divergence and the engine's pulses (for the plot).
void record_divergence(const Expected& exp, const EngineRun& run, std::size_t first, Row& r,
                       std::vector<std::string>& why) {
  r.divergence = make_divergence(run.engine, exp, run, first);
  for (const auto& o : run.out) r.path.push_back(o.pulse);
  why.push_back("first divergence at " + r.divergence->summary);
}

// Pulses lost: every command pulse must give one output pulse; every lost
// pulse must have been flagged as an overrun, and nothing else; and none may
// be lost where the engine must keep up.
void check_losses(const EngineRun& run, bool diverged, double keep_up_pps, Row& r, std::vector<std::string>& why) {
  r.lost = run.out.size() < r.commands ? r.commands - run.out.size() : 0;
  if (run.out.size() > r.commands && !diverged) why.push_back("more output pulses than command pulses");
  if (run.overruns_known) {
    r.overruns = run.overruns;
    if (static_cast<std::uint64_t>(run.overruns) != r.lost)
      why.push_back(std::to_string(r.lost) + " pulses lost but " + std::to_string(run.overruns) +
                    " overruns flagged");
  } else if (r.lost > 0) {
    why.push_back(std::to_string(r.lost) + " pulses lost and the engine cannot flag overruns");
  }
  if (r.required && r.lost > 0)
    why.push_back(std::to_string(r.lost) + " pulses lost at " + rate_label(r.rate_pps) + " pps, where " +
                  run.engine + " must keep up (up to " + rate_label_approx(keep_up_pps) + " pps)");
}

// Final position: the engine's own count against the model's after as many
// pulses.
void check_final_position(const Expected& exp, const EngineRun& run, std::vector<std::string>& why) {
  if (!run.position_known) return;
  const auto& want = exp.pos[std::min(run.out.size(), exp.pos.size() - 1)];
  if (want.first != run.x || want.second != run.y)
    why.push_back("final position " + pos_text(run.x, run.y) + ", model " + pos_text(want.first, want.second));
}

// Latency: output pulse i against command i when nothing was lost,
// otherwise against the latest command at or before it.
void measure_latency(const std::vector<double>& cmd_us, const EngineRun& run, Row& r, std::vector<std::string>& why) {
  if (run.out.empty() || cmd_us.empty()) return;
  r.has_latency = true;
  r.latency_exact = r.lost == 0;
  double sum = 0, lo = 1e300, hi = -1e300;
  for (std::size_t i = 0; i < run.out.size(); ++i) {
    const double t = run.out[i].t_us;
    double c0;
    if (r.latency_exact) {
      c0 = cmd_us[i];
    } else {
      auto it = std::upper_bound(cmd_us.begin(), cmd_us.end(), t);
      c0 = it == cmd_us.begin() ? cmd_us.front() : *(it - 1);
    }
    const double l = t - c0;
    sum += l;
    lo = std::min(lo, l);
    hi = std::max(hi, l);
  }
  r.lat_min_us = lo;
  r.lat_max_us = hi;
  r.lat_mean_us = sum / static_cast<double>(run.out.size());
  if (r.latency_exact && lo < 0) why.push_back("an output pulse before its command pulse");
}

// FAIL with every reason, FLAGGED when pulses were lost (each flagged), PASS.
void give_verdict(const std::vector<std::string>& why, Row& r) {
  if (!why.empty()) {
    r.verdict = Verdict::Fail;
    for (std::size_t i = 0; i < why.size(); ++i) r.note += (i ? "; " : "") + why[i];
  } else if (r.lost > 0) {
    r.verdict = Verdict::Flagged;
    r.note = std::to_string(r.lost) + " of " + std::to_string(r.commands) +
             " command pulses lost, every one flagged as an overrun";
  } else {
    r.verdict = Verdict::Pass;
  }
}

}  // namespace

const char* to_string(Verdict v) {
  switch (v) {
    case Verdict::Pass: return "PASS";
    case Verdict::Flagged: return "FLAGGED";
    case Verdict::Fail: return "FAIL";
    case Verdict::NotRun: return "NOT RUN";
  }
  return "FAIL";
}

const char* css_class(Verdict v) { return v == Verdict::NotRun ? "NOTRUN" : to_string(v); }

Row judge(const Case& c, const Expected& exp, double rate_pps, const std::vector<double>& cmd_us,
          const EngineRun& run, double core_carry_pps) {
  Row r = row_of(c, exp, rate_pps, cmd_us.size(), run, core_carry_pps);
  std::vector<std::string> why;
  const std::optional<std::size_t> first = count_mismatches(exp, run, r);
  if (first) record_divergence(exp, run, *first, r, why);
  check_losses(run, first.has_value(), keep_up_rate(run.engine, core_carry_pps), r, why);
  if (!first) check_final_position(exp, run, why);
  if (!run.error.empty()) why.insert(why.begin(), "simulation error: " + run.error);
  if (!first) measure_latency(cmd_us, run, r, why);
  give_verdict(why, r);
  return r;
}

}  // namespace contour::cosim

namespace contour::cosim {

Row not_run(const Case& c, const Expected& exp, const std::string& engine, double rate_pps, double max_pps) {
  Row r;
  r.case_name = c.name;
  r.engine = engine;
  r.rate_pps = rate_pps;
  r.expected = exp.pulses.size();
  r.verdict = Verdict::NotRun;
  r.note = engine + " takes command rates up to " + rate_label(max_pps) + " pps: not run at " + rate_label(rate_pps) +
           " pps";
  return r;
}

}  // namespace contour::cosim
