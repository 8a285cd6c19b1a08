// A project file read to edit (ProjectDocument::fromJson), and written back: what reads must
// write and read again to the same document.
#include "FuzzInput.h"

#include <lacrima/common/Diagnostics.h>
#include <lacrima/common/ProjectDocument.h>

#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  lacrima::ProjectDocument document;
  try {
    document = lacrima::ProjectDocument::fromJson(lacrima::fuzz::text(data, size), "fuzz.json");
  } catch (const lacrima::FileError&) {
    return 0;
  }
  // A document that was read is written and read back unchanged.
  if (!(lacrima::ProjectDocument::fromJson(document.toJson(), "again.json") == document))
    std::abort();
  return 0;
}
