// A presets file (PresetLibrary::fromJson).
#include "FuzzInput.h"

#include <lacrima/editing/PresetLibrary.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  lacrima::fuzz::refusingOnlyWithFileError([&] {
    (void)lacrima::editing::PresetLibrary::fromJson(lacrima::fuzz::text(data, size), "fuzz.json");
  });
  return 0;
}
