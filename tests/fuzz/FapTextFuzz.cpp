// FAP text (FapReader::parse): any text is an animation or a FileError.
#include "FuzzInput.h"

#include <lacrima/common/FapReader.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  lacrima::fuzz::refusingOnlyWithFileError([&] {
    const lacrima::FapReadResult result =
        lacrima::FapReader::parse(lacrima::fuzz::text(data, size), "fuzz.fap");
    (void)result.animation.frameCount();
  });
  return 0;
}
