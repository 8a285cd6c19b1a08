// TearQuality (TearQuality.h): the names of the levels.
#include <lacrima/common/TearQuality.h>

#include <cstddef>

namespace lacrima::inline common {

std::string_view toString(TearQuality level) {
  return kTearQualityNames.at(static_cast<std::size_t>(level));
}

std::optional<TearQuality> parseTearQuality(std::string_view name) {
  for (std::size_t i = 0; i < kTearQualityNames.size(); ++i)
    if (kTearQualityNames[i] == name) return static_cast<TearQuality>(i);
  return std::nullopt;
}

}  // namespace lacrima::inline common
