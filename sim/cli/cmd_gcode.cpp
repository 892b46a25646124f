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
    "Runs a G-code program (RS274/NGC as LinuxCNC reads it, the subset in\n"
    "model/gcode/gcode.hpp; 3D arcs as paper B; M S T G4 G43 G54.. as events)\n"
    "through paper B's planner: trapezoidal acc/dec planned on the path, one chord per\n"
    "control cycle within the tolerance. Defaults are paper B's conditions.\n"
    "\noptions:\n"
    "  --format F        summary (default), json (total time as \"total_time_s\"), or moves:\n"
    "                    the reader's output only, one line per move (RAPID|LINE feed x y z,\n"
    "                    ARC feed plane CW|CCW x y z cx cy cz), DWELL s, STOP, EVENT code\n"
    "                    and END, machine mm and mm/min\n"
    "  --tool-table FILE tool lengths for G43 H, LinuxCNC's format ('T1 P1 Z12.5'), Z in mm\n"
    "  --accel A         acceleration limit of every axis, mm/min^2 (default 3528000 = 0.1 g)\n"
    "  --cycle MS        control cycle, ms (default 1, at most 1000)\n"
    "  --tol UM          chord tolerance, um (default 0.02)\n"
    "  --blend-tol UM    corner tolerance of G64 without P, um (default 10): a corner\n"
    "                    between feed moves is passed at speed when the chord that cuts\n"
    "                    it stays within this (G64 P sets it per block; G61 stops)\n"
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
    "Exit status: 0 all limits respected, 1 a limit or a tolerance was exceeded by more\n"
    "than 1e-6 relative (floating-point rounding is not an excess),\n"
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

// Refuses a path that is a directory (an ifstream opens one and reads nothing).
void require_regular_file(const std::string& path, const std::string& what) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw UsageError(what + "'" + path + "' is a directory, not a file");
}

void read_config(const std::string& path, planner::Machine& m) {
  require_regular_file(path, "--config: ");
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
  if (g.kind == planner::Segment::Kind::Dwell) return g.dwell_s > 0 ? "dwell" : "stop";
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

// The axis velocity profiles (paper B's velocity figures), one point per chord.
plot::Plot velocity_plot(const std::string& name, const std::vector<planner::Sample>& s, double T) {
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
  return p;
}

// The trajectory projected on the plane of axes `a` and `b` (0 X, 1 Y, 2 Z).
plot::Plot plane_plot(const std::string& name, const std::vector<planner::Sample>& s, int a, int b) {
  const char* names = "XYZ";
  plot::Plot p;
  p.title = std::string("Trajectory in the ") + names[a] + names[b] + " plane: " + name;
  p.x_label = std::string(1, names[a]) + " (mm)";
  p.y_label = std::string(1, names[b]) + " (mm)";
  p.equal_aspect = true;
  plot::Series path{"interpolated", "#d62728", {}};
  for (const auto& x : s) path.points.push_back({x.p[a], x.p[b]});
  p.series = {path};
  return p;
}

// Segment `k`, an arc, in its own UV plane with its points Qs, Qc, Qe.
plot::Plot uv_plot(const planner::Segment& g, std::size_t k, const std::vector<planner::Sample>& s) {
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
  return p;
}

int write_svgs(const std::string& dir, const std::string& file, const planner::Plan& plan,
               const std::vector<planner::Sample>& s) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec || !std::filesystem::is_directory(dir)) throw UsageError("--svg: cannot create directory '" + dir + "'");
  const std::string name = std::filesystem::path(file).filename().string();
  int files = 0;
  write_file(std::filesystem::path(dir) / "velocity.svg", plot::render(velocity_plot(name, s, plan.config.cycle_s)));
  ++files;
  const struct {
    const char* file;
    int a, b;
  } planes[] = {{"xy.svg", 0, 1}, {"yz.svg", 1, 2}, {"zx.svg", 2, 0}};
  for (const auto& pl : planes) {
    write_file(std::filesystem::path(dir) / pl.file, plot::render(plane_plot(name, s, pl.a, pl.b)));
    ++files;
  }
  int arcs = 0;
  for (std::size_t k = 0; k < plan.segs.size() && arcs < 20; ++k) {
    const auto& g = plan.segs[k].geom;
    if (g.kind != planner::Segment::Kind::Arc) continue;
    ++arcs;
    const std::string uv_file = "uv-line" + std::to_string(g.line) + ".svg";
    write_file(std::filesystem::path(dir) / uv_file, plot::render(uv_plot(g, k, s)));
    ++files;
  }
  return files;
}

constexpr double kMaxCycleS = 1.0;  // --cycle: a control cycle of at most 1 s

ChordMethod parse_chord(const std::string& v) {
  if (v == "a") return ChordMethod::Inside;
  if (v == "b") return ChordMethod::Outside;
  if (v == "c") return ChordMethod::InsideOutside;
  throw UsageError("--chord: unknown placement '" + v + "' (one of a, b, c)");
}

// The planner's configuration: paper B's defaults, then --config, then the
// options that override it.
Config parse_config(const Args& a) {
  Config c;
  if (auto f = a.option("config")) read_config(*f, c.machine);
  if (auto v = a.option("accel")) {
    const double acc = positive(*v, "--accel") / 3600;
    c.machine.amax = {acc, acc, acc};
  }
  if (auto v = a.option("cycle")) {
    c.cycle_s = positive(*v, "--cycle") / 1000;
    if (c.cycle_s > kMaxCycleS) throw UsageError("--cycle: at most 1000 ms (got '" + *v + "')");
  }
  if (auto v = a.option("tol")) c.tol_mm = positive(*v, "--tol") / 1000;
  if (auto v = a.option("blend-tol")) {
    c.blend_tol_mm = parse_real(*v, "--blend-tol") / 1000;
    if (!(c.blend_tol_mm >= 0) || !std::isfinite(c.blend_tol_mm))
      throw UsageError("--blend-tol: must be >= 0 (got '" + *v + "')");
  }
  if (auto v = a.option("chord")) c.chord = parse_chord(*v);
  return c;
}

std::string read_text(const std::string& file, const std::string& what) {
  require_regular_file(file, what);
  std::ifstream in(file, std::ios::binary);
  if (!in) throw UsageError(what + "cannot read '" + file + "'");
  // One copy of the text (a stringstream would hold a second).
  std::string text;
  char buf[1 << 16];
  while (in.read(buf, sizeof buf) || in.gcount() > 0) text.append(buf, static_cast<std::size_t>(in.gcount()));
  return text;
}

gcode::ToolTable read_tool_table(const std::string& file) {
  try {
    return gcode::read_tool_table(read_text(file, "--tool-table: "));
  } catch (const gcode::Error& e) {
    throw UsageError("--tool-table: " + file + ": " + e.what());
  }
}

gcode::Program read_program(const std::string& file, const gcode::Options& o) {
  const std::string text = read_text(file, "");
  try {
    return gcode::read(text, o);
  } catch (const gcode::Error& e) {
    throw UsageError(file + ": " + e.what());
  }
}

// What the command line asks for, checked.
struct Request {
  std::string file, format;
  Config config;
  bool pulses = false;        // print the two-stage step stream
  double steps_per_mm = 1000;
  std::string engine;         // the stage-2 engine of --pulses
  gcode::Options read;        // the tool table
};

Request parse_request(const Args& a) {
  Request q;
  a.expect_positional({"FILE"});
  q.file = a.positional()[0];
  q.format = a.option_or("format", "summary");
  if (q.format != "summary" && q.format != "json" && q.format != "moves")
    throw UsageError("--format: unknown format '" + q.format + "' (one of summary, json, moves)");
  q.config = parse_config(a);
  if (auto t = a.option("tool-table")) q.read.tools = read_tool_table(*t);
  q.pulses = a.flag("pulses");
  if (!q.pulses && a.option("engine")) throw UsageError("--engine needs --pulses");
  if (!q.pulses && a.option("steps-per-mm")) throw UsageError("--steps-per-mm needs --pulses");
  if (q.pulses && (a.option("csv") || a.option("svg") || a.option("format")))
    throw UsageError("--pulses prints the step stream; it does not combine with --format, --csv or --svg");
  if (q.pulses) q.steps_per_mm = positive(a.option_or("steps-per-mm", "1000"), "--steps-per-mm");
  q.engine = a.option_or("engine", "model");
  if (q.pulses && !planner::pulse_stages().count(q.engine))
    throw UsageError(unknown_engine(q.engine, stage_names()));
  return q;
}

// Plans the program; refuses one that runs more cycles than fit in memory.
planner::Plan plan_program(const std::string& file, const std::vector<gcode::Block>& blocks, const Config& c) {
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
  return plan;
}

// --pulses: one line per pulse of the two-stage step stream.
int print_pulses(const Request& q, const std::vector<planner::Sample>& samples) {
  std::vector<planner::TimedPulse> out;
  try {
    out = planner::pulse_stages().at(q.engine)(planner::chords_in_steps(samples, q.steps_per_mm), q.config.cycle_s);
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

const char* const kAxisNames[] = {"X", "Y", "Z"};

bool limits_respected(const planner::Report& r) {
  bool all_ok = r.tol_ok && r.blend_ok;
  for (const auto& ax : r.axes) all_ok = all_ok && ax.v_ok && ax.a_ok;
  return all_ok;
}

void print_json(const Request& q, const gcode::Program& prog, const planner::Plan& plan, const planner::Report& r) {
  const Config& c = q.config;
  std::ostringstream o;
  o.precision(10);
  o << "{\"file\": " << json_string(q.file) << ", \"blocks\": " << plan.segs.size() << ", \"cycles\": " << r.cycles
    << ", \"cycle_s\": " << c.cycle_s << ", \"total_time_s\": " << r.total_time_s
    << ", \"tolerance_mm\": " << c.tol_mm << ", \"chord_method\": \"" << planner::chord_name(c.chord)
    << "\", \"peak_feed_mm_min\": " << r.peak_feed * 60 << ", \"max_chord_error_mm\": " << r.max_chord_error
    << ", \"tolerance_ok\": " << (r.tol_ok ? "true" : "false") << ", \"blend_tolerance_mm\": " << c.blend_tol_mm
    << ", \"lookahead_blocks\": " << plan.lookahead_blocks << ", \"max_blend_error_mm\": " << r.max_blend_error << ", \"blend_ok\": " << (r.blend_ok ? "true" : "false")
    << ", \"axes\": {";
  for (int i = 0; i < 3; ++i) {
    const auto& ax = r.axes[i];
    o << (i ? ", " : "") << "\"" << kAxisNames[i] << "\": {\"peak_velocity_mm_min\": " << ax.peak_v * 60
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
  o << "], \"events\": [";
  for (std::size_t k = 0; k < prog.events.size(); ++k)
    o << (k ? ", " : "") << "{\"line\": " << prog.events[k].line << ", \"code\": " << json_string(prog.events[k].code)
      << "}";
  o << "], \"program_end\": " << (prog.ended ? "true" : "false") << ", \"all_ok\": " << (limits_respected(r) ? "true" : "false") << "}\n";
  std::fputs(o.str().c_str(), stdout);
}

void print_events(const gcode::Program& prog) {
  std::printf("events (%zu):\n", prog.events.size());
  for (const auto& e : prog.events) std::printf("  line %-4d %s\n", e.line, e.code.c_str());
}

void print_summary(const Request& q, const planner::Plan& plan, const planner::Report& r) {
  const Config& c = q.config;
  std::printf("program        %s: %zu blocks, %zu cycles of %g ms\n", q.file.c_str(), plan.segs.size(), r.cycles,
              c.cycle_s * 1000);
  std::printf("total time     %.4f s\n", r.total_time_s);
  std::printf("look-ahead     at most %zu blocks\n", plan.lookahead_blocks);
  std::printf("peak feed      %.1f mm/min\n", r.peak_feed * 60);
  std::printf("max chord err  %.4f um (tolerance %g um, chord method %s): %s\n", r.max_chord_error * 1000,
              c.tol_mm * 1000, planner::chord_name(c.chord), r.tol_ok ? "ok" : "EXCEEDED");
  std::printf("max corner err %.4f um (blend tolerance %g um unless G64 P): %s\n", r.max_blend_error * 1000,
              c.blend_tol_mm * 1000, r.blend_ok ? "ok" : "EXCEEDED");
  std::printf("axis  peak v (mm/min)  limit        peak a (mm/min^2)  limit\n");
  for (int i = 0; i < 3; ++i) {
    const auto& ax = r.axes[i];
    std::printf("%-5s %-16.1f %-9.1f %-3s %-18.0f %-9.0f %s\n", kAxisNames[i], ax.peak_v * 60, ax.vmax * 60,
                ax.v_ok ? "ok" : "EXCEEDED", ax.peak_a * 3600, ax.amax * 3600, ax.a_ok ? "ok" : "EXCEEDED");
  }
  std::printf("blocks:\n");
  for (const auto& s : plan.segs)
    std::printf("  line %-4d %-11s %10.3f mm  %8.1f -> %8.1f -> %8.1f mm/min  %8.4f s  (cruise cap: %s)\n",
                s.geom.line, kind_name(s.geom), s.geom.length, s.v_start * 60, s.v_cruise * 60, s.v_end * 60,
                s.duration, planner::cap_name(s.cap));
}

// --format moves: the reader's output, one line per move, dwell and event,
// in machine mm and mm/min (what the rs274 oracle test compares).
void print_moves(const gcode::Program& prog) {
  std::string text;
  char b[320];
  std::size_t e = 0;
  auto events_before = [&](std::size_t k) {
    for (; e < prog.events.size() && prog.events[e].before <= k; ++e)
      text += "EVENT " + prog.events[e].code + "\n";
  };
  for (std::size_t k = 0; k < prog.blocks.size(); ++k) {
    events_before(k);
    const gcode::Block& m = prog.blocks[k];
    const double f = m.feed_mm_s * 60;
    if (m.is_dwell()) {
      std::snprintf(b, sizeof b, "%s %.6f\n", m.dwell_s > 0 ? "DWELL" : "STOP", m.dwell_s);
    } else if (!m.is_arc()) {
      std::snprintf(b, sizeof b, "%s %.6f %.6f %.6f %.6f\n", m.motion == gcode::Motion::Rapid ? "RAPID" : "LINE", f,
                    m.end.x, m.end.y, m.end.z);
    } else {
      std::snprintf(b, sizeof b, "ARC %.6f %s %s %.6f %.6f %.6f %.6f %.6f %.6f\n", f, gcode::plane_name(m.plane),
                    m.motion == gcode::Motion::ArcCW ? "CW" : "CCW", m.end.x, m.end.y, m.end.z, m.centre.x,
                    m.centre.y, m.centre.z);
    }
    text += b;
  }
  events_before(prog.blocks.size());
  if (prog.ended) text += "END\n";
  std::fputs(text.c_str(), stdout);
}

int run_gcode_command(const std::vector<std::string>& argv) {
  const Args a(argv, {"pulses"},
               {"format", "accel", "cycle", "tol", "blend-tol", "chord", "config", "csv", "svg", "steps-per-mm",
                "engine", "tool-table"});
  if (a.help()) {
    std::printf(kHelp, stage_names().c_str());
    return 0;
  }
  const Request q = parse_request(a);
  gcode::Program prog = read_program(q.file, q.read);
  if (q.format == "moves") {
    print_moves(prog);
    return 0;
  }
  const planner::Plan plan = plan_program(q.file, prog.blocks, q.config);
  std::vector<gcode::Block>().swap(prog.blocks);  // the plan has what the output needs
  if (q.pulses) return print_pulses(q, planner::interpolate(plan));

  // The samples are kept only for --csv and --svg; the summary streams them.
  const bool keep = a.option("csv") || a.option("svg");
  std::vector<planner::Sample> samples;
  planner::Analyser an(plan);
  planner::Interpolator it(plan);
  for (planner::Sample s; it.next(s);) {
    an.add(s);
    if (keep) samples.push_back(s);
  }
  const planner::Report r = an.report();
  if (auto p = a.option("csv")) write_csv(*p, samples, q.config.cycle_s);
  int svg_files = 0;
  if (auto d = a.option("svg")) svg_files = write_svgs(*d, q.file, plan, samples);
  if (q.format == "json") {
    print_json(q, prog, plan, r);
  } else {
    print_summary(q, plan, r);
    if (!prog.events.empty()) print_events(prog);
    if (svg_files) std::printf("svg            %d files in %s\n", svg_files, a.option("svg")->c_str());
  }
  return limits_respected(r) ? 0 : 1;
}

const CommandRegistrar kRegistrar{
    Command{"gcode", "paper B: plan and chord-interpolate a G-code program", run_gcode_command}};

}  // namespace
}  // namespace contour::cli
