// The importer process's answer as the parent reads it (ImportedMeshWire.h): a child whose assimp
// a crafted file subverted may send any bytes, and the reader must refuse them with a FileError,
// never crash or allocate what they announce. Seeds: the answers lacrima-import gave for the
// heads of each format family the assimp targets start from, and a refusal.
#include "FuzzInput.h"

#include <lacrima/rigging/ImportedMeshWire.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  lacrima::fuzz::refusingOnlyWithFileError([&] {
    (void)lacrima::rigging::wire::readImportAnswer(lacrima::fuzz::text(data, size), "answer");
  });
  return 0;
}
