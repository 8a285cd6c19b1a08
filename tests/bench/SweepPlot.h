#pragma once
// A headless log-log scatter plot (QPainter on a QImage) of error against cost, one series per
// swept quantity, for `lacrima-bench tears-sweep --png`.
#include <string>
#include <vector>

namespace lacrima::bench {

struct PlotPoint {
  double x = 0, y = 0;  // both > 0 (log axes); others are left out
  std::string label;    // drawn beside the point, e.g. "0.5x"
};

struct PlotSeries {
  std::string name;
  std::vector<PlotPoint> points;  // joined in the order given
};

// Writes a PNG; returns false (and sets `why`) when the image cannot be saved.
bool writeLogLogPlot(const std::string& path, const std::string& title, const std::string& xLabel,
                     const std::string& yLabel, const std::vector<PlotSeries>& series,
                     std::string& why);

}  // namespace lacrima::bench
