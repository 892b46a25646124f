#include "plot/svg.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

namespace contour::plot {
namespace {

TEST(Svg, EscapesTextAndDrawsEverySeries) {
  Plot p;
  p.title = "a < b & c";
  p.series.push_back({"path", "#f00", {{0, 0}, {1, 1}, {2, 0}}});
  p.series.push_back({"ideal", "#00f", {{0, 0}, {2, 0}}, 1.0, true});
  const std::string s = render(p);
  EXPECT_NE(s.find("a &lt; b &amp; c"), std::string::npos);
  EXPECT_EQ(s.find("a < b"), std::string::npos);
  // One polyline per non-empty series, with one coordinate pair per point.
  std::size_t n = 0;
  for (std::size_t at = s.find("<polyline"); at != std::string::npos; at = s.find("<polyline", at + 1)) ++n;
  EXPECT_EQ(n, 2u);
  EXPECT_NE(s.find("stroke-dasharray"), std::string::npos);
  EXPECT_EQ(s.rfind("</svg>\n"), s.size() - 7);
}

TEST(Svg, EqualAspectKeepsTheSameScaleOnBothAxes) {
  Plot p;
  p.equal_aspect = true;
  p.width = 600;
  p.height = 400;
  // A unit square: with equal aspect its drawn width equals its height.
  p.series.push_back({"sq", "#000", {{0, 0}, {10, 0}, {10, 10}, {0, 10}, {0, 0}}});
  const std::string s = render(p);
  const auto at = s.find("points=\"") + 8;
  double x0, y0, x1, y1, x2, y2;
  ASSERT_EQ(std::sscanf(s.c_str() + at, "%lf,%lf %lf,%lf %lf,%lf", &x0, &y0, &x1, &y1, &x2, &y2), 6);
  EXPECT_NEAR(x1 - x0, y1 - y2, 0.01) << "coordinates are written to 6 significant digits";
}

TEST(Svg, PlotsInlinedInOnePageClipToTheirOwnFrames) {
  Plot a, b;
  a.series.push_back({"a", "#000", {{0, 0}, {1, 1}}});
  b.series.push_back({"b", "#000", {{0, 0}, {100, 3}}});
  auto clip_id = [](const std::string& svg) {
    const auto at = svg.find("<clipPath id=\"") + 14;
    return svg.substr(at, svg.find('"', at) - at);
  };
  const std::string ra = render(a), rb = render(b);
  EXPECT_NE(clip_id(ra), clip_id(rb));
  EXPECT_NE(ra.find("clip-path=\"url(#" + clip_id(ra) + ")\""), std::string::npos);
  EXPECT_EQ(clip_id(ra), clip_id(render(a))) << "deterministic";
}

TEST(Svg, LongSeriesAreThinnedKeepingBothEnds) {
  Plot p;
  p.max_points = 11;
  Series s{"ramp", "#000", {}};
  for (int i = 0; i <= 1000; ++i) s.points.push_back({double(i), double(i % 7)});
  p.series = {s};
  const std::string svg = render(p);
  const auto at = svg.find("points=\"") + 8;
  const std::string pts = svg.substr(at, svg.find('"', at) - at);
  EXPECT_EQ(std::count(pts.begin(), pts.end(), ','), 11);
  // Same drawing as the 11 points 0, 100, ..., 1000 given directly.
  Plot q = p;
  q.series[0].points.clear();
  for (int i = 0; i <= 1000; i += 100) q.series[0].points.push_back({double(i), double(i % 7)});
  EXPECT_EQ(render(q), svg);
}

// The legend's box: x, y, width, height (from its <rect ... fill="white" stroke="#ccc"/>).
struct Rect {
  double x = 0, y = 0, w = 0, h = 0;
};
Rect legend_box(const std::string& svg) {
  const auto end = svg.find("fill=\"white\" stroke=\"#ccc\"");
  const auto at = svg.rfind("<rect", end);
  Rect r;
  EXPECT_EQ(std::sscanf(svg.c_str() + at, "<rect x=\"%lf\" y=\"%lf\" width=\"%lf\" height=\"%lf\"", &r.x, &r.y, &r.w,
                        &r.h),
            4)
      << svg.substr(at, 120);
  return r;
}
// The frame (the data area): <rect ... fill="none" stroke="#333"/>.
Rect frame_box(const std::string& svg) {
  const auto end = svg.find("fill=\"none\" stroke=\"#333\"");
  const auto at = svg.rfind("<rect", end);
  Rect r;
  EXPECT_EQ(std::sscanf(svg.c_str() + at, "<rect x=\"%lf\" y=\"%lf\" width=\"%lf\" height=\"%lf\"", &r.x, &r.y, &r.w,
                        &r.h),
            4);
  return r;
}

// Paper A's Fig. 5 path ends at (0, 6), top left: the legend must not hide
// it (it once sat top-left whatever the data).
TEST(Svg, TheLegendGoesToACornerWithoutData) {
  Plot p;
  p.equal_aspect = true;
  p.series.push_back({"pulse path", "#d62728", {{6, 0}, {5, 0}, {5, 4}, {3, 5}, {3, 6}, {0, 6}}});
  const std::string svg = render(p);
  const Rect lg = legend_box(svg), fr = frame_box(svg);
  // Top right: the path's end (0, 6) is top left.
  EXPECT_GT(lg.x, fr.x + fr.w / 2);
  EXPECT_LT(lg.y, fr.y + fr.h / 2);
  // Flipped left-right, the end is top right: the legend moves to the left.
  for (auto& pt : p.series[0].points) pt.x = -pt.x;
  const Rect lg2 = legend_box(render(p));
  EXPECT_LT(lg2.x + lg2.w, fr.x + fr.w / 2);
}

// Data in every corner: the legend goes below the frame, outside the data.
TEST(Svg, WithDataInEveryCornerTheLegendGoesOutside) {
  Plot p;
  Series s{"a long label for a zigzag that fills the frame", "#000", {}};
  for (int i = 0; i <= 40; ++i) s.points.push_back({double(i), double(i % 2)});
  p.series = {s};
  const std::string svg = render(p);
  const Rect lg = legend_box(svg), fr = frame_box(svg);
  EXPECT_GT(lg.y, fr.y + fr.h);
  EXPECT_LE(lg.y + lg.h, p.height);
}

// Rates in kpps and big values print as numbers, not "1e+06".
TEST(Svg, TickLabelsHaveNoExponentsForOrdinaryNumbers) {
  Plot p;
  p.series.push_back({"", "#000", {{0, 0}, {2e6, 3528000}}});
  const std::string svg = render(p);
  EXPECT_EQ(svg.find("e+06"), std::string::npos);
  EXPECT_NE(svg.find(">2000000<"), std::string::npos);
}

}  // namespace
}  // namespace contour::plot
