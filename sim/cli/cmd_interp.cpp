// `contour line` and `contour arc`: run one move on an engine and print its
// pulses (steps), a JSON record, an SVG drawing or a short summary.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "args.hpp"
#include "interp/engine.hpp"
#include "plot/svg.hpp"
#include "registry.hpp"

namespace contour::cli {
namespace {

const char* kLineHelp =
    "usage: contour line XE YE [--engine E] [--format steps|json|svg|summary] [-o FILE]\n"
    "Linear interpolation from (0, 0) to (XE, YE), |XE|, |YE| <= 2^24 - 1 pulses.\n";
const char* kArcHelp =
    "usage: contour arc XS YS XE YE --cw|--ccw [--engine E] [--format steps|json|svg|summary] [-o FILE]\n"
    "Circular interpolation about the centre (0, 0) from (XS, YS) to (XE, YE).\n"
    "The start is on the circle by definition (R^2 = XS^2 + YS^2, 2 <= R^2 <= (2^24-1)^2);\n"
    "the end must satisfy |XE^2 + YE^2 - R^2| <= |XE| + |YE| (any rounded point of the\n"
    "circle does); XE = XS, YE = YS is a full circle.\n";
const char* kCommonHelp =
    "\noptions:\n"
    "  --engine E     which implementation runs the move: %s (default model)\n"
    "  --format F     steps: the pulses on one line (+X -X +Y -Y)\n"
    "                 json: pulses, final state and max deviation\n"
    "                 svg: the pulse path over the ideal contour (needs -o FILE)\n"
    "                 summary (default): pulses, end point, max deviation\n"
    "  -o, --output FILE  where to write (stdout if absent; required for svg)\n"
    "Bad input: one line on stderr, exit status 2.\n";

std::string json_state(const State& s) {
  std::ostringstream o;
  o << "{\"x\": " << s.x << ", \"y\": " << s.y << ", \"d\": " << s.d << ", \"quadrant\": " << int(s.quadrant)
    << ", \"crossings\": " << int(s.crossings) << ", \"pulses\": " << s.pulses
    << ", \"done\": " << (s.done ? "true" : "false") << "}";
  return o.str();
}

plot::Plot path_plot(const Move& m, const RunResult& r, const std::string& engine) {
  plot::Plot p;
  p.title = describe(m) + " (" + engine + ")";
  p.x_label = "X (pulses)";
  p.y_label = "Y (pulses)";
  p.equal_aspect = true;
  plot::Series ideal{"ideal contour", "#888888", {}, 1.5, true};
  if (m.is_arc()) {
    const double R = std::sqrt(double(m.xs * m.xs + m.ys * m.ys));
    const double a0 = std::atan2(double(m.ys), double(m.xs));
    double a1 = std::atan2(double(m.ye), double(m.xe));
    const double dir = m.sense == Sense::CCW ? 1 : -1;
    double sweep = dir * (a1 - a0);
    while (sweep <= 1e-12) sweep += 2 * M_PI;
    for (int i = 0; i <= 720; ++i) {
      const double a = a0 + dir * sweep * i / 720;
      ideal.points.push_back({R * std::cos(a), R * std::sin(a)});
    }
  } else {
    ideal.points = {{0, 0}, {double(m.xe), double(m.ye)}};
  }
  plot::Series path{"pulse path", "#d62728", {}, 1.5, false, r.steps.size() <= 200};
  path.points.push_back({double(r.initial_state.x), double(r.initial_state.y)});
  for (const auto& s : r.steps) path.points.push_back({double(s.state.x), double(s.state.y)});
  p.series = {ideal, path};
  return p;
}

int run_move(const Args& a, const Move& m) {
  const std::string engine_name = a.option_or("engine", "model");
  const auto it = engines().find(engine_name);
  if (it == engines().end())
    throw UsageError(unknown_engine(engine_name, engine_names()));
  const std::string format = a.option_or("format", "summary");
  if (format != "steps" && format != "json" && format != "svg" && format != "summary")
    throw UsageError("--format: unknown format '" + format + "' (one of steps, json, svg, summary)");
  const auto out_path = a.option("output") ? a.option("output") : a.option("o");
  if (format == "svg" && !out_path) throw UsageError("--format svg needs -o FILE");

  RunResult r;
  try {
    r = it->second.make()->run(m);
  } catch (const InputError& e) {
    throw UsageError(e.what());
  }

  std::ostringstream o;
  if (format == "steps") {
    for (std::size_t i = 0; i < r.steps.size(); ++i) o << (i ? " " : "") << to_string(r.steps[i].pulse);
    o << "\n";
  } else if (format == "json") {
    o << "{\"engine\": \"" << engine_name << "\", \"move\": \"" << describe(m) << "\", \"count\": "
      << r.steps.size() << ", \"pulses\": [";
    for (std::size_t i = 0; i < r.steps.size(); ++i) o << (i ? ", " : "") << '"' << to_string(r.steps[i].pulse) << '"';
    o << "], \"final\": " << json_state(r.final_state) << ", \"max_deviation\": " << max_deviation(m, r) << "}\n";
  } else if (format == "summary") {
    std::uint64_t nx = 0, ny = 0;
    for (const auto& s : r.steps) (s.pulse.axis == Axis::X ? nx : ny)++;
    char dev[32];
    std::snprintf(dev, sizeof dev, "%.4f", max_deviation(m, r));
    o << describe(m) << " [engine " << engine_name << "]\n"
      << "  pulses:        " << r.steps.size() << " (X " << nx << ", Y " << ny << ")\n"
      << "  end point:     (" << r.final_state.x << ", " << r.final_state.y << ")"
      << (r.final_state.done ? "" : " NOT REACHED") << "\n"
      << "  max deviation: " << dev << " pulses\n";
  }
  if (format == "svg") {
    plot::write_file(path_plot(m, r, engine_name), *out_path);
    return 0;
  }
  if (out_path) {
    std::ofstream f(*out_path);
    if (!f) throw UsageError("-o: cannot write '" + *out_path + "'");
    f << o.str();
  } else {
    std::fputs(o.str().c_str(), stdout);
  }
  return r.final_state.done ? 0 : 1;
}

void print_help(const char* head) {
  std::printf("%s", head);
  std::printf(kCommonHelp, engine_names().c_str());
}

const std::set<std::string> kOptions = {"engine", "format", "output", "o"};

int cmd_line(const std::vector<std::string>& argv) {
  Args a(argv, {}, kOptions);
  if (a.help()) {
    print_help(kLineHelp);
    return 0;
  }
  a.expect_positional({"XE", "YE"});
  const auto& p = a.positional();
  return run_move(a, Move::line(parse_int(p[0], "XE"), parse_int(p[1], "YE")));
}

int cmd_arc(const std::vector<std::string>& argv) {
  Args a(argv, {"cw", "ccw"}, kOptions);
  if (a.help()) {
    print_help(kArcHelp);
    return 0;
  }
  a.expect_positional({"XS", "YS", "XE", "YE"});
  if (a.flag("cw") == a.flag("ccw")) throw UsageError("give exactly one of --cw and --ccw");
  const auto& p = a.positional();
  return run_move(a, Move::arc(parse_int(p[0], "XS"), parse_int(p[1], "YS"), parse_int(p[2], "XE"),
                               parse_int(p[3], "YE"), a.flag("cw") ? Sense::CW : Sense::CCW));
}

const CommandRegistrar kLine{{"line", "linear interpolation from (0,0) to (XE,YE)", cmd_line}};
const CommandRegistrar kArc{{"arc", "circular interpolation about (0,0), --cw or --ccw", cmd_arc}};

}  // namespace
}  // namespace contour::cli
