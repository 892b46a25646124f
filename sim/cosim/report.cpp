#include "report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <set>
#include <sstream>
#include <stdexcept>

#include "plot/svg.hpp"
#include "top.hpp"

namespace contour::cosim {

namespace {

using plot::escape;

const std::map<std::string, std::string>& engine_colors() {
  static const std::map<std::string, std::string> c = {
      {"model", "#444444"}, {"core", "#1f77b4"}, {"iss", "#2ca02c"}, {"cpu", "#d62728"}};
  return c;
}

// The lost-pulse curves: cpu before iss, so that the dashed iss curve shows
// on top where the two are equal (the same program, T-state exact).
const std::vector<std::string>& plot_order() {
  static const std::vector<std::string> order = {"model", "core", "cpu", "iss"};
  return order;
}

std::string engine_title(const std::string& e) {
  if (e == "model") return "model (golden C++ in an SC_MODULE)";
  if (e == "core") return "core (Verilog core interp_top, Verilated --sc)";
  if (e == "iss") return "iss (8085 program on the C++ ISS)";
  if (e == "cpu") return "cpu (8085 program on the Verilog 8085 board board8085, Verilated --sc)";
  return e;
}

std::string fmt(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

std::string json_str(const std::string& s) {
  std::string o = "\"";
  for (char c : s) {
    switch (c) {
      case '"': o += "\\\""; break;
      case '\\': o += "\\\\"; break;
      case '\n': o += "\\n"; break;
      case '\t': o += "\\t"; break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) o += fmt("\\u%04x", static_cast<unsigned char>(c));
        else o += c;
    }
  }
  return o + "\"";
}

std::string xml_attr(const std::string& s) { return escape(s); }

// The frame the path plots use: the first move's own (a line from its
// start, an arc from its centre, as docs/algorithm.md and paper A draw
// them: Fig. 5 from (6, 0) to (0, 6)); place() counts from the case's start.
plot::Point move_frame_shift(const Case& c) {
  const auto placed = place(c.moves);
  if (placed.empty()) return {0, 0};
  return {-double(placed.front().origin_x), -double(placed.front().origin_y)};
}

// The ideal contour of a case as a polyline (arcs sampled), on the case's
// path (its start at (0, 0)).
std::vector<plot::Point> ideal_path(const Case& c) {
  std::vector<plot::Point> pts;
  for (const auto& p : place(c.moves)) {
    if (pts.empty()) pts.push_back({double(p.start_x), double(p.start_y)});
    if (!p.move.is_arc()) {
      pts.push_back({double(p.end_x), double(p.end_y)});
      continue;
    }
    const Move& m = p.move;
    const double r = std::hypot(double(m.xs), double(m.ys));
    const double a0 = std::atan2(double(m.ys), double(m.xs)), a1 = std::atan2(double(m.ye), double(m.xe));
    const double two_pi = 2 * std::numbers::pi;
    double span = m.sense == Sense::CCW ? a1 - a0 : a0 - a1;
    span = std::fmod(span + 2 * two_pi, two_pi);
    if (span < 1e-9) span = two_pi;  // start = end: a full circle
    const int n = std::max(16, static_cast<int>(span * r));
    for (int i = 1; i <= n; ++i) {
      const double a = a0 + (m.sense == Sense::CCW ? 1 : -1) * span * i / n;
      pts.push_back({p.origin_x + r * std::cos(a), p.origin_y + r * std::sin(a)});
    }
    pts.back() = {double(p.end_x), double(p.end_y)};
  }
  return pts;
}

std::vector<plot::Point> pulse_path(const std::vector<Pulse>& pulses) {
  std::vector<plot::Point> pts{{0, 0}};
  double x = 0, y = 0;
  for (const auto& p : pulses) {
    (p.axis == Axis::X ? x : y) += p.sign;
    pts.push_back({x, y});
  }
  return pts;
}

// `pts` moved by `d`.
std::vector<plot::Point> shifted(std::vector<plot::Point> pts, plot::Point d) {
  for (auto& p : pts) p = {p.x + d.x, p.y + d.y};
  return pts;
}

std::string path_svg(const Case& c, const Expected& e, const std::vector<const Row*>& diverged) {
  const plot::Point d = move_frame_shift(c);
  plot::Plot pl;
  pl.title = c.name + ": output pulses over the ideal contour";
  pl.x_label = c.moves.front().is_arc() ? "X from the first arc's centre (pulses)" : "X from the start (pulses)";
  pl.y_label = c.moves.front().is_arc() ? "Y from the first arc's centre (pulses)" : "Y from the start (pulses)";
  pl.equal_aspect = true;
  pl.width = 520;
  pl.height = 440;
  pl.series.push_back({"ideal contour", "#999999", shifted(ideal_path(c), d), 2.0, true, false});
  pl.series.push_back({"model (= agreeing engines)", "#1f77b4", shifted(pulse_path(e.pulses), d), 1.5,
                       false, e.pulses.size() <= 200});
  std::set<std::string> shown;
  for (const Row* r : diverged) {
    if (!shown.insert(r->engine).second) continue;
    pl.series.push_back({r->engine + " @ " + rate_label(r->rate_pps) + " (diverged)", "#d62728",
                         shifted(pulse_path(r->path), d), 1.5, false, r->path.size() <= 200});
  }
  return plot::render(pl);
}

std::string deviation_svg(const Case& c, const Expected& e) {
  const auto placed = place(c.moves);
  plot::Plot pl;
  pl.title = c.name + ": distance from the ideal contour";
  pl.x_label = "output pulse";
  pl.y_label = "deviation (pulses)";
  pl.width = 520;
  pl.height = 440;
  plot::Series s{"model pulse path", "#1f77b4", {}, 1.5, false, e.pulses.size() <= 200};
  for (std::size_t i = 0; i < e.pulses.size(); ++i) {
    const Placed& p = placed[e.move_of[i]];
    const double d = deviation(p.move, e.pos[i + 1].first - p.origin_x, e.pos[i + 1].second - p.origin_y);
    s.points.push_back({double(i + 1), d});
  }
  pl.series.push_back(s);
  pl.series.push_back({"bound: 1 pulse", "#999999", {{1, 1}, {double(std::max<std::size_t>(e.pulses.size(), 2)), 1}},
                       1.0, true, false});
  pl.series.push_back({"", "#ffffff", {{1, 0}}, 0.1, false, false});  // keep 0 in view
  return plot::render(pl);
}

std::string lost_svg(const std::string& case_name, const std::vector<Row>& rows) {
  plot::Plot pl;
  pl.title = case_name + ": command pulses lost vs command rate";
  pl.x_label = "command rate (kpps)";
  pl.y_label = "lost (% of command pulses)";
  pl.log_x = true;
  pl.width = 520;
  pl.height = 380;
  for (const auto& e : plot_order()) {
    plot::Series s{e, engine_colors().at(e), {}, 2.0, e == "iss", true};
    for (const auto& r : rows)
      if (r.case_name == case_name && r.engine == e && r.commands > 0)
        s.points.push_back({r.rate_pps / 1e3, 100.0 * double(r.lost) / double(r.commands)});
    if (!s.points.empty()) pl.series.push_back(s);
  }
  return plot::render(pl);
}

// Every case together: the paper's result in one picture.
std::string lost_all_svg(const std::vector<Row>& rows) {
  plot::Plot pl;
  pl.title = "All cases: command pulses lost vs command rate";
  pl.x_label = "command rate (kpps)";
  pl.y_label = "lost (% of all command pulses)";
  pl.log_x = true;
  pl.width = 800;
  pl.height = 420;
  // Only the rates every case ran at (cases of several suites have their
  // own sweeps), so that each point sums the same cases.
  std::map<double, std::set<std::string>> cases_at;
  std::set<std::string> all_cases;
  for (const auto& r : rows) {
    cases_at[r.rate_pps].insert(r.case_name);
    all_cases.insert(r.case_name);
  }
  for (const auto& e : plot_order()) {
    std::map<double, std::pair<std::uint64_t, std::uint64_t>> at;  // rate -> (lost, commands)
    for (const auto& r : rows)
      if (r.engine == e && r.commands > 0 && cases_at[r.rate_pps].size() == all_cases.size()) {
        at[r.rate_pps].first += r.lost;
        at[r.rate_pps].second += r.commands;
      }
    plot::Series s{e, engine_colors().at(e), {}, 2.5, e == "iss", true};
    for (const auto& [rate, lc] : at) s.points.push_back({rate / 1e3, 100.0 * double(lc.first) / double(lc.second)});
    if (!s.points.empty()) pl.series.push_back(s);
  }
  return plot::render(pl);
}

std::string css() {
  return R"(body{font-family:system-ui,Segoe UI,Helvetica,Arial,sans-serif;margin:24px;color:#222;max-width:1150px}
h1{font-size:26px;margin:0 0 6px 0;padding:10px 14px;border-radius:6px}
h1.pass{background:#e3f4e3;color:#1a6b1a}h1.fail{background:#fbe3e3;color:#a01818}
h2{margin-top:34px;border-bottom:1px solid #ccc;padding-bottom:4px}h3{margin-bottom:6px}
table{border-collapse:collapse;margin:8px 0 16px 0;font-size:13px;display:block;overflow-x:auto;max-width:100%}
th,td{border:1px solid #ccc;padding:3px 7px;text-align:right}th{background:#f2f2f2}
td.l,th.l{text-align:left}
td.PASS{background:#e3f4e3}td.NOTRUN{background:#eee;color:#777}
p.fault{background:#fbe3e3;border:2px solid #a01818;padding:8px 12px;font-weight:bold}td.FLAGGED{background:#fff3cd}td.FAIL{background:#f8d0d0;font-weight:bold}td.na{color:#aaa}
pre{background:#f7f7f7;border:1px solid #ddd;padding:8px;font-size:12px;overflow-x:auto}
.plots{display:flex;flex-wrap:wrap;gap:12px}.plots svg{border:1px solid #eee;background:#fff}
.meta{color:#555;font-size:13px}code{background:#f2f2f2;padding:1px 4px}
)";
}

std::string cell_text(const Row& r) {
  std::string t = to_string(r.verdict);
  if (r.lost > 0 || r.overruns > 0) t += " " + std::to_string(r.lost) + "/" + std::to_string(r.overruns);
  if (r.mismatches > 0) t += " &#8800;" + std::to_string(r.mismatches);
  return t;
}

// Rows counted as the verdict line counts them: acceptable() ones passed,
// NOT RUN ones apart.
struct Tally {
  std::size_t passed = 0, failed = 0, not_run = 0;
};
Tally tally(const std::vector<Row>& rows) {
  Tally t;
  for (const auto& r : rows) {
    if (r.acceptable()) ++t.passed;
    else if (r.ran()) ++t.failed;
    else ++t.not_run;
  }
  return t;
}

}  // namespace

std::string verdict_line(const std::vector<Row>& rows) {
  const Tally t = tally(rows);
  const std::size_t ran = t.passed + t.failed;
  const double pct = ran == 0 ? 0.0 : 100.0 * double(t.passed) / double(ran);
  return fmt("%.2f%%", pct) + (t.failed == 0 && t.passed > 0 ? " PASS " : " FAIL ") + std::to_string(t.passed) +
         " PASSED, " + std::to_string(t.failed) + " FAILED" +
         (t.not_run ? ", " + std::to_string(t.not_run) + " NOT RUN" : "");
}

namespace {

// One point of a .dat line ("C '\001f\002FILE\001l\002LINE...\001page\002PAGE\001o\002WHAT..."):
// "PAGE FILE:LINE WHAT", the file without its directory.
std::string coverage_point_text(const std::string& point) {
  std::map<std::string, std::string> kv;
  std::size_t at = 0;
  while ((at = point.find('\001', at)) != std::string::npos) {
    const auto sep = point.find('\002', at);
    const auto next = point.find('\001', at + 1);
    if (sep == std::string::npos || sep > next) break;
    kv[point.substr(at + 1, sep - at - 1)] = point.substr(sep + 1, next == std::string::npos ? std::string::npos : next - sep - 1);
    at = sep;
  }
  const std::string file = kv["f"].substr(kv["f"].rfind('/') + 1);
  return kv["page"] + " " + file + ":" + kv["l"] + " " + kv["o"];
}

}  // namespace

std::optional<RtlCoverage> read_rtl_coverage(const std::string& dat_path) {
  std::ifstream f(dat_path);
  if (!f) return std::nullopt;
  RtlCoverage c;
  c.path = dat_path;
  for (std::string line; std::getline(f, line);) {
    if (line.rfind("C '", 0) != 0) continue;
    const auto page = line.find("page\002");
    const auto close = line.rfind("' ");
    if (page == std::string::npos || close == std::string::npos) continue;
    const bool toggle = line.compare(page + 5, 8, "v_toggle") == 0;
    const bool hit = std::strtoull(line.c_str() + close + 2, nullptr, 10) > 0;
    (toggle ? c.toggles : c.lines) += 1;
    (toggle ? c.toggles_hit : c.lines_hit) += hit;
    if (!hit) c.uncovered.push_back(coverage_point_text(line.substr(0, close)));
  }
  if (c.lines + c.toggles == 0) return std::nullopt;
  return c;
}

std::string coverage_line(const Coverage& c) {
  std::string s = "functional coverage: " + std::to_string(c.hit()) + " of " + std::to_string(c.bins().size()) +
                  " bins (" + fmt("%.2f%%", c.percent()) + ")";
  std::string missed;
  for (const auto& b : c.bins())
    if (b.total() == 0) missed += (missed.empty() ? "" : "; ") + b.group + ": " + b.name;
  return missed.empty() ? s : s + "; not reached: " + missed;
}

std::string rerun_command(const Row& r, const Options& opt) {
  std::string suite_name;
  for (const auto& n : suite_names()) {
    for (const auto& c : suite(n).cases)
      if (c.name == r.case_name) suite_name = n;
    if (!suite_name.empty()) break;
  }
  std::string cmd = "contour cosim --suite " + suite_name + " --case " + r.case_name + " --rate " +
                    rate_label(r.rate_pps) + " --engines " + (r.engine == "model" ? "model" : "model," + r.engine);
  const StepTiming def;
  if (opt.timing.len != def.len) cmd += " --step-len " + std::to_string(opt.timing.len);
  if (opt.timing.space != def.space) cmd += " --step-space " + std::to_string(opt.timing.space);
  if (opt.free_clock) cmd += " --free-clock";
  for (const auto& f : opt.faults)
    if (f.engine == r.engine) cmd += " --inject " + to_string(f);
  return cmd;
}

Limit limit_of(const std::vector<Row>& rows, const std::string& case_name, const std::string& engine) {
  Limit l;
  std::vector<const Row*> rs;
  for (const auto& r : rows)
    if (r.case_name == case_name && r.engine == engine) rs.push_back(&r);
  std::sort(rs.begin(), rs.end(), [](const Row* a, const Row* b) { return a->rate_pps < b->rate_pps; });
  bool agreeing = true;
  for (const Row* r : rs) {
    if (!r->ran()) continue;
    if (r->lost > 0 && l.first_loss == 0) l.first_loss = r->rate_pps;
    if (r->mismatches > 0 && l.first_mismatch == 0) l.first_mismatch = r->rate_pps;
    agreeing = agreeing && r->lost == 0 && r->mismatches == 0;
    if (agreeing) l.agree_up_to = r->rate_pps;
  }
  return l;
}

namespace {

// --- report.json ---------------------------------------------------------------

std::string json_latency(const Row& r) {
  if (!r.has_latency) return ", \"latency_us\": null";
  return ", \"latency_us\": {\"min\": " + fmt("%.4f", r.lat_min_us) + ", \"mean\": " + fmt("%.4f", r.lat_mean_us) +
         ", \"max\": " + fmt("%.4f", r.lat_max_us) + ", \"exact\": " + (r.latency_exact ? "true" : "false") + "}";
}

std::string json_divergence(const Row& r) {
  if (!r.divergence) return ", \"first_divergence\": null";
  return ", \"first_divergence\": {\"pulse\": " + std::to_string(r.divergence->index) +
         ", \"summary\": " + json_str(r.divergence->summary) + ", \"t_us\": " +
         (r.divergence->t_us < 0 ? std::string("null") : fmt("%.3f", r.divergence->t_us)) + ", \"sim_time_us\": " +
         (r.divergence->t_us < 0 ? std::string("null") : fmt("%.3f", r.case_start_us + r.divergence->t_us)) + "}";
}

void write_json_result(std::ostream& j, const Row& r, const Options& opt) {
  j << "    {\"case\": " << json_str(r.case_name) << ", \"engine\": " << json_str(r.engine)
    << ", \"rate_pps\": " << fmt("%.0f", r.rate_pps) << ", \"pulses\": " << r.pulses
    << ", \"mismatches\": " << r.mismatches << ", \"lost\": " << r.lost << ", \"overruns\": " << r.overruns
    << ", \"verdict\": " << json_str(to_string(r.verdict)) << ", \"expected\": " << r.expected
    << ", \"commands\": " << r.commands << ", \"required\": " << (r.required ? "true" : "false");
  j << ", \"case_start_us\": " << fmt("%.3f", r.case_start_us) << ", \"wall_seconds\": " << fmt("%.4f", r.wall_seconds);
  j << json_latency(r) << json_divergence(r) << ", \"note\": " << json_str(r.note);
  if (r.verdict == Verdict::Fail) j << ", \"rerun\": " << json_str(rerun_command(r, opt));
  j << "}";
}

void write_json_limits(std::ostream& j, const ReportInput& in, const std::vector<std::string>& engines) {
  bool first = true;
  for (const auto& c : in.cases)
    for (const auto& e : engines) {
      const Limit l = limit_of(in.rows, c.name, e);
      j << (first ? "" : ",\n") << "    {\"case\": " << json_str(c.name) << ", \"engine\": " << json_str(e)
        << ", \"agrees_up_to_pps\": " << fmt("%.0f", l.agree_up_to) << ", \"first_loss_pps\": "
        << (l.first_loss > 0 ? fmt("%.0f", l.first_loss) : std::string("null")) << ", \"first_mismatch_pps\": "
        << (l.first_mismatch > 0 ? fmt("%.0f", l.first_mismatch) : std::string("null")) << "}";
      first = false;
    }
}

// "coverage": {"bins", "hit", "percent", "items": [{"group", "name",
// "total", "hits": {engine: n}}...]}
void write_json_coverage(std::ostream& j, const Coverage& c) {
  j << ",\n  \"coverage\": {\"bins\": " << c.bins().size() << ", \"hit\": " << c.hit()
    << ", \"percent\": " << fmt("%.2f", c.percent()) << ", \"items\": [\n";
  for (std::size_t i = 0; i < c.bins().size(); ++i) {
    const auto& b = c.bins()[i];
    j << "    {\"group\": " << json_str(b.group) << ", \"name\": " << json_str(b.name) << ", \"total\": " << b.total()
      << ", \"hits\": {";
    bool first = true;
    for (const auto& [e, n] : b.hits) {
      j << (first ? "" : ", ") << json_str(e) << ": " << n;
      first = false;
    }
    j << "}}" << (i + 1 < c.bins().size() ? "," : "") << "\n";
  }
  j << "  ]}";
}

std::string report_json(const ReportInput& in, const std::string& verdict, const std::vector<std::string>& engines) {
  std::ostringstream j;
  const Tally t = tally(in.rows);
  j << "{\n  \"schema_version\": " << kReportSchemaVersion << ",\n  \"verdict\": " << json_str(verdict)
    << ",\n  \"suite\": " << json_str(in.suite) << ",\n  \"passed\": " << t.passed << ",\n  \"failed\": " << t.failed
    << ",\n  \"not_run\": " << t.not_run << ",\n  \"command\": " << json_str(in.command)
    << ",\n  \"sim_seconds\": " << fmt("%.6f", in.sim_seconds) << ",\n  \"results\": [\n";
  for (std::size_t i = 0; i < in.rows.size(); ++i) {
    write_json_result(j, in.rows[i], in.opt);
    j << (i + 1 < in.rows.size() ? "," : "") << "\n";
  }
  j << "  ],\n  \"limits\": [\n";
  write_json_limits(j, in, engines);
  j << "\n  ]";
  if (in.coverage) write_json_coverage(j, *in.coverage);
  if (in.rtl_coverage)
    j << ",\n  \"rtl_coverage\": {\"path\": " << json_str(in.rtl_coverage->path)
      << ", \"lines\": " << in.rtl_coverage->lines << ", \"lines_hit\": " << in.rtl_coverage->lines_hit
      << ", \"toggles\": " << in.rtl_coverage->toggles << ", \"toggles_hit\": " << in.rtl_coverage->toggles_hit
      << "}";
  j << "\n}\n";
  return j.str();
}

// --- junit.xml -----------------------------------------------------------------

void write_testcase(std::ostream& x, const std::string& suite, const Row& r, const Options& opt) {
  x << "    <testcase classname=\"cosim." << xml_attr(suite + "." + r.case_name) << "\" name=\""
    << xml_attr(r.engine + "@" + rate_label(r.rate_pps)) << "\" time=\"" << fmt("%.4f", r.wall_seconds) << "\"";
  if (!r.ran()) {
    x << "><skipped message=\"" << xml_attr(r.note) << "\"/></testcase>\n";
  } else if (r.acceptable()) {
    x << ">";
    if (!r.note.empty()) x << "<system-out>" << escape(r.note) << "</system-out>";
    x << "</testcase>\n";
  } else {
    x << ">\n      <failure message=\"" << xml_attr(r.note) << "\">"
      << escape((r.divergence ? r.divergence->context : r.note) + "\nre-run: " + rerun_command(r, opt))
      << "</failure>\n    </testcase>\n";
  }
}

std::string junit_xml(const ReportInput& in) {
  std::ostringstream x;
  const Tally t = tally(in.rows);
  x << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"contour cosim\" tests=\"" << in.rows.size()
    << "\" failures=\"" << t.failed << "\" skipped=\"" << t.not_run << "\">\n  <testsuite name=\"cosim."
    << xml_attr(in.suite) << "\" tests=\"" << in.rows.size() << "\" failures=\"" << t.failed << "\" skipped=\""
    << t.not_run << "\" time=\"" << fmt("%.3f", in.wall_seconds) << "\">\n";
  for (const auto& r : in.rows) write_testcase(x, in.suite, r, in.opt);
  x << "  </testsuite>\n</testsuites>\n";
  return x.str();
}

// --- report.html ---------------------------------------------------------------

// Links to the FST traces of the run (--trace), relative when they sit in
// the report's directory.
void write_html_traces(std::ostream& h, const ReportInput& in) {
  if (in.traces.empty()) return;
  namespace fs = std::filesystem;
  h << "<p class=\"meta\">Waveforms (FST, e.g. <code>gtkwave FILE</code>; SystemC time as in the failures below): ";
  for (std::size_t i = 0; i < in.traces.size(); ++i) {
    const fs::path p(in.traces[i]);
    std::error_code ec;
    const bool here = fs::equivalent(p.parent_path().empty() ? fs::path(".") : p.parent_path(),
                                     in.opt.report_dir.empty() ? fs::path(".") : fs::path(in.opt.report_dir), ec);
    const std::string href = here ? p.filename().string() : fs::absolute(p).string();
    h << (i ? ", " : "") << "<a href=\"" << xml_attr(href) << "\">" << escape(p.filename().string()) << "</a>";
  }
  h << "</p>\n";
}

void write_html_head(std::ostream& h, const ReportInput& in, const std::string& verdict,
                     const std::vector<std::string>& engines) {
  const bool ok = verdict.find(" PASS ") != std::string::npos;
  h << "<!-- " << verdict << " -->\n<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
    << "<title>contour cosim " << escape(in.suite) << ": " << escape(verdict) << "</title><style>" << css()
    << "</style></head><body>\n";
  h << "<h1 class=\"" << (ok ? "pass" : "fail") << "\">" << escape(verdict) << "</h1>\n";
  const Tally t = tally(in.rows);
  std::set<std::pair<std::string, double>> runs;
  std::set<double> rates;
  for (const auto& r : in.rows)
    if (r.ran()) runs.insert({r.case_name, r.rate_pps}), rates.insert(r.rate_pps);
  h << "<p class=\"meta\">Suite <b>" << escape(in.suite) << "</b>: " << in.cases.size() << " case(s), "
    << runs.size() << " (case, rate) run(s) at " << rates.size() << " rate(s)";
  if (!rates.empty()) h << " from " << rate_label(*rates.begin()) << " to " << rate_label(*rates.rbegin()) << " pps";
  h << "; " << t.passed + t.failed << " row(s) ran (" << t.passed << " passed, " << t.failed << " failed)";
  if (t.not_run) h << ", " << t.not_run << " NOT RUN";
  h << "; engines ";
  for (std::size_t i = 0; i < engines.size(); ++i) h << (i ? ", " : "") << "<b>" << escape(engines[i]) << "</b>";
  h << ". Simulated " << fmt("%.3f", in.sim_seconds) << " s of SystemC time in " << fmt("%.1f", in.wall_seconds)
    << " s.<br>Command: <code>" << escape(in.command) << "</code><br>"
    << "Clocks: core " << fmt("%g", in.opt.core_hz / 1e6) << " MHz (output stage STEP_LEN " << in.opt.timing.len
    << ", STEP_SPACE " << in.opt.timing.space << ", DIR_SETUP " << in.opt.timing.setup << ", DIR_HOLD "
    << in.opt.timing.hold << " clocks), 8085 " << fmt("%g", in.opt.cpu_hz / 1e6) << " MHz. "
    << "Command rates each engine takes: the core up to " << rate_label(max_rate("core", in.opt.core_hz))
    << " pps (its pin is sampled at " << fmt("%g", in.opt.core_hz / 1e6) << " MHz), the 8085 engines up to "
    << rate_label(kMaxRate8085) << " pps (above: NOT RUN).</p>\n";
  write_html_traces(h, in);
  for (const auto& f : in.opt.faults)
    h << "<p class=\"fault\">A fault was injected: <code>--inject " << escape(to_string(f))
      << "</code> corrupts the " << escape(f.engine)
      << " engine's output on its way to the scoreboard. This run tests the scoreboard: the failures it causes "
         "are planted, not the engine's.</p>\n";
}

std::string how_to_read(const ReportInput& in) {
  const StepTiming& t = in.opt.timing;
  const double carry = core_carry_rate(in.opt.core_hz, t.len, t.space, t.setup, t.hold);
  return "<h2>How to read this</h2><p class=\"meta\">Every engine gets the same command pulse train (N pulses at the "
         "rate, N = the model's output pulse count). Its output pulses are compared one by one with the golden "
         "model's (axis, sign, order); <b>lost</b> = command pulses that gave no output pulse, <b>overruns</b> = the "
         "ones the engine itself flagged (core: OVR_COUNT; 8085 program: the mailbox overrun count). "
         "<b>PASS</b>: identical pulses, nothing lost. <b>FLAGGED</b>: the pulses given are the model's, and every "
         "lost command pulse was flagged (allowed above an engine's limit). <b>FAIL</b>: a pulse differs, a loss was "
         "not flagged, the final position is wrong, or an engine lost pulses where it must keep up (the core up to "
         + rate_label_approx(keep_up_rate("core", carry)) + " pps: paper A's " + rate_label(kCoreRequiredRate) +
         " pps or what its output stage carries at the programmed timing, " + fmt("%g", in.opt.core_hz / 1e6) +
         " MHz / (STEP_LEN + STEP_SPACE + DIR_SETUP + DIR_HOLD) = " + rate_label_approx(carry) +
         " pps, whichever is lower; the 8085 up to " + rate_label(kRequiredRate8085) + " pps). <b>NOT RUN</b>: the "
         "engine cannot take the rate. Cells read <i>verdict lost/overruns</i>. In a divergence, <i>at (x, y)</i> is the position on the "
         "case's path (its start is (0, 0)); the states are in the move's own frame (a line from its start, an arc "
         "from its centre), as in docs/algorithm.md.</p>\n";
}

// Where each engine falls behind: a table and the lost-pulse plots.
void write_html_limits(std::ostream& h, const ReportInput& in, const std::vector<std::string>& engines) {
  h << "<h2>Where each engine falls behind</h2>\n<p class=\"meta\">Rates in pulses/s: the highest rate up to "
       "which the engine agreed at every rate, the lowest at which it lost command pulses, the lowest at which a "
       "pulse differed from the model's.</p>\n<table><tr><th class=\"l\">case</th>";
  for (const auto& e : engines)
    h << "<th>" << escape(e) << ": agrees up to</th><th>first loss</th><th>first mismatch</th>";
  h << "</tr>\n";
  for (const auto& c : in.cases) {
    h << "<tr><td class=\"l\">" << escape(c.name) << "</td>";
    for (const auto& e : engines) {
      const Limit l = limit_of(in.rows, c.name, e);
      h << "<td>" << (l.agree_up_to > 0 ? rate_label(l.agree_up_to) : "-") << "</td><td>"
        << (l.first_loss > 0 ? rate_label(l.first_loss) : "none") << "</td><td"
        << (l.first_mismatch > 0 ? " class=\"FAIL\">" + rate_label(l.first_mismatch) : ">none") << "</td>";
    }
    h << "</tr>\n";
  }
  h << "</table>\n<p class=\"meta\">Paper A (Table 1): the 8085 at 3 MHz kept up to 4.0 kpps (linear) and 3.0 kpps "
       "(circular); a dedicated processor was expected to reach 250 kpps.</p>\n";
  h << "<div class=\"plots\">" << lost_all_svg(in.rows) << "</div>\n<div class=\"plots\">\n";
  for (const auto& c : in.cases) h << lost_svg(c.name, in.rows) << "\n";
  h << "</div>\n";
}

// The contract's bins, hits per engine, unreached bins in red.
void write_html_coverage(std::ostream& h, const Coverage& c, const std::vector<std::string>& engines) {
  h << "<h2 id=\"coverage\">Functional coverage of the contract: " << c.hit() << " of " << c.bins().size()
    << " bins (" << fmt("%.2f%%", c.percent()) << ")</h2>\n<p class=\"meta\">Each bin counts what the engines "
       "did, not what the cases ask for: every passed run's own output pulses are replayed in the move's frame "
       "against docs/algorithm.md (quadrant table Q, D, the tie and end-point rules, crossings), plus what its host "
       "side saw (queue full, a refused PUSH, ABORT). Failed runs count nothing. The ABORT bin is an abort of a "
       "loaded move before its first step and of a queued one, before every core case; an abort in the middle of "
       "the steps is tested by tb/interp (InterpTop.AbortInTheMiddleThenANewMove), not here.</p>\n"
       "<table><tr><th class=\"l\">group</th><th class=\"l\">bin</th>";
  for (const auto& e : engines) h << "<th>" << escape(e) << "</th>";
  h << "<th>total</th></tr>\n";
  for (const auto& b : c.bins()) {
    h << "<tr><td class=\"l\">" << escape(b.group) << "</td><td class=\"l\">" << escape(b.name) << "</td>";
    for (const auto& e : engines) {
      const auto it = b.hits.find(e);
      h << "<td>" << (it == b.hits.end() ? 0 : it->second) << "</td>";
    }
    h << "<td class=\"" << (b.total() ? "PASS" : "FAIL") << "\">" << b.total() << "</td></tr>\n";
  }
  h << "</table>\n";
}

// The core's line and toggle coverage, when `make coverage` was run.
void write_html_rtl_coverage(std::ostream& h, const std::optional<RtlCoverage>& c) {
  h << "<h3>Line and toggle coverage of the core (<code>make coverage</code>)</h3>\n<p class=\"meta\">";
  if (!c) {
    h << "Not run: <code>make coverage</code> writes <code>build/coverage/merged.dat</code> (the interp_core "
         "regression of tb/interp; docs/rtl.md, Coverage), which this report then shows.</p>\n";
    return;
  }
  auto pct = [](std::uint64_t hit, std::uint64_t all) {
    return all ? fmt("%.1f%%", 100.0 * double(hit) / double(all)) + " (" + std::to_string(hit) + "/" +
                     std::to_string(all) + ")"
               : std::string("-");
  };
  h << "Lines (v_line + v_branch): <b>" << pct(c->lines_hit, c->lines) << "</b>; toggles: <b>"
    << pct(c->toggles_hit, c->toggles) << "</b>. From <code>" << escape(c->path)
    << "</code> (the interp_core regression of tb/interp, W = 8 and W = 24; the causes of the points never hit "
       "are in docs/rtl.md, Coverage).</p>\n";
  if (c->uncovered.empty()) return;
  h << "<details><summary>" << c->uncovered.size() << " point(s) never hit (page, source line, signal)</summary><pre>";
  for (const auto& u : c->uncovered) h << escape(u) << "\n";
  h << "</pre></details>\n";
}

void write_html_failures(std::ostream& h, const std::vector<Row>& rows, const Options& opt) {
  std::vector<const Row*> failed;
  for (const auto& r : rows)
    if (r.verdict == Verdict::Fail) failed.push_back(&r);
  h << "<h2>Failures (" << failed.size() << ")</h2>\n";
  if (failed.empty()) h << "<p>None.</p>\n";
  for (const Row* r : failed) {
    h << "<h3>" << escape(r->case_name) << " on " << escape(r->engine) << " at " << rate_label(r->rate_pps)
      << " pps</h3><p>" << escape(r->note) << "</p>\n<p class=\"meta\">The case started at SystemC time "
      << fmt("%.3f", r->case_start_us) << " us";
    if (r->divergence && r->divergence->t_us >= 0)
      h << "; the first divergence came at " << fmt("%.3f", r->case_start_us + r->divergence->t_us) << " us (t = "
        << fmt("%.3f", r->divergence->t_us) << " us into the case)";
    h << ". Re-run this row alone: <code>" << escape(rerun_command(*r, opt)) << "</code></p>\n";
    if (r->divergence) h << "<pre>" << escape(r->divergence->context) << "</pre>\n";
  }
}

const Row* find_row(const std::vector<Row>& rows, const std::string& case_name, const std::string& engine,
                    double rate) {
  const Row* found = nullptr;
  for (const auto& r : rows)
    if (r.case_name == case_name && r.engine == engine && r.rate_pps == rate) found = &r;
  return found;
}

std::string latency_cell(const Row* r) {
  if (!r || !r->has_latency) return "<td class=\"na\">-</td>";
  return "<td>" + fmt("%.3f", r->lat_min_us) + " / " + fmt("%.3f", r->lat_mean_us) + " / " +
         fmt("%.3f", r->lat_max_us) + (r->latency_exact ? "" : "*") + "</td>";
}

// One rate of a case: each engine's verdict, then the core and cpu latencies.
void write_rate_row(std::ostream& h, const ReportInput& in, const Case& c, double rate,
                    const std::vector<std::string>& engines) {
  h << "<tr><td>" << rate_label(rate) << "</td>";
  const Row* lat[2] = {nullptr, nullptr};
  for (const auto& e : engines) {
    const Row* found = find_row(in.rows, c.name, e, rate);
    if (!found) {
      h << "<td class=\"na\">-</td>";
      continue;
    }
    if (e == "core") lat[0] = found;
    if (e == "cpu") lat[1] = found;
    h << "<td class=\"" << css_class(found->verdict) << "\" title=\"" << xml_attr(found->note) << "\">"
      << cell_text(*found) << "</td>";
  }
  for (const Row* r : lat) h << latency_cell(r);
  h << "</tr>\n";
}

void write_html_case(std::ostream& h, const ReportInput& in, std::size_t ci, const std::vector<std::string>& engines) {
  const Case& c = in.cases[ci];
  h << "<h3 id=\"" << escape(c.name) << "\">" << escape(c.name) << ": " << escape(c.title)
    << "</h3>\n<p class=\"meta\">";
  for (std::size_t i = 0; i < c.moves.size(); ++i)
    h << (i ? ", " : "") << "<code>" << escape(describe(c.moves[i])) << "</code>";
  h << "; " << in.exps[ci].pulses.size() << " output pulses.</p>\n<table><tr><th>rate (pps)</th>";
  for (const auto& e : engines) h << "<th>" << escape(e) << "</th>";
  h << "<th>core latency (us)</th><th>cpu latency (us)</th></tr>\n";
  std::set<double> ran;  // only the rates the case ran at
  for (const auto& r : in.rows)
    if (r.case_name == c.name && r.ran()) ran.insert(r.rate_pps);
  for (double rate : ran) write_rate_row(h, in, c, rate, engines);
  h << "</table>\n<p class=\"meta\">Latency: min / mean / max from a command pulse's rising edge to its output "
       "step pulse; * = pulses were lost, measured from the latest command pulse.</p>\n";
  std::vector<const Row*> diverged;
  for (const auto& r : in.rows)
    if (r.case_name == c.name && r.divergence) diverged.push_back(&r);
  h << "<div class=\"plots\">" << path_svg(c, in.exps[ci], diverged) << deviation_svg(c, in.exps[ci]) << "</div>\n";
}

// Everything, for the record.
void write_html_all_results(std::ostream& h, const std::vector<Row>& rows) {
  h << "<h2>All results</h2>\n<details><summary>" << rows.size()
    << " rows (case, engine, rate)</summary><table><tr><th class=\"l\">case</th><th class=\"l\">engine</th>"
       "<th>rate</th><th>commands</th><th>pulses</th><th>mismatches</th><th>lost</th><th>overruns</th>"
       "<th>verdict</th><th class=\"l\">note</th></tr>\n";
  for (const auto& r : rows)
    h << "<tr><td class=\"l\">" << escape(r.case_name) << "</td><td class=\"l\">" << escape(r.engine) << "</td><td>"
      << rate_label(r.rate_pps) << "</td><td>" << r.commands << "</td><td>" << r.pulses << "</td><td>" << r.mismatches
      << "</td><td>" << r.lost << "</td><td>" << (r.overruns < 0 ? std::string("-") : std::to_string(r.overruns))
      << "</td><td class=\"" << css_class(r.verdict) << "\">" << to_string(r.verdict) << "</td><td class=\"l\">"
      << escape(r.note) << "</td></tr>\n";
  h << "</table></details>\n";
}

std::string report_html(const ReportInput& in, const std::string& verdict, const std::vector<std::string>& engines) {
  std::ostringstream h;
  write_html_head(h, in, verdict, engines);
  h << how_to_read(in);
  write_html_limits(h, in, engines);
  write_html_failures(h, in.rows, in.opt);
  if (in.coverage) write_html_coverage(h, *in.coverage, engines);
  if (in.coverage) write_html_rtl_coverage(h, in.rtl_coverage);
  h << "<h2>Cases</h2>\n";
  for (std::size_t ci = 0; ci < in.cases.size(); ++ci) write_html_case(h, in, ci, engines);
  write_html_all_results(h, in.rows);
  h << "<h2>Engines</h2><ul>";
  for (const auto& e : engines) h << "<li>" << escape(engine_title(e)) << "</li>";
  h << "</ul>\n</body></html>\n";
  return h.str();
}

// The engines that have rows, in the usual order.
std::vector<std::string> engines_in(const std::vector<Row>& rows) {
  std::vector<std::string> engines;
  for (const auto& e : engine_names())
    for (const auto& r : rows)
      if (r.engine == e) {
        engines.push_back(e);
        break;
      }
  return engines;
}

// Writes DIR/NAME and adds its path to `written`.
void write_file(const std::string& dir, const std::string& name, const std::string& text,
                std::vector<std::string>& written) {
  const std::string path = dir + "/" + name;
  std::ofstream f(path);
  f << text;
  if (!f) throw std::runtime_error(path + ": write failed");
  written.push_back(path);
}

}  // namespace

std::vector<std::pair<double, double>> drawn_pulse_path(const Case& c, const Expected& e) {
  std::vector<std::pair<double, double>> out;
  for (const auto& p : shifted(pulse_path(e.pulses), move_frame_shift(c))) out.push_back({p.x, p.y});
  return out;
}

std::vector<std::string> write_reports(const std::string& dir, const ReportInput& in) {
  std::vector<std::string> written;
  const std::string verdict = verdict_line(in.rows);
  const std::vector<std::string> engines = engines_in(in.rows);
  write_file(dir, "report.json", report_json(in, verdict, engines), written);
  write_file(dir, "junit.xml", junit_xml(in), written);
  write_file(dir, "report.html", report_html(in, verdict, engines), written);
  return written;
}

}  // namespace contour::cosim
