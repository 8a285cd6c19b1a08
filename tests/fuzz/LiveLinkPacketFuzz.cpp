// Live Link Face packets (decodeLiveLinkPacket, then the shipped mapping): any datagram is a
// packet whose retargeted FAPs are finite, or a FileError.
#include "FuzzInput.h"

#include <lacrima/common/LiveLinkMapping.h>

#include <cmath>
#include <cstdlib>

namespace {

// A few rows of every kind (blendshape, angle) with large gains: retargeting must stay finite.
const lacrima::LiveLinkMapping& mapping() {
  static const lacrima::LiveLinkMapping kMapping = [] {
    lacrima::LiveLinkMapping m;
    m.rows = {{17, 3, 1e7}, {17, 3, 1e7}, {52, 49, -1e7}, {55, 23, 1e5}, {43, 31, 400}};
    return m;
  }();
  return kMapping;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  lacrima::fuzz::refusingOnlyWithFileError([&] {
    const lacrima::LiveLinkPacket packet =
        lacrima::decodeLiveLinkPacket(lacrima::fuzz::text(data, size), "fuzz.livelink");
    for (const float v : mapping().retarget(packet))
      if (!std::isfinite(v)) std::abort();
    (void)packet.frameRate();
  });
  return 0;
}
