// A presets file (PresetLibrary::fromJson).
#include "FuzzInput.h"

#include <lacrima/common/Diagnostics.h>
#include <lacrima/editing/PresetLibrary.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    (void)lacrima::editing::PresetLibrary::fromJson(lacrima::fuzz::text(data, size), "fuzz.json");
  } catch (const lacrima::FileError&) {
  }
  return 0;
}
