#include "SweepPlot.h"

#include <QtGui/QColor>
#include <QtGui/QFont>
#include <QtGui/QGuiApplication>
#include <QtGui/QImage>
#include <QtGui/QPainter>
#include <QtGui/QPainterPath>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <vector>

namespace lacrima::bench {

namespace {

// One axis: where values land (in [0, 1] of the plot area) and the grid lines to draw.
struct AxisScale {
  bool log = true;
  double lo = 0, hi = 1;  // decades on a log axis, values on a linear one
  struct Tick {
    double value;
    bool major;  // labelled, drawn darker
  };
  std::vector<Tick> ticks;

  double fraction(double v) const { return ((log ? std::log10(v) : v) - lo) / (hi - lo); }
  bool drawable(double v) const { return std::isfinite(v) && (!log || v > 0); }
};

// Log: whole decades, with 2..9 of each decade as faint lines so values can be read off.
AxisScale logScale(double minValue, double maxValue) {
  AxisScale a;
  a.lo = std::floor(std::log10(minValue));
  a.hi = std::ceil(std::log10(maxValue));
  if (a.hi <= a.lo) a.hi = a.lo + 1;  // one value still gets a readable decade
  for (int e = int(a.lo); e <= int(a.hi); ++e)
    for (int m = 1; m <= 9 && (m == 1 || e < int(a.hi)); ++m)
      a.ticks.push_back({m * std::pow(10.0, e), m == 1});
  return a;
}

// Linear: from 0 (or below, for negative values) to the data's top, about six steps of 1, 2 or
// 5 times a power of ten; half steps as faint lines.
AxisScale linearScale(double minValue, double maxValue) {
  AxisScale a;
  a.log = false;
  const double lo = std::min(0.0, minValue), hi = std::max(maxValue, lo + 1e-12);
  const double raw = (hi - lo) / 6, power = std::pow(10.0, std::floor(std::log10(raw)));
  double step = power;
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (m * power >= raw) {
      step = m * power;
      break;
    }
  a.lo = std::floor(lo / step) * step;
  a.hi = std::ceil(hi / step) * step;
  if (a.hi <= a.lo) a.hi = a.lo + step;
  for (int k = 0; a.lo + k * step / 2 <= a.hi + step * 1e-9; ++k)
    a.ticks.push_back({a.lo + k * step / 2, k % 2 == 0});
  return a;
}

QString tickLabel(const AxisScale& axis, double value) {
  if (axis.log) {
    // Plain numbers read faster than 1e-3 for the decades these benchmarks span.
    const int exponent = int(std::lround(std::log10(value)));
    if (exponent >= 0 && exponent <= 4) return QString::number(value, 'f', 0);
    if (exponent < 0 && exponent >= -3) return QString::number(value, 'f', -exponent);
    return QStringLiteral("1e%1").arg(exponent);
  }
  return QString::number(value, 'g', 4);
}

}  // namespace

bool writePlot(const std::string& path, const PlotAxes& axes, const std::vector<PlotSeries>& series,
               std::string& why) {
  double xMin = std::numeric_limits<double>::infinity(), xMax = -xMin, yMin = xMin, yMax = -xMin;
  for (const PlotSeries& s : series)
    for (const PlotPoint& p : s.points)
      if (std::isfinite(p.x) && std::isfinite(p.y) && (!axes.logX || p.x > 0) &&
          (!axes.logY || p.y > 0)) {
        xMin = std::min(xMin, p.x), xMax = std::max(xMax, p.x);
        yMin = std::min(yMin, p.y), yMax = std::max(yMax, p.y);
      }
  if (!(xMax >= xMin)) xMin = 1, xMax = 10, yMin = 1, yMax = 10;  // empty plot: axes only
  const AxisScale xs = axes.logX ? logScale(xMin, xMax) : linearScale(xMin, xMax);
  const AxisScale ys = axes.logY ? logScale(yMin, yMax) : linearScale(yMin, yMax);

  // Text needs the font database, which needs a QGuiApplication; the offscreen platform keeps
  // the benchmark headless (no display on build machines).
  std::unique_ptr<QGuiApplication> app;
  if (!QGuiApplication::instance()) {
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
    static int argc = 1;
    static char name[] = "lacrima-bench";
    static char* argv[] = {name, nullptr};
    app = std::make_unique<QGuiApplication>(argc, argv);
  }

  const int width = 1180, height = 700;
  const QRectF area(110, 60, 620, 540);  // the legend goes to the right of the plot area
  QImage image(width, height, QImage::Format_ARGB32);
  image.fill(Qt::white);
  QPainter painter(&image);
  painter.setRenderHint(QPainter::Antialiasing);
  QFont font = painter.font();
  font.setPixelSize(15);
  painter.setFont(font);

  auto toX = [&](double v) { return area.left() + xs.fraction(v) * area.width(); };
  auto toY = [&](double v) { return area.bottom() - ys.fraction(v) * area.height(); };

  for (const AxisScale::Tick& t : xs.ticks) {
    const int grey = t.major ? 180 : 230;
    painter.setPen(QPen(QColor(grey, grey, grey), 1));
    painter.drawLine(QPointF(toX(t.value), area.top()), QPointF(toX(t.value), area.bottom()));
    if (!t.major) continue;
    painter.setPen(Qt::black);
    painter.drawText(QRectF(toX(t.value) - 40, area.bottom() + 6, 80, 20), Qt::AlignCenter,
                     tickLabel(xs, t.value));
  }
  for (const AxisScale::Tick& t : ys.ticks) {
    const int grey = t.major ? 180 : 230;
    painter.setPen(QPen(QColor(grey, grey, grey), 1));
    painter.drawLine(QPointF(area.left(), toY(t.value)), QPointF(area.right(), toY(t.value)));
    if (!t.major) continue;
    painter.setPen(Qt::black);
    painter.drawText(QRectF(area.left() - 75, toY(t.value) - 10, 68, 20),
                     Qt::AlignRight | Qt::AlignVCenter, tickLabel(ys, t.value));
  }
  painter.setPen(QPen(Qt::black, 1.5));
  painter.drawRect(area);

  // Title and axis labels.
  QFont big = font;
  big.setPixelSize(19);
  big.setBold(true);
  painter.setFont(big);
  painter.drawText(QRectF(0, 10, width, 36), Qt::AlignCenter, QString::fromStdString(axes.title));
  painter.setFont(font);
  painter.drawText(QRectF(area.left(), area.bottom() + 32, area.width(), 24), Qt::AlignCenter,
                   QString::fromStdString(axes.xLabel));
  painter.save();
  painter.translate(22, area.center().y());
  painter.rotate(-90);
  painter.drawText(QRectF(-area.height() / 2, -12, area.height(), 24), Qt::AlignCenter,
                   QString::fromStdString(axes.yLabel));
  painter.restore();

  // Series: distinct hues and marker shapes, so they stay apart in greyscale too.
  const QColor colours[] = {QColor(31, 119, 180),  QColor(214, 39, 40),   QColor(44, 160, 44),
                            QColor(148, 103, 189), QColor(255, 127, 14),  QColor(23, 190, 207),
                            QColor(140, 86, 75),   QColor(227, 119, 194), QColor(0, 0, 0)};
  // The series' own shape, else circle, square and triangle by position in the list.
  auto marker = [&](QPointF c, const PlotSeries& s, std::size_t position) {
    using Shape = PlotSeries::Shape;
    const Shape byPosition[] = {Shape::Circle, Shape::Square, Shape::Triangle};
    const Shape shape = s.shape != Shape::ByPosition ? s.shape : byPosition[position % 3];
    const double r = 6;
    QPainterPath path;
    switch (shape) {
      case Shape::Square:
        path.addRect(QRectF(c.x() - r, c.y() - r, 2 * r, 2 * r));
        break;
      case Shape::Triangle:
        path.moveTo(c.x(), c.y() - r - 1);
        path.lineTo(c.x() + r + 1, c.y() + r);
        path.lineTo(c.x() - r - 1, c.y() + r);
        path.closeSubpath();
        break;
      case Shape::Diamond:
        path.moveTo(c.x(), c.y() - r - 2);
        path.lineTo(c.x() + r + 1, c.y());
        path.lineTo(c.x(), c.y() + r + 2);
        path.lineTo(c.x() - r - 1, c.y());
        path.closeSubpath();
        break;
      default:
        path.addEllipse(c, r, r);
    }
    painter.drawPath(path);
  };
  auto drawable = [&](const PlotPoint& p) { return xs.drawable(p.x) && ys.drawable(p.y); };
  QFont small = font;
  small.setPixelSize(12);
  painter.setClipRect(area.adjusted(-8, -8, 8, 8));  // fitted lines may run past the data
  // Points already labelled: a point drawn on top of one (the same run in two series, e.g. the
  // default kernel and the default sub-step) keeps the first label, so the text stays readable.
  std::vector<QPointF> labelled;
  for (std::size_t k = 0; k < series.size(); ++k) {
    const PlotSeries& s = series[k];
    const QColor colour =
        colours[std::size_t(s.colour >= 0 ? s.colour : int(k)) % std::size(colours)];
    QPen line(colour, 2, s.dashed ? Qt::DashLine : Qt::SolidLine);
    painter.setPen(line);
    painter.setBrush(Qt::NoBrush);
    QPointF last;
    bool haveLast = false;
    for (const PlotPoint& p : s.points) {
      if (!drawable(p)) continue;
      const QPointF c(toX(p.x), toY(p.y));
      if (haveLast) painter.drawLine(last, c);
      last = c;
      haveLast = true;
    }
    if (!s.markers) continue;
    // Hollow markers for dashed series: the same runs, another reference.
    painter.setBrush(s.dashed ? QBrush(Qt::white) : QBrush(colour));
    painter.setFont(small);
    for (const PlotPoint& p : s.points) {
      if (!drawable(p)) continue;
      const QPointF c(toX(p.x), toY(p.y));
      painter.setPen(QPen(colour, 2));
      marker(c, s, k);
      const bool covered = std::any_of(labelled.begin(), labelled.end(), [&](QPointF q) {
        return std::abs(q.x() - c.x()) < 3 && std::abs(q.y() - c.y()) < 3;
      });
      if (covered || p.label.empty()) continue;
      labelled.push_back(c);
      painter.setPen(colour.darker(140));
      painter.drawText(c + QPointF(8, -8), QString::fromStdString(p.label));
    }
    painter.setFont(font);
  }
  painter.setClipping(false);

  // Legend, right of the plot area so it never covers data.
  for (std::size_t k = 0; k < series.size(); ++k) {
    const PlotSeries& s = series[k];
    const QColor colour =
        colours[std::size_t(s.colour >= 0 ? s.colour : int(k)) % std::size(colours)];
    const QPointF at(area.right() + 24, area.top() + 14 + 30 * double(k));
    painter.setPen(QPen(colour, 2, s.dashed ? Qt::DashLine : Qt::SolidLine));
    painter.setBrush(s.dashed ? QBrush(Qt::white) : QBrush(colour));
    painter.drawLine(at, at + QPointF(36, 0));
    painter.setPen(QPen(colour, 2));
    if (s.markers) marker(at + QPointF(18, 0), s, k);
    painter.setPen(Qt::black);
    painter.drawText(QRectF(at.x() + 44, at.y() - 12, width - at.x() - 46, 24),
                     Qt::AlignLeft | Qt::AlignVCenter, QString::fromStdString(s.name));
  }
  painter.end();
  // No alpha channel, and PNG's strongest compression (quality 0): the figures are committed.
  const QImage opaque = image.convertToFormat(QImage::Format_RGB888);
  if (!opaque.save(QString::fromStdString(path), "PNG", 0)) {
    why = "cannot write " + path;
    return false;
  }
  return true;
}

bool writeLogLogPlot(const std::string& path, const std::string& title, const std::string& xLabel,
                     const std::string& yLabel, const std::vector<PlotSeries>& series,
                     std::string& why) {
  return writePlot(path, PlotAxes{title, xLabel, yLabel, true, true}, series, why);
}

}  // namespace lacrima::bench
