#pragma once
// A headless scatter plot (QPainter on a QImage), one series per swept quantity: error against
// cost on log axes for `lacrima-bench tears-sweep --png`, and measured speeds beside their fitted
// line on linear axes for `lacrima-bench tears-slide --png`.
#include <string>
#include <vector>

namespace lacrima::bench {

struct PlotPoint {
  double x = 0, y = 0;  // finite; > 0 on a log axis (others are left out)
  std::string label;    // drawn beside the point, e.g. "0.5x"
};

struct PlotSeries {
  std::string name;
  std::vector<PlotPoint> points;  // joined in the order given
  int colour = -1;      // palette index (8: black); -1: the series' own position in the list
  bool dashed = false;  // e.g. the same runs measured against another reference
  bool markers = true;  // false: a line alone (a fitted law)
  enum class Shape { ByPosition, Circle, Square, Triangle, Diamond };
  Shape shape = Shape::ByPosition;  // ByPosition: circle, square, triangle in turn
};

struct PlotAxes {
  std::string title, xLabel, yLabel;
  bool logX = true, logY = true;
};

// Writes a PNG; returns false (and sets `why`) when the image cannot be saved.
bool writePlot(const std::string& path, const PlotAxes& axes, const std::vector<PlotSeries>& series,
               std::string& why);

// Log-log (the sweep's error against cost).
bool writeLogLogPlot(const std::string& path, const std::string& title, const std::string& xLabel,
                     const std::string& yLabel, const std::vector<PlotSeries>& series,
                     std::string& why);

}  // namespace lacrima::bench
