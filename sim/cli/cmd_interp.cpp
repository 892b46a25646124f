// `contour line` and `contour arc`: run one move on an engine and print its
// pulses (steps), a JSON record, an SVG drawing or a short summary, as the
// engine makes them (Engine::stream): memory does not grow with the move.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "args.hpp"
#include "interp/engine.hpp"
#include "numbers.hpp"
#include "plot/svg.hpp"
#include "progress.hpp"
#include "registry.hpp"

namespace contour::cli {
namespace {

const char* kLineHelp =
    "usage: contour line XE YE [--engine E] [--format steps|json|svg|summary] [-o FILE]\n"
    "                          [--progress|--no-progress]\n"
    "Linear interpolation from (0, 0) to (XE, YE), |XE|, |YE| <= 2^24 - 1 pulses.\n";
const char* kArcHelp =
    "usage: contour arc XS YS XE YE --cw|--ccw [--engine E] [--format steps|json|svg|summary] [-o FILE]\n"
    "                                [--progress|--no-progress]\n"
    "Circular interpolation about the centre (0, 0) from (XS, YS) to (XE, YE).\n"
    "The start is on the circle by definition (R^2 = XS^2 + YS^2, 2 <= R^2 <= (2^24-1)^2);\n"
    "the end must satisfy |XE^2 + YE^2 - R^2| <= |XE| + |YE| (any rounded point of the\n"
    "circle does); XE = XS, YE = YS is a full circle.\n";
const char* kCommonHelp =
    "\noptions:\n"
    "  --engine E     which implementation runs the move: %s (default model)\n"
    "  --format F     steps: the pulses on one line (+X -X +Y -Y)\n"
    "                 json: pulses, count, final state and max deviation\n"
    "                 svg: the pulse path over the ideal contour (needs -o FILE;\n"
    "                 a long path is thinned to a few thousand points)\n"
    "                 summary (default): pulses, end point, max deviation\n"
    "  -o, --output FILE  where to write (stdout if absent; required for svg)\n"
    "  --progress, --no-progress  pulses so far on stderr (default: when stderr is a terminal)\n"
    "Output is written as the engine runs; memory does not grow with the move.\n"
    "%s"
    "Bad input: one line on stderr, exit status 2.\n";

std::string json_state(const State& s) {
  std::ostringstream o;
  o << "{\"x\": " << s.x << ", \"y\": " << s.y << ", \"d\": " << s.d << ", \"quadrant\": " << int(s.quadrant)
    << ", \"crossings\": " << int(s.crossings) << ", \"pulses\": " << s.pulses
    << ", \"done\": " << (s.done ? "true" : "false") << "}";
  return o.str();
}

// The points of a path of any length in bounded memory: while more than
// 2 * kKeep are held, every other one is dropped and from then on only
// every `stride_`-th point is taken (the last point is always kept).
class ThinnedPath {
 public:
  static constexpr std::size_t kKeep = 4096;
  void add(plot::Point p) {
    if (n_++ % stride_ == 0) {
      points_.push_back(p);
      if (points_.size() >= 2 * kKeep) halve();
    }
    last_ = p;
  }
  std::uint64_t count() const { return n_; }
  // The kept points, the last one included.
  std::vector<plot::Point> finish() {
    if (n_ && (n_ - 1) % stride_ != 0) points_.push_back(last_);
    return std::move(points_);
  }

 private:
  void halve() {
    std::size_t j = 0;
    for (std::size_t i = 0; i < points_.size(); i += 2) points_[j++] = points_[i];
    points_.resize(j);
    stride_ *= 2;
  }
  std::vector<plot::Point> points_;
  plot::Point last_;
  std::uint64_t n_ = 0, stride_ = 1;
};

plot::Plot path_plot(const Move& m, const State& start, std::vector<plot::Point> steps, std::uint64_t n,
                     const std::string& engine) {
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
  plot::Series path{"pulse path", "#d62728", {}, 1.5, false, n <= 200};
  path.points.reserve(steps.size() + 1);
  path.points.push_back({double(start.x), double(start.y)});
  path.points.insert(path.points.end(), steps.begin(), steps.end());
  p.series = {ideal, path};
  return p;
}

// The text output, stdout or the -o file, opened before the run.
class Output {
 public:
  explicit Output(const std::optional<std::string>& path) {
    if (!path) return;
    f_ = std::fopen(path->c_str(), "w");
    if (!f_) throw UsageError("-o: cannot write '" + *path + "'");
  }
  ~Output() {
    if (f_ != stdout) std::fclose(f_);
  }
  Output(const Output&) = delete;
  Output& operator=(const Output&) = delete;
  std::FILE* file() const { return f_; }

 private:
  std::FILE* f_ = stdout;
};

// What is kept of a streamed run, whatever its length: counts, the largest
// deviation so far, and (for svg) a thinned path.
struct Tally {
  std::uint64_t n = 0, nx = 0, ny = 0;
  double worst = 0;
  ThinnedPath path;
};

// One step: written out (steps, json), counted, measured, drawn (svg).
void take_step(const Move& m, const std::string& format, std::FILE* out, Tally& t, const StepRecord& s) {
  if (format == "steps") {
    if (t.n) std::fputc(' ', out);
    std::fputs(to_string(s.pulse).c_str(), out);
  } else if (format == "json") {
    std::fprintf(out, "%s\"%s\"", t.n ? ", " : "", to_string(s.pulse).c_str());
  } else if (format == "svg") {
    t.path.add({double(s.state.x), double(s.state.y)});
  }
  ++t.n;
  (s.pulse.axis == Axis::X ? t.nx : t.ny)++;
  t.worst = std::max(t.worst, deviation(m, s.state.x, s.state.y));
}

// The pulses of an arc, estimated for the progress line: the distance X
// and Y travel along the ideal arc (each axis' total variation, summed
// between the quadrant boundaries the arc crosses). The pulse path differs
// by a few pulses.
std::uint64_t arc_pulses_estimate(const Move& m) {
  const double R = std::hypot(double(m.xs), double(m.ys));
  const double a0 = std::atan2(double(m.ys), double(m.xs));
  const double dir = m.sense == Sense::CCW ? 1 : -1;
  double sweep = dir * (std::atan2(double(m.ye), double(m.xe)) - a0);
  while (sweep <= 1e-12) sweep += 2 * M_PI;
  double travel = 0, prev = 0;
  for (double next = 0; prev < sweep; prev = next) {
    // The next quadrant boundary (a multiple of pi/2) along the arc, or its end.
    const double a = a0 + dir * prev;
    const double k = dir > 0 ? std::floor(a / (M_PI / 2) + 1e-9) + 1 : std::ceil(a / (M_PI / 2) - 1e-9) - 1;
    next = std::min(sweep, dir * (k * M_PI / 2 - a0));
    const double b = a0 + dir * next;
    travel += std::fabs(std::cos(b) - std::cos(a)) + std::fabs(std::sin(b) - std::sin(a));
  }
  return static_cast<std::uint64_t>(std::llround(R * travel));
}

// The pulses of a line, exactly; of an arc, an estimate.
std::uint64_t expected_pulses(const Move& m) {
  auto mag = [](std::int64_t v) { return static_cast<std::uint64_t>(v < 0 ? -v : v); };
  return m.is_arc() ? arc_pulses_estimate(m) : mag(m.xe) + mag(m.ye);
}

// What follows the steps: the end of the steps line, the rest of the JSON
// record, the summary.
void write_tail(const Move& m, const std::string& format, const std::string& engine, std::FILE* out, const Tally& t,
                const RunResult& r, double worst) {
  if (format == "steps") {
    std::fputc('\n', out);
  } else if (format == "json") {
    std::fprintf(out, "], \"count\": %llu, \"final\": %s, \"max_deviation\": %g}\n",
                 static_cast<unsigned long long>(t.n), json_state(r.final_state).c_str(), worst);
  } else if (format == "summary") {
    std::fprintf(out,
                 "%s [engine %s]\n  pulses:        %llu (X %llu, Y %llu)\n  end point:     (%lld, %lld)%s\n"
                 "  max deviation: %.4f pulses\n",
                 describe(m).c_str(), engine.c_str(), static_cast<unsigned long long>(t.n),
                 static_cast<unsigned long long>(t.nx), static_cast<unsigned long long>(t.ny),
                 static_cast<long long>(r.final_state.x), static_cast<long long>(r.final_state.y),
                 r.final_state.done ? "" : " NOT REACHED", worst);
  }
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
  try {
    validate<24>(m);
  } catch (const InputError& e) {
    throw UsageError(e.what());
  }
  Progress progress(progress_wanted(a), describe(m) + " [engine " + engine_name + "]", "pulses");
  const std::uint64_t total = expected_pulses(m);
  if (m.is_arc()) progress.totals_are_estimates();
  Output out(out_path);  // svg: opened here to refuse an unwritable path before the run
  if (format == "json")
    std::fprintf(out.file(), "{\"engine\": \"%s\", \"move\": \"%s\", \"pulses\": [", engine_name.c_str(),
                 describe(m).c_str());
  Tally t;
  RunResult r;
  try {
    r = it->second.make()->stream(m, [&](const StepRecord& s) {
      take_step(m, format, out.file(), t, s);
      progress.update(t.n, total);
    });
  } catch (const InputError& e) {
    throw UsageError(e.what());
  }
  progress.finish();
  const double worst = std::max(t.worst, deviation(m, r.initial_state.x, r.initial_state.y));
  write_tail(m, format, engine_name, out.file(), t, r, worst);
  if (format == "svg") plot::write_file(path_plot(m, r.initial_state, t.path.finish(), t.n, engine_name), *out_path);
  if (std::fflush(out.file()) != 0) throw std::runtime_error("cannot write the output");
  return r.final_state.done ? 0 : 1;
}

void print_help(const char* head) {
  std::printf("%s", head);
  std::printf(kCommonHelp, engine_names().c_str(), kNumberRules);
}

const std::set<std::string> kOptions = {"engine", "format", "output", "o"};
const std::set<std::string> kLineFlags = {"progress", "no-progress"};
const std::set<std::string> kArcFlags = {"cw", "ccw", "progress", "no-progress"};

int cmd_line(const std::vector<std::string>& argv) {
  Args a(argv, kLineFlags, kOptions);
  if (a.help()) {
    print_help(kLineHelp);
    return 0;
  }
  a.expect_positional({"XE", "YE"});
  const auto& p = a.positional();
  return run_move(a, Move::line(parse_int(p[0], "XE"), parse_int(p[1], "YE")));
}

int cmd_arc(const std::vector<std::string>& argv) {
  Args a(argv, kArcFlags, kOptions);
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
