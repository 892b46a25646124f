#include "planner/plot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace contour::planner {

namespace {

std::string num(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.2f", v);
  return b;
}

std::string label(double v, double step) {
  char b[32];
  const int dec = step >= 1 ? 0 : static_cast<int>(std::ceil(-std::log10(step) - 1e-9));
  std::snprintf(b, sizeof b, "%.*f", std::min(dec, 6), std::fabs(v) < step * 1e-9 ? 0.0 : v);
  return b;
}

std::string escape(const std::string& s) {
  std::string o;
  for (char c : s) {
    if (c == '<') o += "&lt;";
    else if (c == '>') o += "&gt;";
    else if (c == '&') o += "&amp;";
    else o += c;
  }
  return o;
}

}  // namespace

std::vector<double> nice_ticks(double lo, double hi, int target) {
  if (!(hi > lo)) return {lo};
  const double raw = (hi - lo) / target;
  const double mag = std::pow(10.0, std::floor(std::log10(raw)));
  double step = mag;
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (m * mag >= raw) {
      step = m * mag;
      break;
    }
  std::vector<double> t;
  for (double v = std::ceil(lo / step - 1e-9) * step; v <= hi + step * 1e-9; v += step) t.push_back(v);
  return t;
}

std::string render_svg(const PlotSpec& spec, std::size_t max_points) {
  const double W = 720, H = spec.equal_aspect ? 640 : 440;
  const double ml = 80, mr = 150, mt = 40, mb = 55;  // margins; legend on the right
  double x0 = std::numeric_limits<double>::infinity(), x1 = -x0, y0 = x0, y1 = -x0;
  for (const auto& s : spec.series)
    for (const auto& [x, y] : s.points) {
      x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
    }
  if (!(x1 >= x0)) x0 = 0, x1 = 1, y0 = 0, y1 = 1;
  if (x1 - x0 < 1e-12) x0 -= 1, x1 += 1;
  if (y1 - y0 < 1e-12) y0 -= 1, y1 += 1;
  // 5 % padding.
  double px = (x1 - x0) * 0.05, py = (y1 - y0) * 0.05;
  x0 -= px, x1 += px, y0 -= py, y1 += py;
  const double pw = W - ml - mr, ph = H - mt - mb;
  if (spec.equal_aspect) {
    const double sx = (x1 - x0) / pw, sy = (y1 - y0) / ph, s = std::max(sx, sy);
    const double cx = (x0 + x1) / 2, cy = (y0 + y1) / 2;
    x0 = cx - s * pw / 2, x1 = cx + s * pw / 2, y0 = cy - s * ph / 2, y1 = cy + s * ph / 2;
  }
  auto X = [&](double x) { return ml + (x - x0) / (x1 - x0) * pw; };
  auto Y = [&](double y) { return mt + (y1 - y) / (y1 - y0) * ph; };

  std::string o;
  o += "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + num(W) + "\" height=\"" + num(H) +
       "\" font-family=\"sans-serif\" font-size=\"12\">\n";
  o += "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  o += "<text x=\"" + num(ml + pw / 2) + "\" y=\"22\" text-anchor=\"middle\" font-size=\"15\">" + escape(spec.title) +
       "</text>\n";
  // Grid and ticks.
  const auto xt = nice_ticks(x0, x1), yt = nice_ticks(y0, y1);
  const double xs = xt.size() > 1 ? xt[1] - xt[0] : 1, ys = yt.size() > 1 ? yt[1] - yt[0] : 1;
  for (double t : xt) {
    o += "<line x1=\"" + num(X(t)) + "\" y1=\"" + num(mt) + "\" x2=\"" + num(X(t)) + "\" y2=\"" + num(mt + ph) +
         "\" stroke=\"#e4e4e4\"/>\n";
    o += "<line x1=\"" + num(X(t)) + "\" y1=\"" + num(mt + ph) + "\" x2=\"" + num(X(t)) + "\" y2=\"" +
         num(mt + ph + 5) + "\" stroke=\"black\"/>\n";
    o += "<text x=\"" + num(X(t)) + "\" y=\"" + num(mt + ph + 18) + "\" text-anchor=\"middle\">" + label(t, xs) +
         "</text>\n";
  }
  for (double t : yt) {
    o += "<line x1=\"" + num(ml) + "\" y1=\"" + num(Y(t)) + "\" x2=\"" + num(ml + pw) + "\" y2=\"" + num(Y(t)) +
         "\" stroke=\"#e4e4e4\"/>\n";
    o += "<line x1=\"" + num(ml - 5) + "\" y1=\"" + num(Y(t)) + "\" x2=\"" + num(ml) + "\" y2=\"" + num(Y(t)) +
         "\" stroke=\"black\"/>\n";
    o += "<text x=\"" + num(ml - 8) + "\" y=\"" + num(Y(t) + 4) + "\" text-anchor=\"end\">" + label(t, ys) +
         "</text>\n";
  }
  o += "<rect x=\"" + num(ml) + "\" y=\"" + num(mt) + "\" width=\"" + num(pw) + "\" height=\"" + num(ph) +
       "\" fill=\"none\" stroke=\"black\"/>\n";
  o += "<text x=\"" + num(ml + pw / 2) + "\" y=\"" + num(H - 12) + "\" text-anchor=\"middle\">" +
       escape(spec.xlabel) + "</text>\n";
  o += "<text transform=\"translate(18," + num(mt + ph / 2) + ") rotate(-90)\" text-anchor=\"middle\">" +
       escape(spec.ylabel) + "</text>\n";
  // Series.
  int li = 0;
  for (const auto& s : spec.series) {
    if (s.points.empty()) continue;
    const std::size_t n = s.points.size();
    const std::size_t stride = n > max_points ? (n + max_points - 1) / max_points : 1;
    o += "<polyline fill=\"none\" stroke=\"" + s.color + "\" stroke-width=\"1.5\" points=\"";
    for (std::size_t i = 0; i < n; i += stride) o += num(X(s.points[i].first)) + "," + num(Y(s.points[i].second)) + " ";
    if ((n - 1) % stride != 0) o += num(X(s.points.back().first)) + "," + num(Y(s.points.back().second));
    o += "\"/>\n";
    const double ly = mt + 10 + 18 * li++;
    o += "<line x1=\"" + num(ml + pw + 12) + "\" y1=\"" + num(ly) + "\" x2=\"" + num(ml + pw + 36) + "\" y2=\"" +
         num(ly) + "\" stroke=\"" + s.color + "\" stroke-width=\"2\"/>\n";
    o += "<text x=\"" + num(ml + pw + 42) + "\" y=\"" + num(ly + 4) + "\">" + escape(s.name) + "</text>\n";
  }
  o += "</svg>\n";
  return o;
}

}  // namespace contour::planner
