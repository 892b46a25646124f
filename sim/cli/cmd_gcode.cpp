// `contour gcode FILE`: paper B's planner on a G-code program. Prints a
// summary or JSON, and optionally a per-cycle CSV, SVG plots like paper B's
// figures, or the two-stage 3-axis step stream.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "args.hpp"
#include "gcode/gcode.hpp"
#include "planner/planner.hpp"
#include "plot/svg.hpp"
#include "planner/two_stage.hpp"
#include "registry.hpp"

namespace contour::cli {
namespace {

using planner::ChordMethod;
using planner::Config;

const char* kHelp =
    "usage: contour gcode FILE [options]\n"
    "Runs a G-code program (G0-G3, G17-G19, G20/G21, G90/G91; 3D arcs as paper B)\n"
    "through paper B's planner: trapezoidal acc/dec planned on the path, one chord per\n"
    "control cycle within the tolerance. Defaults are paper B's conditions.\n"
    "\noptions:\n"
    "  --format F        summary (default) or json (total time as \"total_time_s\")\n"
    "  --accel A         acceleration limit of every axis, mm/min^2 (default 3528000 = 0.1 g)\n"
    "  --cycle MS        control cycle, ms (default 1)\n"
    "  --tol UM          chord tolerance, um (default 0.02)\n"
    "  --chord M         chord placement, paper B Fig. 1: a inside, b outside,\n"
    "                    c inside and outside (default c)\n"
    "  --config FILE     machine limits, lines 'key = value' ('#' comments): vmax_x vmax_y\n"
    "                    vmax_z (mm/min), amax_x amax_y amax_z (mm/min^2), rapid (mm/min);\n"
    "                    --accel overrides the amax_ keys\n"
    "  --csv FILE        one row per cycle: t, X, Y, Z, feed, vx, vy, vz (mm, mm/min)\n"
    "  --svg DIR         velocity.svg (axis velocity profiles), xy.svg, yz.svg, zx.svg\n"
    "                    (trajectories) and uv-line<N>.svg (each arc in its UV plane)\n"
    "  --pulses          print the two-stage step stream instead: one line per pulse,\n"
    "                    '<time s> <+X|-X|+Y|...>'; each cycle's chord, rounded to steps,\n"
    "                    drives the 3-axis linear interpolator, pulses spread over the cycle\n"
    "  --steps-per-mm N  with --pulses: steps per mm (default 1000)\n"
    "  --engine E        with --pulses: stage-2 engine, %s (default model)\n"
    "Exit status: 0 all limits respected, 1 a limit or the tolerance was exceeded,\n"
    "2 bad input (one line on stderr naming the problem).\n";

std::string stage_names() {
  std::string s;
  for (const auto& [name, fn] : planner::pulse_stages()) s += (s.empty() ? "" : "|") + name;
  return s;
}

double positive(const std::string& text, const std::string& what) {
  const double v = parse_real(text, what);
  if (!(v > 0)) throw UsageError(what + ": must be > 0 (got '" + text + "')");
  return v;
}

void read_config(const std::string& path, planner::Machine& m) {
  std::ifstream in(path);
  if (!in) throw UsageError("--config: cannot read '" + path + "'");
  std::string line;
  int n = 0;
  while (std::getline(in, line)) {
    ++n;
    if (auto h = line.find('#'); h != std::string::npos) line.erase(h);
    const auto first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos) continue;
    const auto eq = line.find('=');
    const std::string where = path + ":" + std::to_string(n);
    if (eq == std::string::npos) throw UsageError(where + ": expected 'key = value'");
    auto trim = [](std::string s) {
      const auto a = s.find_first_not_of(" \t\r"), b = s.find_last_not_of(" \t\r");
      return a == std::string::npos ? std::string() : s.substr(a, b - a + 1);
    };
    const std::string key = trim(line.substr(0, eq)), val = trim(line.substr(eq + 1));
    const double v = positive(val, where + ": " + key);
    const std::string axes = "xyz";
    if (key.size() == 6 && (key.rfind("vmax_", 0) == 0 || key.rfind("amax_", 0) == 0) &&
        axes.find(key[5]) != std::string::npos) {
      const int i = static_cast<int>(axes.find(key[5]));
      if (key[0] == 'v') m.vmax[i] = v / 60;
      else m.amax[i] = v / 3600;
    } else if (key == "rapid") {
      m.rapid = v / 60;
    } else {
      throw UsageError(where + ": unknown key '" + key + "' (vmax_x|y|z, amax_x|y|z, rapid)");
    }
  }
}

std::string json_string(const std::string& s) {
  std::string o = "\"";
  for (unsigned char c : s) {
    if (c == '"' || c == '\\') o += '\\', o += static_cast<char>(c);
    else if (c < 0x20) {
      char b[8];
      std::snprintf(b, sizeof b, "\\u%04x", c);
      o += b;
    } else o += static_cast<char>(c);
  }
  return o + "\"";
}

const char* kind_name(const planner::Segment& g) {
  if (g.kind == planner::Segment::Kind::Line) return g.rapid ? "G0 line" : "G1 line";
  if (g.arc3d) return "3D arc";
  if (g.helix()) return "helix";
  return g.full_circle ? "full circle" : "arc";
}

void write_csv(const std::string& path, const std::vector<planner::Sample>& s, double T) {
  std::ofstream o(path);
  if (!o) throw UsageError("--csv: cannot write '" + path + "'");
  o << "t_s,x_mm,y_mm,z_mm,feed_mm_min,vx_mm_min,vy_mm_min,vz_mm_min\n";
  char b[256];
  for (std::size_t n = 0; n < s.size(); ++n) {
    Vec3 v;
    if (n > 0) v = (60.0 / T) * (s[n].p - s[n - 1].p);
    std::snprintf(b, sizeof b, "%.6f,%.9f,%.9f,%.9f,%.6f,%.6f,%.6f,%.6f\n", s[n].t, s[n].p.x, s[n].p.y, s[n].p.z,
                  norm(v), v.x, v.y, v.z);
    o << b;
  }
}

void write_file(const std::filesystem::path& p, const std::string& text) {
  std::ofstream o(p);
  if (!o) throw UsageError("--svg: cannot write '" + p.string() + "'");
  o << text;
}

int write_svgs(const std::string& dir, const std::string& file, const planner::Plan& plan,
               const std::vector<planner::Sample>& s) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec || !std::filesystem::is_directory(dir)) throw UsageError("--svg: cannot create directory '" + dir + "'");
  const double T = plan.config.cycle_s;
  const std::string name = std::filesystem::path(file).filename().string();
  int files = 0;
  {
    plot::Plot p;
    p.title = "Axis velocity profiles: " + name;
    p.x_label = "time (s)";
    p.y_label = "velocity (mm/min)";
    plot::Series vx{"Vx", "#1f77b4", {}}, vy{"Vy", "#d62728", {}}, vz{"Vz", "#2ca02c", {}}, f{"feed", "#999999", {}};
    for (std::size_t n = 1; n < s.size(); ++n) {
      const Vec3 v = (60.0 / T) * (s[n].p - s[n - 1].p);
      const double t = s[n].t - T / 2;  // the chord's mid-time
      vx.points.push_back({t, v.x});
      vy.points.push_back({t, v.y});
      vz.points.push_back({t, v.z});
      f.points.push_back({t, norm(v)});
    }
    p.series = {f, vx, vy, vz};
    write_file(std::filesystem::path(dir) / "velocity.svg", plot::render(p));
    ++files;
  }
  const struct {
    const char* file;
    int a, b;
  } planes[] = {{"xy.svg", 0, 1}, {"yz.svg", 1, 2}, {"zx.svg", 2, 0}};
  const char* names = "XYZ";
  for (const auto& pl : planes) {
    plot::Plot p;
    p.title = std::string("Trajectory in the ") + names[pl.a] + names[pl.b] + " plane: " + name;
    p.x_label = std::string(1, names[pl.a]) + " (mm)";
    p.y_label = std::string(1, names[pl.b]) + " (mm)";
    p.equal_aspect = true;
    plot::Series path{"interpolated", "#d62728", {}};
    for (const auto& x : s) path.points.push_back({x.p[pl.a], x.p[pl.b]});
    p.series = {path};
    write_file(std::filesystem::path(dir) / pl.file, plot::render(p));
    ++files;
  }
  int arcs = 0;
  for (std::size_t k = 0; k < plan.segs.size() && arcs < 20; ++k) {
    const auto& g = plan.segs[k].geom;
    if (g.kind != planner::Segment::Kind::Arc) continue;
    ++arcs;
    plot::Plot p;
    p.title = std::string("Line ") + std::to_string(g.line) + " (" + kind_name(g) + ") in its UV plane";
    p.x_label = "U (mm)";
    p.y_label = "V (mm)";
    p.equal_aspect = true;
    plot::Series path{"interpolated", "#d62728", {}}, marks{"Qs, Qc, Qe", "#1f77b4", {}, 1.0, true, true};
    for (const auto& x : s) {
      if (x.seg != static_cast<int>(k)) continue;
      const Vec3 w = x.p - g.origin;
      path.points.push_back({dot(w, g.u_hat), dot(w, g.v_hat)});
    }
    marks.points = {{g.qs.u, g.qs.v}, {g.qc.u, g.qc.v}, {g.qe.u, g.qe.v}};
    p.series = {path, marks};
    write_file(std::filesystem::path(dir) / ("uv-line" + std::to_string(g.line) + ".svg"), plot::render(p));
    ++files;
  }
  return files;
}

int run_gcode_command(const std::vector<std::string>& argv) {
  const Args a(argv, {"pulses"},
               {"format", "accel", "cycle", "tol", "chord", "config", "csv", "svg", "steps-per-mm", "engine"});
  if (a.help()) {
    std::printf(kHelp, stage_names().c_str());
    return 0;
  }
  a.expect_positional({"FILE"});
  const std::string file = a.positional()[0];
  const std::string format = a.option_or("format", "summary");
  if (format != "summary" && format != "json")
    throw UsageError("--format: unknown format '" + format + "' (one of summary, json)");

  Config c;
  if (auto f = a.option("config")) read_config(*f, c.machine);
  if (auto v = a.option("accel")) {
    const double acc = positive(*v, "--accel") / 3600;
    c.machine.amax = {acc, acc, acc};
  }
  if (auto v = a.option("cycle")) c.cycle_s = positive(*v, "--cycle") / 1000;
  if (auto v = a.option("tol")) c.tol_mm = positive(*v, "--tol") / 1000;
  if (auto v = a.option("chord")) {
    if (*v == "a") c.chord = ChordMethod::Inside;
    else if (*v == "b") c.chord = ChordMethod::Outside;
    else if (*v == "c") c.chord = ChordMethod::InsideOutside;
    else throw UsageError("--chord: unknown placement '" + *v + "' (one of a, b, c)");
  }
  const bool pulses = a.flag("pulses");
  if (!pulses && a.option("engine")) throw UsageError("--engine needs --pulses");
  if (!pulses && a.option("steps-per-mm")) throw UsageError("--steps-per-mm needs --pulses");
  if (pulses && (a.option("csv") || a.option("svg") || a.option("format")))
    throw UsageError("--pulses prints the step stream; it does not combine with --format, --csv or --svg");
  const double spm = pulses ? positive(a.option_or("steps-per-mm", "1000"), "--steps-per-mm") : 1000;
  const std::string engine = a.option_or("engine", "model");
  if (pulses && !planner::pulse_stages().count(engine))
    throw UsageError("--engine: unknown engine '" + engine + "' (one of " + stage_names() + ")");

  std::ifstream in(file, std::ios::binary);
  if (!in) throw UsageError("cannot read '" + file + "'");
  std::stringstream buf;
  buf << in.rdbuf();
  std::vector<gcode::Block> blocks;
  try {
    blocks = gcode::parse(buf.str());
  } catch (const gcode::Error& e) {
    throw UsageError(file + ": " + e.what());
  }
  planner::Plan plan;
  try {
    plan = planner::plan(blocks, c);
  } catch (const std::invalid_argument& e) {
    throw UsageError(file + ": " + e.what());
  }
  constexpr double kMaxCycles = 2e7;  // samples are kept in memory (~64 bytes each)
  if (plan.total_time / c.cycle_s > kMaxCycles)
    throw UsageError(file + ": the program runs " + std::to_string(plan.total_time) + " s = " +
                     std::to_string(static_cast<long long>(plan.total_time / c.cycle_s)) +
                     " cycles, more than this tool simulates (2e7)");
  const auto samples = planner::interpolate(plan);

  if (pulses) {
    std::vector<planner::TimedPulse> out;
    try {
      out = planner::pulse_stages().at(engine)(planner::chords_in_steps(samples, spm), c.cycle_s);
    } catch (const InputError& e) {
      throw UsageError(std::string("--pulses: ") + e.what());
    } catch (const std::invalid_argument& e) {
      throw UsageError(std::string("--pulses: ") + e.what());
    }
    std::string text;
    char b[64];
    for (const auto& p : out) {
      std::snprintf(b, sizeof b, "%.9f %s\n", p.t, to_string(p.pulse).c_str());
      text += b;
      if (text.size() > (1u << 16)) std::fputs(text.c_str(), stdout), text.clear();
    }
    std::fputs(text.c_str(), stdout);
    return 0;
  }

  const planner::Report r = planner::analyse(plan, samples);
  if (auto p = a.option("csv")) write_csv(*p, samples, c.cycle_s);
  int svg_files = 0;
  if (auto d = a.option("svg")) svg_files = write_svgs(*d, file, plan, samples);
  bool all_ok = r.tol_ok;
  for (const auto& ax : r.axes) all_ok = all_ok && ax.v_ok && ax.a_ok;
  const char* names[] = {"X", "Y", "Z"};

  if (format == "json") {
    std::ostringstream o;
    o.precision(10);
    o << "{\"file\": " << json_string(file) << ", \"blocks\": " << plan.segs.size() << ", \"cycles\": " << r.cycles
      << ", \"cycle_s\": " << c.cycle_s << ", \"total_time_s\": " << r.total_time_s
      << ", \"tolerance_mm\": " << c.tol_mm << ", \"chord_method\": \"" << planner::chord_name(c.chord)
      << "\", \"peak_feed_mm_min\": " << r.peak_feed * 60 << ", \"max_chord_error_mm\": " << r.max_chord_error
      << ", \"tolerance_ok\": " << (r.tol_ok ? "true" : "false") << ", \"axes\": {";
    for (int i = 0; i < 3; ++i) {
      const auto& ax = r.axes[i];
      o << (i ? ", " : "") << "\"" << names[i] << "\": {\"peak_velocity_mm_min\": " << ax.peak_v * 60
        << ", \"velocity_limit_mm_min\": " << ax.vmax * 60 << ", \"velocity_ok\": " << (ax.v_ok ? "true" : "false")
        << ", \"peak_accel_mm_min2\": " << ax.peak_a * 3600 << ", \"accel_limit_mm_min2\": " << ax.amax * 3600
        << ", \"accel_ok\": " << (ax.a_ok ? "true" : "false") << "}";
    }
    o << "}, \"segments\": [";
    for (std::size_t k = 0; k < plan.segs.size(); ++k) {
      const auto& s = plan.segs[k];
      o << (k ? ", " : "") << "{\"line\": " << s.geom.line << ", \"kind\": \"" << kind_name(s.geom)
        << "\", \"length_mm\": " << s.geom.length << ", \"time_s\": " << s.duration
        << ", \"v_start_mm_min\": " << s.v_start * 60 << ", \"v_cruise_mm_min\": " << s.v_cruise * 60
        << ", \"v_end_mm_min\": " << s.v_end * 60 << ", \"accel_mm_s2\": " << s.a_t << ", \"cap\": \""
        << planner::cap_name(s.cap) << "\"}";
    }
    o << "], \"all_ok\": " << (all_ok ? "true" : "false") << "}\n";
    std::fputs(o.str().c_str(), stdout);
  } else {
    std::printf("program        %s: %zu blocks, %zu cycles of %g ms\n", file.c_str(), plan.segs.size(), r.cycles,
                c.cycle_s * 1000);
    std::printf("total time     %.4f s\n", r.total_time_s);
    std::printf("peak feed      %.1f mm/min\n", r.peak_feed * 60);
    std::printf("max chord err  %.4f um (tolerance %g um, chord method %s): %s\n", r.max_chord_error * 1000,
                c.tol_mm * 1000, planner::chord_name(c.chord), r.tol_ok ? "ok" : "EXCEEDED");
    std::printf("axis  peak v (mm/min)  limit        peak a (mm/min^2)  limit\n");
    for (int i = 0; i < 3; ++i) {
      const auto& ax = r.axes[i];
      std::printf("%-5s %-16.1f %-9.1f %-3s %-18.0f %-9.0f %s\n", names[i], ax.peak_v * 60, ax.vmax * 60,
                  ax.v_ok ? "ok" : "EXCEEDED", ax.peak_a * 3600, ax.amax * 3600, ax.a_ok ? "ok" : "EXCEEDED");
    }
    std::printf("blocks:\n");
    for (const auto& s : plan.segs)
      std::printf("  line %-4d %-11s %10.3f mm  %8.1f -> %8.1f -> %8.1f mm/min  %8.4f s  (cruise cap: %s)\n",
                  s.geom.line, kind_name(s.geom), s.geom.length, s.v_start * 60, s.v_cruise * 60, s.v_end * 60,
                  s.duration, planner::cap_name(s.cap));
    if (svg_files) std::printf("svg            %d files in %s\n", svg_files, a.option("svg")->c_str());
  }
  return all_ok ? 0 : 1;
}

const CommandRegistrar kRegistrar{
    Command{"gcode", "paper B: plan and chord-interpolate a G-code program", run_gcode_command}};

}  // namespace
}  // namespace contour::cli
