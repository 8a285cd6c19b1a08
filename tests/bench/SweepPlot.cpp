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

namespace lacrima::bench {

namespace {

struct LogRange {
  double lo = 0, hi = 0;  // decades, whole numbers
};

LogRange decades(double minValue, double maxValue) {
  LogRange r{std::floor(std::log10(minValue)), std::ceil(std::log10(maxValue))};
  if (r.hi <= r.lo) r.hi = r.lo + 1;  // one value still gets a readable decade
  return r;
}

QString decadeLabel(int exponent) {
  // Plain numbers read faster than 1e-3 for the decades this benchmark spans.
  if (exponent >= 0 && exponent <= 4) return QString::number(std::pow(10.0, exponent), 'f', 0);
  if (exponent < 0 && exponent >= -3)
    return QString::number(std::pow(10.0, exponent), 'f', -exponent);
  return QStringLiteral("1e%1").arg(exponent);
}

}  // namespace

bool writeLogLogPlot(const std::string& path, const std::string& title, const std::string& xLabel,
                     const std::string& yLabel, const std::vector<PlotSeries>& series,
                     std::string& why) {
  double xMin = std::numeric_limits<double>::infinity(), xMax = 0, yMin = xMin, yMax = 0;
  for (const PlotSeries& s : series)
    for (const PlotPoint& p : s.points)
      if (p.x > 0 && p.y > 0 && std::isfinite(p.x) && std::isfinite(p.y)) {
        xMin = std::min(xMin, p.x), xMax = std::max(xMax, p.x);
        yMin = std::min(yMin, p.y), yMax = std::max(yMax, p.y);
      }
  if (xMax <= 0) xMin = 1, xMax = 10, yMin = 1, yMax = 10;  // empty plot: axes only
  const LogRange xr = decades(xMin, xMax), yr = decades(yMin, yMax);

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

  const int width = 1120, height = 700;
  const QRectF area(110, 60, 620, 540);  // the legend goes to the right of the plot area
  QImage image(width, height, QImage::Format_ARGB32);
  image.fill(Qt::white);
  QPainter painter(&image);
  painter.setRenderHint(QPainter::Antialiasing);
  QFont font = painter.font();
  font.setPixelSize(15);
  painter.setFont(font);

  auto toX = [&](double v) {
    return area.left() + (std::log10(v) - xr.lo) / (xr.hi - xr.lo) * area.width();
  };
  auto toY = [&](double v) {
    return area.bottom() - (std::log10(v) - yr.lo) / (yr.hi - yr.lo) * area.height();
  };

  // Grid: decades solid, 2..9 within each decade faint, so values can be read off.
  for (int e = int(xr.lo); e <= int(xr.hi); ++e) {
    for (int m = 1; m <= 9 && (m == 1 || e < int(xr.hi)); ++m) {
      const double x = toX(m * std::pow(10.0, e));
      painter.setPen(QPen(QColor(m == 1 ? 180 : 230, m == 1 ? 180 : 230, m == 1 ? 180 : 230), 1));
      painter.drawLine(QPointF(x, area.top()), QPointF(x, area.bottom()));
    }
    painter.setPen(Qt::black);
    painter.drawText(QRectF(toX(std::pow(10.0, e)) - 40, area.bottom() + 6, 80, 20),
                     Qt::AlignCenter, decadeLabel(e));
  }
  for (int e = int(yr.lo); e <= int(yr.hi); ++e) {
    for (int m = 1; m <= 9 && (m == 1 || e < int(yr.hi)); ++m) {
      const double y = toY(m * std::pow(10.0, e));
      painter.setPen(QPen(QColor(m == 1 ? 180 : 230, m == 1 ? 180 : 230, m == 1 ? 180 : 230), 1));
      painter.drawLine(QPointF(area.left(), y), QPointF(area.right(), y));
    }
    painter.setPen(Qt::black);
    painter.drawText(QRectF(area.left() - 75, toY(std::pow(10.0, e)) - 10, 68, 20),
                     Qt::AlignRight | Qt::AlignVCenter, decadeLabel(e));
  }
  painter.setPen(QPen(Qt::black, 1.5));
  painter.drawRect(area);

  // Title and axis labels.
  QFont big = font;
  big.setPixelSize(19);
  big.setBold(true);
  painter.setFont(big);
  painter.drawText(QRectF(0, 10, width, 36), Qt::AlignCenter, QString::fromStdString(title));
  painter.setFont(font);
  painter.drawText(QRectF(area.left(), area.bottom() + 32, area.width(), 24), Qt::AlignCenter,
                   QString::fromStdString(xLabel));
  painter.save();
  painter.translate(22, area.center().y());
  painter.rotate(-90);
  painter.drawText(QRectF(-area.height() / 2, -12, area.height(), 24), Qt::AlignCenter,
                   QString::fromStdString(yLabel));
  painter.restore();

  // Series: distinct hues and marker shapes, so they stay apart in greyscale too.
  const QColor colours[] = {QColor(31, 119, 180),  QColor(214, 39, 40),  QColor(44, 160, 44),
                            QColor(148, 103, 189), QColor(255, 127, 14), QColor(23, 190, 207)};
  auto marker = [&](QPointF c, int shape) {
    const double r = 6;
    if (shape % 3 == 0) {
      painter.drawEllipse(c, r, r);
    } else if (shape % 3 == 1) {
      painter.drawRect(QRectF(c.x() - r, c.y() - r, 2 * r, 2 * r));
    } else {
      QPainterPath tri;
      tri.moveTo(c.x(), c.y() - r - 1);
      tri.lineTo(c.x() + r + 1, c.y() + r);
      tri.lineTo(c.x() - r - 1, c.y() + r);
      tri.closeSubpath();
      painter.drawPath(tri);
    }
  };
  QFont small = font;
  small.setPixelSize(12);
  for (std::size_t k = 0; k < series.size(); ++k) {
    const QColor colour = colours[k % std::size(colours)];
    painter.setPen(QPen(colour, 2));
    painter.setBrush(Qt::NoBrush);
    QPointF last;
    bool haveLast = false;
    for (const PlotPoint& p : series[k].points) {
      if (!(p.x > 0 && p.y > 0)) continue;
      const QPointF c(toX(p.x), toY(p.y));
      if (haveLast) painter.drawLine(last, c);
      last = c;
      haveLast = true;
    }
    painter.setBrush(colour);
    painter.setFont(small);
    for (const PlotPoint& p : series[k].points) {
      if (!(p.x > 0 && p.y > 0)) continue;
      const QPointF c(toX(p.x), toY(p.y));
      painter.setPen(QPen(colour, 2));
      marker(c, int(k));
      painter.setPen(colour.darker(140));
      painter.drawText(c + QPointF(8, -8), QString::fromStdString(p.label));
    }
    painter.setFont(font);
    // Legend entry.
    const QPointF at(area.right() + 30, area.top() + 20 + 32 * double(k));
    painter.setPen(QPen(colour, 2));
    painter.drawLine(at, at + QPointF(36, 0));
    marker(at + QPointF(18, 0), int(k));
    painter.setPen(Qt::black);
    painter.drawText(QRectF(at.x() + 46, at.y() - 12, width - at.x() - 50, 24),
                     Qt::AlignLeft | Qt::AlignVCenter, QString::fromStdString(series[k].name));
  }
  painter.end();
  if (!image.save(QString::fromStdString(path), "PNG")) {
    why = "cannot write " + path;
    return false;
  }
  return true;
}

}  // namespace lacrima::bench
