// Tear parameters as a project's scene.simulation holds them (readTearParameters).
#include "FuzzInput.h"

#include <lacrima/common/JsonInput.h>
#include <lacrima/common/TearParameters.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  lacrima::fuzz::refusingOnlyWithFileError([&] {
    const lacrima::JsonInput input =
        lacrima::JsonInput::parse(lacrima::fuzz::text(data, size), "fuzz.json");
    (void)lacrima::readTearParameters(input.root());
  });
  return 0;
}
