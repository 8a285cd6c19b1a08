#include <lacrima/rigging/InfluenceRadius.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <stdexcept>
#include <string>

namespace lacrima::rigging {

namespace {

int parsePart(std::string_view text) {
  int value = -1;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  return error == std::errc() && end == text.data() + text.size() && !text.empty() ? value : -1;
}

double positive(double value, const char* unit, std::string_view featurePoint) {
  if (!(value > 0) || !std::isfinite(value))
    throw std::invalid_argument("defaultInfluenceRadius: " + std::string(unit) +
                                " for feature point " + std::string(featurePoint) +
                                " is not a positive distance");
  return value;
}

}  // namespace

double defaultInfluenceRadius(const FapuSet& fapu, std::string_view featurePoint) {
  const size_t dot = featurePoint.find('.');
  const int group = dot == std::string_view::npos ? -1 : parsePart(featurePoint.substr(0, dot));
  const int index = dot == std::string_view::npos ? -1 : parsePart(featurePoint.substr(dot + 1));
  if (group < 2 || group > 11 || index < 1)
    throw std::invalid_argument("defaultInfluenceRadius: '" + std::string(featurePoint) +
                                "' is not a feature point id of groups 2-11 such as \"8.3\"");
  const auto mw = [&] { return positive(fapu.mw0, "MW0", featurePoint); };
  const auto es = [&] { return positive(fapu.es0, "ES0", featurePoint); };
  switch (group) {
    case 2:
      return index == 1 || index >= 10 ? mw() : mw() / 4;
    case 8:
    case 6:
      return mw() / 4;
    case 3:
    case 10:
      return es() / 4;
    case 4:
      return es() / 3;
    case 9:
      return positive(fapu.ens0, "ENS0", featurePoint) / 4;
    default:  // 5 cheeks, 7 head, 11 hair line
      return es() / 2;
  }
}

std::optional<FoldFreeRange> foldFreeRange(int fap) {
  if (fap >= 31 && fap <= 36) return FoldFreeRange{-200, 400};
  if (fap == 37 || fap == 38) return FoldFreeRange{-200, 100};
  return std::nullopt;
}

DirectionalReach directionalReach(double radius, double unitValue, const FoldFreeRange& range) {
  DirectionalReach reach;
  reach.across = radius;
  reach.ahead = std::max(radius, kReachPerDisplacement * std::max(0.0, range.max) * unitValue);
  reach.behind = std::max(radius, kReachPerDisplacement * std::max(0.0, -range.min) * unitValue);
  return reach;
}

}  // namespace lacrima::rigging
