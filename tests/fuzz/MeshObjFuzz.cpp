// A head as OBJ text through assimp (importHeadMesh), the "bring your own head" path.
#include "FuzzInput.h"

#include <lacrima/rigging/MeshImport.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const lacrima::fuzz::InputFile file(data, size, ".obj");
  lacrima::fuzz::refusingOnlyWithFileError(
      [&] { (void)lacrima::rigging::importHeadMesh(file.path()); });
  return 0;
}
