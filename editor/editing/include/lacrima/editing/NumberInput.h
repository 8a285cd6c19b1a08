#pragma once
// Typed numbers, read exactly as typed or refused with a reason: the editor's fields never fix
// up input (QSpinBox dropped the '-' of "-5", the letters of "abc1.5e3" and the last digit of
// "999999", silently). A field's text is a number in C notation, nothing else:
//
//   [spaces] [+|-] digits [. digits] [(e|E) [+|-] digits] [spaces] [unit]
//
// (".5" and "5." are numbers too). The unit, when the field has one ("%", "fps"), may follow
// the number, with or without a space. The number must be finite, inside [min, max], and whole
// when the field takes whole numbers ("1.5e3" is 1500, whole; "2.5" of a particle is refused,
// not rounded). Decimal commas and thousands separators are refused with a hint, since "1,500"
// is 1.5 in half of the world's locales and 1500 in the other half.
//
// Time is read by parseTime: a number of seconds ("2.5", "2.5s", "2.5 s") or of frames ("55f",
// "55 f") at the project's rate; a bare number is read in the unit the field shows.
#include <QString>

#include <optional>

namespace lacrima::editing {

struct NumberRange {
  double min = 0, max = 0;
  bool wholeNumbers = false;
  QString unit;  // optional unit accepted after the number ("%", "fps"); empty: none
};

struct NumberParse {
  std::optional<double> value;  // set when accepted
  QString reason;               // why it was refused ("below 0", "not a number")
  bool accepted() const { return value.has_value(); }
};

// Reads text as a number inside range, or says why not.
NumberParse parseNumber(const QString& text, const NumberRange& range);

// "0 … 100000 whole particles", "-18600 … 18600", "1 … 240 fps": the range as a user reads it.
QString describeRange(const NumberRange& range, const QString& what = {});

// The text a field shows for a value: whole numbers without a decimal point, others with at
// most `decimals` decimals and no trailing zeros ("2.5", not "2.500").
QString formatNumber(double value, int decimals);

enum class TimeUnit { Seconds, Frames };

struct TimeParse {
  std::optional<double> seconds;  // set when accepted
  QString reason;
  bool accepted() const { return seconds.has_value(); }
};

// The longest time the time field reaches: an hour of animation.
inline constexpr double kMaxEditTime = 3600.0;

// Reads "2.5", "2.5 s", "55f" at fps frames per second; bare numbers are in `shown`. Frames
// must be whole; times lie in [0, kMaxEditTime].
TimeParse parseTime(const QString& text, double fps, TimeUnit shown);

}  // namespace lacrima::editing
