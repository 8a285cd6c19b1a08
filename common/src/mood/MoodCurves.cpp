#include <lacrima/common/mood/MoodCurves.h>

#include <algorithm>
#include <cmath>

namespace lacrima::inline common {

bool MoodCurves::empty() const {
  return std::all_of(curves.begin(), curves.end(),
                     [](const IntensityCurve& curve) { return curve.empty(); });
}

MoodLevels MoodCurves::at(double seconds) const {
  MoodLevels levels;
  for (Mood mood : kMoods) {
    const double value = (*this)[mood].at(seconds);
    levels[mood] = std::isfinite(value) ? std::clamp(value, 0.0, 1.0) : 0.0;
  }
  return levels;
}

double MoodCurves::startTime() const {
  bool any = false;
  double start = 0;
  for (const IntensityCurve& curve : curves) {
    if (curve.empty()) continue;
    start = any ? std::min(start, curve.startTime()) : curve.startTime();
    any = true;
  }
  return start;
}

double MoodCurves::endTime() const {
  double end = 0;
  for (const IntensityCurve& curve : curves)
    if (!curve.empty()) end = std::max(end, curve.endTime());
  return end;
}

}  // namespace lacrima::inline common
