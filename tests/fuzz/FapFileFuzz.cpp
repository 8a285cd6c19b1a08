// A FAP file on disk (FapReader::readFile: the chunked streaming path).
#include "FuzzInput.h"

#include <lacrima/common/FapReader.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const lacrima::fuzz::InputFile file(data, size, ".fap");
  lacrima::fuzz::refusingOnlyWithFileError(
      [&] { (void)lacrima::FapReader::readFile(file.path()); });
  return 0;
}
