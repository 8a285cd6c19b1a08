#include <lacrima/editing/NumberInput.h>

#include <charconv>
#include <cmath>
#include <string>

namespace lacrima::editing {
namespace {

bool isDigit(QChar c) { return c >= QLatin1Char('0') && c <= QLatin1Char('9'); }

// The longest prefix of `text` that is a number in C notation (see the header's grammar);
// returns its length, 0 when the text does not start with one.
qsizetype numberPrefix(QStringView text) {
  qsizetype i = 0;
  const qsizetype n = text.size();
  if (i < n && (text[i] == QLatin1Char('+') || text[i] == QLatin1Char('-'))) ++i;
  qsizetype digits = 0;
  while (i < n && isDigit(text[i])) ++i, ++digits;
  if (i < n && text[i] == QLatin1Char('.')) {
    ++i;
    while (i < n && isDigit(text[i])) ++i, ++digits;
  }
  if (digits == 0) return 0;
  // An exponent counts only when digits follow it: "2e" is the number 2 and the unit "e".
  if (i < n && (text[i] == QLatin1Char('e') || text[i] == QLatin1Char('E'))) {
    qsizetype j = i + 1;
    if (j < n && (text[j] == QLatin1Char('+') || text[j] == QLatin1Char('-'))) ++j;
    const qsizetype exponentStart = j;
    while (j < n && isDigit(text[j])) ++j;
    if (j > exponentStart) i = j;
  }
  return i;
}

struct Split {
  std::optional<double> number;  // the leading number, when there is one and it is finite
  QString rest;                  // what follows it, trimmed
  QString reason;                // why there is no number
};

// Splits "  -2.5e1 fps " into -25 and "fps".
Split splitNumber(const QString& text) {
  Split split;
  const QString trimmed = text.trimmed();
  if (trimmed.isEmpty()) {
    split.reason = QStringLiteral("empty");
    return split;
  }
  const qsizetype length = numberPrefix(trimmed);
  if (length == 0) {
    split.reason = QStringLiteral("not a number");
    return split;
  }
  // std::from_chars is exact (correctly rounded) and ignores the C locale, which a Qt
  // application sets from the environment (strtod would read "2.5" as 2 under de_DE).
  std::string ascii = trimmed.left(length).toStdString();
  if (ascii.front() == '+') ascii.erase(0, 1);
  double value = 0;
  const auto [end, error] = std::from_chars(ascii.data(), ascii.data() + ascii.size(), value);
  if (error == std::errc::result_out_of_range || !std::isfinite(value)) {
    split.reason = QStringLiteral("too large to be a number here");
    return split;
  }
  if (error != std::errc() || end != ascii.data() + ascii.size()) {
    split.reason = QStringLiteral("not a number");
    return split;
  }
  split.number = value + 0.0;  // -0 reads as 0
  split.rest = trimmed.mid(length).trimmed();
  return split;
}

// Why `rest` cannot follow a number: decimal commas and separators get a hint.
QString trailingReason(const QString& rest) {
  if (rest.startsWith(QLatin1Char(',')))
    return QStringLiteral("use '.' for decimals and no thousands separators");
  return QStringLiteral("\"%1\" after the number").arg(rest);
}

}  // namespace

QString formatNumber(double value, int decimals) {
  if (!std::isfinite(value)) return QStringLiteral("?");
  if (value == std::floor(value) && std::abs(value) < 1e15)
    return QString::number(static_cast<long long>(value));
  QString text = QString::number(value, 'f', std::max(0, decimals));
  if (text.contains(QLatin1Char('.'))) {
    while (text.endsWith(QLatin1Char('0'))) text.chop(1);
    if (text.endsWith(QLatin1Char('.'))) text.chop(1);
  }
  if (text == QLatin1String("-0")) text = QStringLiteral("0");
  return text;
}

QString describeRange(const NumberRange& range, const QString& what) {
  QString text =
      QStringLiteral("%1 … %2").arg(formatNumber(range.min, 6), formatNumber(range.max, 6));
  if (!what.isEmpty()) return text + QLatin1Char(' ') + what;
  if (!range.unit.isEmpty()) text += QLatin1Char(' ') + range.unit;
  if (range.wholeNumbers) text += QStringLiteral(", whole numbers");
  return text;
}

NumberParse parseNumber(const QString& text, const NumberRange& range) {
  NumberParse result;
  const Split split = splitNumber(text);
  if (!split.number) {
    result.reason = split.reason;
    return result;
  }
  if (!split.rest.isEmpty() &&
      (range.unit.isEmpty() ||
       split.rest.compare(range.unit.trimmed(), Qt::CaseInsensitive) != 0)) {
    result.reason = trailingReason(split.rest);
    return result;
  }
  const double v = *split.number;
  if (range.wholeNumbers && v != std::floor(v)) {
    result.reason = QStringLiteral("not a whole number");
    return result;
  }
  if (v < range.min) {
    result.reason = QStringLiteral("below %1").arg(formatNumber(range.min, 6));
    return result;
  }
  if (v > range.max) {
    result.reason = QStringLiteral("above %1").arg(formatNumber(range.max, 6));
    return result;
  }
  result.value = v;
  return result;
}

TimeParse parseTime(const QString& text, double fps, TimeUnit shown) {
  TimeParse result;
  if (!(fps > 0) || !std::isfinite(fps)) {
    result.reason = QStringLiteral("the project has no frame rate");
    return result;
  }
  const Split split = splitNumber(text);
  if (!split.number) {
    result.reason = split.reason;
    return result;
  }
  TimeUnit unit = shown;
  if (split.rest.compare(QLatin1String("s"), Qt::CaseInsensitive) == 0)
    unit = TimeUnit::Seconds;
  else if (split.rest.compare(QLatin1String("f"), Qt::CaseInsensitive) == 0)
    unit = TimeUnit::Frames;
  else if (!split.rest.isEmpty()) {
    result.reason = trailingReason(split.rest) + QStringLiteral(" (units: s or f)");
    return result;
  }
  const double v = *split.number;
  if (unit == TimeUnit::Frames && v != std::floor(v)) {
    result.reason = QStringLiteral("frames are whole");
    return result;
  }
  const double seconds = unit == TimeUnit::Frames ? v / fps : v;
  if (seconds < 0) {
    result.reason = QStringLiteral("before 0 s");
    return result;
  }
  if (seconds > kMaxEditTime) {
    result.reason = QStringLiteral("after %1 s").arg(formatNumber(kMaxEditTime, 0));
    return result;
  }
  result.seconds = seconds;
  return result;
}

}  // namespace lacrima::editing
