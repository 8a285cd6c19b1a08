// A project turned into an animation, as the player and lacrima-fap do (readAnimationFile):
// read to bake, then baked. The bake must stay within kMaxBakedFrames and throw nothing.
#include "FuzzInput.h"

#include <lacrima/common/Diagnostics.h>
#include <lacrima/common/ProjectDocument.h>

#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  lacrima::ProjectDocument document;
  try {
    document = lacrima::ProjectDocument::fromJson(lacrima::fuzz::text(data, size), "fuzz.json",
                                                  lacrima::ProjectDocument::Use::Bake);
  } catch (const lacrima::FileError&) {
    return 0;
  }
  const lacrima::FapAnimation animation = document.bake();
  if (!(static_cast<double>(animation.frames.size()) <= lacrima::kMaxBakedFrames)) std::abort();
  return 0;
}
