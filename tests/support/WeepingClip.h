#pragma once
// A short animation for the tests that render or export one: the jaw opens by `jawPerFrame` a
// frame while both eyes weep `tears` particles' worth, at 22 fps.
#include <lacrima/common/FapAnimation.h>
#include <lacrima/common/FapTable.h>

namespace lacrima::testsupport {

inline FapAnimation weepingClip(int frames, float jawPerFrame, float tears) {
  FapAnimation a;
  a.name = "short";
  a.fps = 22;
  for (int f = 0; f < frames; ++f) {
    FapValues v{};
    v[static_cast<std::size_t>(channelIndex(*fapByName("open_jaw")))] =
        jawPerFrame * static_cast<float>(f);
    v[static_cast<std::size_t>(channelIndex(kTearLeftFap))] =
        v[static_cast<std::size_t>(channelIndex(kTearRightFap))] = tears;
    a.frames.push_back(v);
  }
  return a;
}

}  // namespace lacrima::testsupport
