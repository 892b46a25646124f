// Minimal hand-written SVG line plots for `contour gcode --svg`: axes,
// ticks at 1-2-5 steps, axis labels, title and legend.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace contour::planner {

struct Series {
  std::string name;
  std::string color;  // any SVG colour, e.g. "#d62728"
  std::vector<std::pair<double, double>> points;
};

struct PlotSpec {
  std::string title, xlabel, ylabel;
  bool equal_aspect = false;  // same scale on both axes (trajectories)
  std::vector<Series> series;
};

// The SVG document. Series longer than max_points are thinned evenly (the
// first and last points are kept).
std::string render_svg(const PlotSpec& spec, std::size_t max_points = 4000);

// Tick positions covering [lo, hi] with a 1-2-5 step, about `target` of them.
std::vector<double> nice_ticks(double lo, double hi, int target = 6);

}  // namespace contour::planner
