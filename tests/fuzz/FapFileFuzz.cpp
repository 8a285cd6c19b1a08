// A FAP file on disk (FapReader::readFile: the chunked streaming path).
#include "FuzzInput.h"

#include <lacrima/common/Diagnostics.h>
#include <lacrima/common/FapReader.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const lacrima::fuzz::InputFile file(data, size, ".fap");
  try {
    (void)lacrima::FapReader::readFile(file.path());
  } catch (const lacrima::FileError&) {
  }
  return 0;
}
