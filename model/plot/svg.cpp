#include "plot/svg.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <limits>
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

std::string fmt(double v) {
  char buf[32];
  if (v != 0 && (std::fabs(v) >= 1e6 || std::fabs(v) < 1e-3)) std::snprintf(buf, sizeof buf, "%.3g", v);
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

std::string render(const Plot& plot) {
  const double left = 70, right = 20, top = 40, bottom = 55;
  const double pw = plot.width - left - right, ph = plot.height - top - bottom;
  auto tx = [&](double x) { return plot.log_x ? std::log10(std::max(x, 1e-300)) : x; };

  Range rx, ry;
  for (const auto& s : plot.series)
    for (const auto& p : s.points) {
      rx.add(tx(p.x));
      ry.add(p.y);
    }
  if (rx.empty()) rx = Range{0, 1};
  if (ry.empty()) ry = Range{0, 1};
  if (rx.hi == rx.lo) rx = Range{rx.lo - 1, rx.hi + 1};
  if (ry.hi == ry.lo) ry = Range{ry.lo - 1, ry.hi + 1};
  // A margin of 5 % so lines do not sit on the frame.
  const double mx = 0.05 * (rx.hi - rx.lo), my = 0.05 * (ry.hi - ry.lo);
  rx = Range{rx.lo - mx, rx.hi + mx};
  ry = Range{ry.lo - my, ry.hi + my};
  double sx = pw / (rx.hi - rx.lo), sy = ph / (ry.hi - ry.lo);
  if (plot.equal_aspect) {
    const double s = std::min(sx, sy);
    const double cx = (rx.lo + rx.hi) / 2, cy = (ry.lo + ry.hi) / 2;
    rx = Range{cx - pw / s / 2, cx + pw / s / 2};
    ry = Range{cy - ph / s / 2, cy + ph / s / 2};
    sx = sy = s;
  }
  auto X = [&](double x) { return left + (tx(x) - rx.lo) * sx; };
  auto Y = [&](double y) { return top + ph - (y - ry.lo) * sy; };

  // Several plots inlined in one HTML page share one id namespace: name the
  // clip path after the plot's content (deterministic, distinct per plot).
  std::uint64_t h = 1469598103934665603ull;
  auto mix = [&h](double v) {
    std::uint64_t bits;
    std::memcpy(&bits, &v, sizeof bits);
    h = (h ^ bits) * 1099511628211ull;
  };
  for (char c : plot.title) mix(c);
  mix(rx.lo), mix(rx.hi), mix(ry.lo), mix(ry.hi), mix(plot.width), mix(plot.height);
  for (const auto& s : plot.series)
    for (const auto& p : thin(s.points, plot.max_points)) mix(p.x), mix(p.y);  // as drawn
  char clip_id[32];
  std::snprintf(clip_id, sizeof clip_id, "frame%016llx", static_cast<unsigned long long>(h));

  std::ostringstream o;
  o.precision(6);
  o << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << plot.width << "\" height=\"" << plot.height
    << "\" viewBox=\"0 0 " << plot.width << ' ' << plot.height
    << "\" font-family=\"sans-serif\" font-size=\"12\">\n"
    << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
    << "<text x=\"" << plot.width / 2 << "\" y=\"22\" text-anchor=\"middle\" font-size=\"15\">"
    << escape(plot.title) << "</text>\n";
  // Grid and ticks.
  o << "<g stroke=\"#ddd\" stroke-width=\"1\">\n";
  std::ostringstream labels;
  if (plot.log_x) {
    for (double d = std::floor(rx.lo); d <= rx.hi; d += 1) {
      if (d < rx.lo) continue;
      const double px = left + (d - rx.lo) * sx;
      o << "<line x1=\"" << px << "\" y1=\"" << top << "\" x2=\"" << px << "\" y2=\"" << top + ph << "\"/>\n";
      labels << "<text x=\"" << px << "\" y=\"" << top + ph + 16 << "\" text-anchor=\"middle\">"
             << fmt(std::pow(10.0, d)) << "</text>\n";
    }
  } else {
    const double step = nice_step(rx.hi - rx.lo, 8);
    for (double v = std::ceil(rx.lo / step) * step; v <= rx.hi; v += step) {
      const double px = X(v);
      o << "<line x1=\"" << px << "\" y1=\"" << top << "\" x2=\"" << px << "\" y2=\"" << top + ph << "\"/>\n";
      labels << "<text x=\"" << px << "\" y=\"" << top + ph + 16 << "\" text-anchor=\"middle\">"
             << fmt(std::fabs(v) < step * 1e-9 ? 0 : v) << "</text>\n";
    }
  }
  const double ystep = nice_step(ry.hi - ry.lo, 6);
  for (double v = std::ceil(ry.lo / ystep) * ystep; v <= ry.hi; v += ystep) {
    const double py = Y(v);
    o << "<line x1=\"" << left << "\" y1=\"" << py << "\" x2=\"" << left + pw << "\" y2=\"" << py << "\"/>\n";
    labels << "<text x=\"" << left - 6 << "\" y=\"" << py + 4 << "\" text-anchor=\"end\">"
           << fmt(std::fabs(v) < ystep * 1e-9 ? 0 : v) << "</text>\n";
  }
  o << "</g>\n" << labels.str();
  o << "<rect x=\"" << left << "\" y=\"" << top << "\" width=\"" << pw << "\" height=\"" << ph
    << "\" fill=\"none\" stroke=\"#333\"/>\n";
  o << "<text x=\"" << left + pw / 2 << "\" y=\"" << plot.height - 14 << "\" text-anchor=\"middle\">"
    << escape(plot.x_label) << "</text>\n";
  o << "<text transform=\"translate(16," << top + ph / 2 << ") rotate(-90)\" text-anchor=\"middle\">"
    << escape(plot.y_label) << "</text>\n";
  // Data, clipped to the frame.
  o << "<clipPath id=\"" << clip_id << "\"><rect x=\"" << left << "\" y=\"" << top << "\" width=\"" << pw << "\" height=\""
    << ph << "\"/></clipPath>\n<g clip-path=\"url(#" << clip_id << ")\" fill=\"none\">\n";
  for (const auto& full : plot.series) {
    if (full.points.empty()) continue;
    Series s = full;
    s.points = thin(full.points, plot.max_points);
    o << "<polyline stroke=\"" << s.color << "\" stroke-width=\"" << s.width << "\""
      << (s.dashed ? " stroke-dasharray=\"6 4\"" : "") << " points=\"";
    for (const auto& p : s.points) o << X(p.x) << ',' << Y(p.y) << ' ';
    o << "\"/>\n";
    if (s.markers)
      for (const auto& p : s.points)
        o << "<circle cx=\"" << X(p.x) << "\" cy=\"" << Y(p.y) << "\" r=\"2.5\" fill=\"" << s.color << "\"/>\n";
  }
  o << "</g>\n";
  // Legend, on a translucent box so that it reads over the data.
  std::size_t entries = 0, longest = 0;
  for (const auto& s : plot.series)
    if (!s.label.empty()) {
      ++entries;
      longest = std::max(longest, s.label.size());
    }
  if (entries > 0)
    o << "<rect x=\"" << left + 4 << "\" y=\"" << top + 3 << "\" width=\"" << 44 + 7 * longest << "\" height=\""
      << 16 * entries + 4 << "\" fill=\"white\" fill-opacity=\"0.85\" stroke=\"#ccc\"/>\n";
  double ly = top + 14;
  for (const auto& s : plot.series) {
    if (s.label.empty()) continue;
    o << "<line x1=\"" << left + 10 << "\" y1=\"" << ly - 4 << "\" x2=\"" << left + 34 << "\" y2=\"" << ly - 4
      << "\" stroke=\"" << s.color << "\" stroke-width=\"2\"" << (s.dashed ? " stroke-dasharray=\"6 4\"" : "")
      << "/>\n<text x=\"" << left + 40 << "\" y=\"" << ly << "\">" << escape(s.label) << "</text>\n";
    ly += 16;
  }
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
