// A small, dependency-free SVG line plot: axes with "nice" ticks, a title,
// axis labels, a legend, and any number of polylines. Used by the CLI's
// `--format svg`, the co-simulation report and paper B's plots.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace contour::plot {

struct Point {
  double x = 0, y = 0;
};

struct Series {
  std::string label;
  std::string color = "#1f77b4";
  std::vector<Point> points;
  double width = 1.5;
  bool dashed = false;
  bool markers = false;  // a dot on every point
};

struct Plot {
  std::string title;
  std::string x_label;
  std::string y_label;
  std::vector<Series> series;
  bool equal_aspect = false;  // same scale on both axes (paths, contours)
  bool log_x = false;         // logarithmic x axis (rate sweeps)
  int width = 640;
  int height = 480;
  // Longer series are thinned evenly to this many points (first and last
  // kept), so a 10^5-sample profile stays a light file.
  std::size_t max_points = 4000;
};

// The whole <svg> element (no XML prolog), ready to write to a file or to
// inline into HTML.
std::string render(const Plot& plot);

// Writes render(plot) to `path`; throws std::runtime_error naming the path.
void write_file(const Plot& plot, const std::string& path);

// Escapes &, <, > and quotes for SVG/HTML text.
std::string escape(const std::string& text);

}  // namespace contour::plot
