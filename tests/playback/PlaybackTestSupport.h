#pragma once
// Shared by the playback suites: the default head rigged once per suite, and small animations
// built in memory so each test states exactly what it plays.

#include "../support/MissingData.h"

#include <lacrima/common/FapAnimation.h>
#include <lacrima/common/FapTable.h>
#include <lacrima/playback/HeadRig.h>
#include <lacrima/rigging/DefaultHead.h>
#include <lacrima/tears/ParticleSet.h>

#include <QtTest>

#include <cmath>
#include <functional>
#include <vector>

// In a suite's initTestCase: rigs the default head into `rig` (a std::unique_ptr<HeadRig>),
// or skips the suite when the head has not been fetched.
#define LOAD_DEFAULT_HEAD_RIG(rig)                                                        \
  do {                                                                                    \
    if (!::lacrima::rigging::defaultHeadAvailable()) LACRIMA_SKIP_WITHOUT_DEFAULT_HEAD(); \
    (rig) = ::lacrima::playback::loadDefaultHeadRig();                                    \
    QVERIFY((rig) && (rig)->blender);                                                     \
  } while (false)

namespace lacrima::playback::test {

inline constexpr double kFps = 22.0;

inline float& channel(FapValues& v, const char* name) {
  return v[static_cast<std::size_t>(channelIndex(*fapByName(name)))];
}

// `frames` frames at 22 fps, each filled by `fill(frame, values)`.
inline FapAnimation makeAnimation(int frames, const std::function<void(int, FapValues&)>& fill) {
  FapAnimation a;
  a.name = "test";
  a.fps = kFps;
  for (int f = 0; f < frames; ++f) {
    FapValues v{};
    fill(f, v);
    a.frames.push_back(v);
    for (int c = 0; c < kChannelCount; ++c)
      if (v[static_cast<std::size_t>(c)] != 0) a.animated.set(static_cast<std::size_t>(c));
  }
  return a;
}

// The jaw opens and closes (the skin under the tears moves) while `perEye` tears flow from
// frame `start` to frame `stop` (exclusive).
inline FapAnimation cryingAnimation(int frames, int perEye, int start = 0, int stop = 1 << 30) {
  return makeAnimation(frames, [=](int f, FapValues& v) {
    channel(v, "open_jaw") =
        static_cast<float>(std::round(300.0 * std::sin(f * 0.15) * std::sin(f * 0.15)));
    channel(v, "raise_l_i_eyebrow") = static_cast<float>(std::min(f, 40) * 5);
    const float tears = f >= start && f < stop ? static_cast<float>(perEye) : 0.0f;
    channel(v, "tears_l_eye") = tears;
    channel(v, "tears_r_eye") = tears;
  });
}

// The face moves, no tear channel is ever non-zero.
inline FapAnimation dryAnimation(int frames) {
  return makeAnimation(frames, [](int f, FapValues& v) {
    channel(v, "open_jaw") =
        static_cast<float>(std::round(400.0 * std::sin(f * 0.2) * std::sin(f * 0.2)));
    channel(v, "raise_l_cornerlip") = static_cast<float>(-2 * f);
  });
}

// Particles by id, then every state vector bit for bit (order is the solver's, also compared).
inline bool sameParticles(const tears::ParticleSet& a, const tears::ParticleSet& b) {
  return a.id == b.id && a.position == b.position && a.velocity == b.velocity && a.mass == b.mass &&
         a.age == b.age && a.eye == b.eye;
}

}  // namespace lacrima::playback::test
