#include <lacrima/editing/Mirror.h>

#include <lacrima/common/FapTable.h>

namespace lacrima::editing {

Keyframe mirrored(const Keyframe& key) {
  Keyframe out;
  out.time = key.time;
  out.interpolation = key.interpolation;
  for (int fap = 1; fap <= kChannelCount; ++fap) {
    if (!key.has(fap)) continue;
    const float v = key.value(fap);
    out.set(mirroredFap(fap), mirrorNegates(fap) ? -v : v);
  }
  return out;
}

std::optional<std::pair<int, float>> symmetricPartner(int fap, float value) {
  const int partner = mirroredFap(fap);
  if (partner == fap) return std::nullopt;
  return std::make_pair(partner, mirrorNegates(fap) ? -value : value);
}

}  // namespace lacrima::editing
