// A mood script (MoodScript::parse) and the take it drives: two seconds at 22 fps, every channel
// within its range, as lacrima-fap generate makes it.
#include "FuzzInput.h"

#include <lacrima/common/mood/MoodGenerator.h>

#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  lacrima::fuzz::refusingOnlyWithFileError([&] {
    const lacrima::MoodScript script =
        lacrima::MoodScript::parse(lacrima::fuzz::text(data, size), "fuzz.json");
    const lacrima::MoodTake take = lacrima::generateMoodTake(script, size, 2, 22);
    for (const lacrima::FapValues& frame : take.animation.frames)
      for (int fap = 1; fap <= lacrima::kChannelCount; ++fap) {
        const float v = frame[lacrima::channelIndex(fap)];
        const lacrima::ChannelRange range = lacrima::generatedRange(fap);
        if (!(v >= range.min && v <= range.max)) std::abort();
      }
  });
  return 0;
}
