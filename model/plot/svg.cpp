#include "plot/svg.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <limits>
#include <optional>
#include <sstream>
#include <stdexcept>

namespace contour::plot {

namespace {

struct Range {
  double lo = std::numeric_limits<double>::infinity();
  double hi = -std::numeric_limits<double>::infinity();
  void add(double v) {
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  bool empty() const { return !(lo <= hi); }
};

// A tick step of 1, 2 or 5 times a power of ten giving about `n` ticks.
double nice_step(double span, int n) {
  if (span <= 0) return 1;
  const double raw = span / n;
  const double mag = std::pow(10.0, std::floor(std::log10(raw)));
  const double f = raw / mag;
  return (f < 1.5 ? 1 : f < 3.5 ? 2 : f < 7.5 ? 5 : 10) * mag;
}

// Tick labels: integers as integers (no "1e+06"), others to 6 digits,
// exponents only for the very large and the very small.
std::string fmt(double v) {
  char buf[32];
  if (std::fabs(v) < 1e12 && v == std::round(v)) std::snprintf(buf, sizeof buf, "%.0f", v);
  else if (v != 0 && (std::fabs(v) >= 1e12 || std::fabs(v) < 1e-3)) std::snprintf(buf, sizeof buf, "%.3g", v);
  else std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

// Every k-th point, first and last kept, at most `limit` of them.
std::vector<Point> thin(const std::vector<Point>& pts, std::size_t limit) {
  if (limit < 2 || pts.size() <= limit) return pts;
  std::vector<Point> out;
  out.reserve(limit);
  for (std::size_t i = 0; i < limit; ++i) out.push_back(pts[i * (pts.size() - 1) / (limit - 1)]);
  return out;
}

// Plot margins, px: room for the y tick labels, the title and the x label.
constexpr double kLeft = 76, kRight = 20, kTop = 40, kBottom = 58;
// Text, px: readable when a plot is shown at its own size (or an 800 px
// one at 800 px): ticks and legend 13, axis labels 14, title 16.
constexpr int kFont = 13, kLabelFont = 14, kTitleFont = 16;
// The legend's metrics: an average glyph of the 13 px sans-serif font,
// one entry's height, the sample line and the padding.
constexpr double kGlyph = 7.6, kEntry = 18, kSample = 30, kPad = 6;

// The data ranges and their mapping to the drawing area.
struct Frame {
  double left = kLeft, top = kTop;
  double pw = 0, ph = 0;  // width, height of the drawing area
  bool log_x = false;
  Range rx, ry;           // rx in log10 units when log_x
  double sx = 1, sy = 1;  // px per unit

  double tx(double x) const { return log_x ? std::log10(std::max(x, 1e-300)) : x; }
  double X(double x) const { return left + (tx(x) - rx.lo) * sx; }
  double Y(double y) const { return top + ph - (y - ry.lo) * sy; }
};

// Ranges of the data with a margin of 5 % (so lines do not sit on the
// frame), widened to equal scales when the plot asks for them.
Frame fit_frame(const Plot& plot, double band) {
  Frame f;
  f.pw = plot.width - kLeft - kRight;
  f.ph = plot.height - kTop - kBottom - band;
  f.log_x = plot.log_x;
  Range rx, ry;
  for (const auto& s : plot.series)
    for (const auto& p : s.points) {
      rx.add(f.tx(p.x));
      ry.add(p.y);
    }
  if (rx.empty()) rx = Range{0, 1};
  if (ry.empty()) ry = Range{0, 1};
  if (rx.hi == rx.lo) rx = Range{rx.lo - 1, rx.hi + 1};
  if (ry.hi == ry.lo) ry = Range{ry.lo - 1, ry.hi + 1};
  const double mx = 0.05 * (rx.hi - rx.lo), my = 0.05 * (ry.hi - ry.lo);
  f.rx = Range{rx.lo - mx, rx.hi + mx};
  f.ry = Range{ry.lo - my, ry.hi + my};
  f.sx = f.pw / (f.rx.hi - f.rx.lo);
  f.sy = f.ph / (f.ry.hi - f.ry.lo);
  if (plot.equal_aspect) {
    const double s = std::min(f.sx, f.sy);
    const double cx = (f.rx.lo + f.rx.hi) / 2, cy = (f.ry.lo + f.ry.hi) / 2;
    f.rx = Range{cx - f.pw / s / 2, cx + f.pw / s / 2};
    f.ry = Range{cy - f.ph / s / 2, cy + f.ph / s / 2};
    f.sx = f.sy = s;
  }
  return f;
}

// Several plots inlined in one HTML page share one id namespace: name the
// clip path after the plot's content (deterministic, distinct per plot).
std::string clip_id(const Plot& plot, const Frame& f) {
  std::uint64_t h = 1469598103934665603ull;
  auto mix = [&h](double v) {
    std::uint64_t bits;
    std::memcpy(&bits, &v, sizeof bits);
    h = (h ^ bits) * 1099511628211ull;
  };
  for (char c : plot.title) mix(c);
  mix(f.rx.lo), mix(f.rx.hi), mix(f.ry.lo), mix(f.ry.hi), mix(plot.width), mix(plot.height);
  for (const auto& s : plot.series)
    for (const auto& p : thin(s.points, plot.max_points)) mix(p.x), mix(p.y);  // as drawn
  char id[32];
  std::snprintf(id, sizeof id, "frame%016llx", static_cast<unsigned long long>(h));
  return id;
}

void write_header(std::ostream& o, const Plot& plot) {
  o << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << plot.width << "\" height=\"" << plot.height
    << "\" viewBox=\"0 0 " << plot.width << ' ' << plot.height
    << "\" font-family=\"sans-serif\" font-size=\"" << kFont << "\">\n"
    << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
    << "<text x=\"" << plot.width / 2 << "\" y=\"24\" text-anchor=\"middle\" font-size=\"" << kTitleFont << "\">"
    << escape(plot.title) << "</text>\n";
}

// A vertical grid line at px, to `o`, and its label, to `labels`.
void write_x_tick(std::ostream& o, std::ostream& labels, const Frame& f, double px, const std::string& label) {
  o << "<line x1=\"" << px << "\" y1=\"" << f.top << "\" x2=\"" << px << "\" y2=\"" << f.top + f.ph << "\"/>\n";
  labels << "<text x=\"" << px << "\" y=\"" << f.top + f.ph + 18 << "\" text-anchor=\"middle\">" << label
         << "</text>\n";
}

// Grid lines and tick labels: decades on a log x axis, nice steps otherwise.
void write_grid(std::ostream& o, const Frame& f) {
  o << "<g stroke=\"#ddd\" stroke-width=\"1\">\n";
  std::ostringstream labels;
  if (f.log_x) {
    for (double d = std::floor(f.rx.lo); d <= f.rx.hi; d += 1) {
      if (d < f.rx.lo) continue;
      write_x_tick(o, labels, f, f.left + (d - f.rx.lo) * f.sx, fmt(std::pow(10.0, d)));
    }
  } else {
    const double step = nice_step(f.rx.hi - f.rx.lo, 8);
    for (double v = std::ceil(f.rx.lo / step) * step; v <= f.rx.hi; v += step)
      write_x_tick(o, labels, f, f.X(v), fmt(std::fabs(v) < step * 1e-9 ? 0 : v));
  }
  const double ystep = nice_step(f.ry.hi - f.ry.lo, 6);
  for (double v = std::ceil(f.ry.lo / ystep) * ystep; v <= f.ry.hi; v += ystep) {
    const double py = f.Y(v);
    o << "<line x1=\"" << f.left << "\" y1=\"" << py << "\" x2=\"" << f.left + f.pw << "\" y2=\"" << py << "\"/>\n";
    labels << "<text x=\"" << f.left - 6 << "\" y=\"" << py + 4 << "\" text-anchor=\"end\">"
           << fmt(std::fabs(v) < ystep * 1e-9 ? 0 : v) << "</text>\n";
  }
  o << "</g>\n" << labels.str();
}

// The frame rectangle and the axis labels.
void write_frame(std::ostream& o, const Plot& plot, const Frame& f) {
  o << "<rect x=\"" << f.left << "\" y=\"" << f.top << "\" width=\"" << f.pw << "\" height=\"" << f.ph
    << "\" fill=\"none\" stroke=\"#333\"/>\n";
  o << "<text x=\"" << f.left + f.pw / 2 << "\" y=\"" << f.top + f.ph + 42 << "\" text-anchor=\"middle\" font-size=\""
    << kLabelFont << "\">" << escape(plot.x_label) << "</text>\n";
  o << "<text transform=\"translate(18," << f.top + f.ph / 2 << ") rotate(-90)\" text-anchor=\"middle\" font-size=\""
    << kLabelFont << "\">" << escape(plot.y_label) << "</text>\n";
}

// Data, clipped to the frame.
void write_series(std::ostream& o, const Plot& plot, const Frame& f) {
  const std::string id = clip_id(plot, f);
  o << "<clipPath id=\"" << id << "\"><rect x=\"" << f.left << "\" y=\"" << f.top << "\" width=\"" << f.pw
    << "\" height=\"" << f.ph << "\"/></clipPath>\n<g clip-path=\"url(#" << id << ")\" fill=\"none\">\n";
  for (const auto& full : plot.series) {
    if (full.points.empty()) continue;
    Series s = full;
    s.points = thin(full.points, plot.max_points);
    o << "<polyline stroke=\"" << s.color << "\" stroke-width=\"" << s.width << "\""
      << (s.dashed ? " stroke-dasharray=\"6 4\"" : "") << " points=\"";
    for (const auto& p : s.points) o << f.X(p.x) << ',' << f.Y(p.y) << ' ';
    o << "\"/>\n";
    if (s.markers)
      for (const auto& p : s.points)
        o << "<circle cx=\"" << f.X(p.x) << "\" cy=\"" << f.Y(p.y) << "\" r=\"2.5\" fill=\"" << s.color << "\"/>\n";
  }
  o << "</g>\n";
}

// The legend's entries (series with a label) and the size of its box.
struct Legend {
  std::vector<const Series*> entries;
  double w = 0, h = 0;
  explicit Legend(const Plot& plot) {
    std::size_t longest = 0;
    for (const auto& s : plot.series)
      if (!s.label.empty()) {
        entries.push_back(&s);
        longest = std::max(longest, s.label.size());
      }
    w = kPad * 3 + kSample + kGlyph * double(longest);
    h = kEntry * double(entries.size()) + kPad;
  }
};

struct Box {
  double x0, y0, x1, y1;
  bool contains(double x, double y) const { return x >= x0 && x <= x1 && y >= y0 && y <= y1; }
};

// Whether the segment a-b (pixels) meets the box: clipped against it
// (Liang-Barsky).
bool meets(const Box& b, double ax, double ay, double bx, double by) {
  double t0 = 0, t1 = 1;
  const double dx = bx - ax, dy = by - ay;
  const double p[4] = {-dx, dx, -dy, dy}, q[4] = {ax - b.x0, b.x1 - ax, ay - b.y0, b.y1 - ay};
  for (int i = 0; i < 4; ++i) {
    if (p[i] == 0) {
      if (q[i] < 0) return false;
      continue;
    }
    const double t = q[i] / p[i];
    if (p[i] < 0) t0 = std::max(t0, t);
    else t1 = std::min(t1, t);
    if (t0 > t1) return false;
  }
  return true;
}

// Whether any drawn line or marker of the plot meets the box (grown by
// the markers' radius and half a line).
bool box_has_data(const Plot& plot, const Frame& f, Box b) {
  b = Box{b.x0 - 4, b.y0 - 4, b.x1 + 4, b.y1 + 4};
  for (const auto& s : plot.series) {
    const auto pts = thin(s.points, plot.max_points);
    for (std::size_t i = 0; i < pts.size(); ++i) {
      const double x = f.X(pts[i].x), y = f.Y(pts[i].y);
      if (b.contains(x, y)) return true;
      if (i > 0 && meets(b, f.X(pts[i - 1].x), f.Y(pts[i - 1].y), x, y)) return true;
    }
  }
  return false;
}

// The first corner of the frame (top right, top left, bottom right, bottom
// left) where the legend's box covers no data, if any.
std::optional<Box> free_corner(const Plot& plot, const Frame& f, const Legend& lg) {
  const double l = f.left + 6, r = f.left + f.pw - 6 - lg.w, t = f.top + 6, btm = f.top + f.ph - 6 - lg.h;
  for (const auto& [x, y] : {std::pair{r, t}, std::pair{l, t}, std::pair{r, btm}, std::pair{l, btm}}) {
    const Box b{x, y, x + lg.w, y + lg.h};
    if (!box_has_data(plot, f, b)) return b;
  }
  return std::nullopt;
}

// The legend's entries, one a line, in the box whose top left is (x, y).
void write_legend(std::ostream& o, const Legend& lg, double x, double y) {
  if (lg.entries.empty()) return;
  o << "<rect x=\"" << x << "\" y=\"" << y << "\" width=\"" << lg.w << "\" height=\"" << lg.h
    << "\" fill=\"white\" stroke=\"#ccc\"/>\n";
  double ly = y + kPad + kEntry / 2;
  for (const Series* s : lg.entries) {
    o << "<line x1=\"" << x + kPad << "\" y1=\"" << ly << "\" x2=\"" << x + kPad + kSample << "\" y2=\"" << ly
      << "\" stroke=\"" << s->color << "\" stroke-width=\"2\"" << (s->dashed ? " stroke-dasharray=\"6 4\"" : "")
      << "/>\n<text x=\"" << x + 2 * kPad + kSample << "\" y=\"" << ly + 4.5 << "\">" << escape(s->label)
      << "</text>\n";
    ly += kEntry;
  }
}

}  // namespace

std::string escape(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

// The legend goes in an empty corner of the frame; when every corner has
// data, below the x axis label, the frame shortened to make room.
std::string render(const Plot& plot) {
  const Legend lg(plot);
  Frame f = fit_frame(plot, 0);
  std::optional<Box> at;
  if (!lg.entries.empty()) {
    at = free_corner(plot, f, lg);
    if (!at) {
      f = fit_frame(plot, lg.h + 8);
      const double x = f.left + (f.pw - lg.w) / 2, y = f.top + f.ph + kBottom - 4;
      at = Box{x, y, x + lg.w, y + lg.h};
    }
  }
  std::ostringstream o;
  o.precision(6);
  write_header(o, plot);
  write_grid(o, f);
  write_frame(o, plot, f);
  write_series(o, plot, f);
  if (at) write_legend(o, lg, at->x0, at->y0);
  o << "</svg>\n";
  return o.str();
}

void write_file(const Plot& plot, const std::string& path) {
  std::ofstream f(path);
  if (!f) throw std::runtime_error("cannot write " + path);
  f << render(plot);
  if (!f) throw std::runtime_error("error writing " + path);
}

}  // namespace contour::plot
