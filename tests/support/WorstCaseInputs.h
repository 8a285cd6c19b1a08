#pragma once
// Inputs at the far end of what the readers and the baker meet, shared by the unit tests that
// check what these produce and by `lacrima-bench worst-cases`, which times them.
#include "KeyBuilders.h"

#include <lacrima/common/FapChannels.h>
#include <lacrima/common/Keyframes.h>

#include <random>
#include <string>
#include <vector>

namespace lacrima::test {

// Channels of tenMinutesOfKeys(): every key sets the first two, every tenth key the third.
inline constexpr int kTenMinutesChannels[] = {3, 69, 5};

// 13,200 keys, one per frame for 10 minutes at 22 fps, linear and smooth by turns.
inline KeyframeSequence tenMinutesOfKeys() {
  std::vector<Keyframe> list;
  std::mt19937 random(1);
  std::uniform_real_distribution<float> value(-300.0f, 300.0f);
  const auto [jaw, tears, lip] = kTenMinutesChannels;
  for (int i = 0; i < 13200; ++i) {
    list.push_back(keyAt(i / 22.0, {{jaw, value(random)}, {tears, 3.0f}},
                         i % 2 ? Interpolation::Smooth : Interpolation::Linear));
    if (i % 10 == 0) list.back().set(lip, value(random));
  }
  return KeyframeSequence(std::move(list));
}

// A FAP file whose third line, a frame of FAP 3, is 8 MiB of digits: the reader must refuse it
// at its line limit, on line 3.
inline std::string eightMebibyteLineFap() {
  std::string maskLine = "0 0 1";
  for (int fap = 4; fap <= kFapCount; ++fap) maskLine += " 0";
  return "2.1 t 25 1\n" + maskLine + "\n" + std::string(8 << 20, '7') + "\n";
}

}  // namespace lacrima::test
