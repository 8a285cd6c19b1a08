#include <lacrima/common/FaceColours.h>

#include <algorithm>
#include <cmath>

namespace lacrima::inline common {
namespace {

double unit(double x) { return std::isfinite(x) ? std::clamp(x, 0.0, 1.0) : 0.0; }

}  // namespace

KeyedColours FaceColourCurves::at(double seconds) const {
  KeyedColours keyed;
  if (!redness.empty()) keyed.redness = unit(redness.at(seconds));
  if (!blush.empty()) keyed.blush = unit(blush.at(seconds));
  return keyed;
}

}  // namespace lacrima::inline common
