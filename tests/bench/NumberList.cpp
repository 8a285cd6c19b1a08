#include "NumberList.h"

#include <QStringList>

#include <cmath>

namespace lacrima::bench {

std::string readNumberList(const QString& text, double low, double high, bool whole,
                           std::vector<double>& out) {
  const std::string expected =
      std::string("expected a comma-separated list of ") + (whole ? "whole numbers" : "numbers") +
      " from " + QString::number(low).toStdString() + " to " + QString::number(high).toStdString() +
      ", not '" + text.toStdString() + "'";
  std::vector<double> values;
  for (const QString& part : text.split(',')) {
    bool ok = false;
    const double v = part.trimmed().toDouble(&ok);
    if (!ok || !(v >= low && v <= high) || (whole && v != std::floor(v))) return expected;
    values.push_back(v);
  }
  if (values.empty()) return expected;
  out = std::move(values);
  return {};
}

}  // namespace lacrima::bench
