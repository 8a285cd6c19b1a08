// A three.js JSON model (readThreeModel): the format of the MakeHuman default head and its
// proxies, read at set-up from the npm package.
#include "FuzzInput.h"
#include "ThreeJsonModel.h"  // internal to lacrima_rigging (rigging/src is on this target's path)

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const lacrima::fuzz::InputFile file(data, size, ".json");
  lacrima::fuzz::refusingOnlyWithFileError(
      [&] { (void)lacrima::rigging::readThreeModel(file.path()); });
  return 0;
}
