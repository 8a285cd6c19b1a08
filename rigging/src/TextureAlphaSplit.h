#pragma once
// Telling apart the parts of a mesh that its texture makes transparent.
#include "ThreeJsonModel.h"

#include <string>
#include <vector>

namespace lacrima::rigging {

// For each face in `faceIndices` of `model`: whether the texture at `texturePath` is mostly
// transparent (alpha below one half) at the centre of the face's uvs. MakeHuman's eye texture
// paints the cornea transparent black: drawn with the eyeball's opaque material it would hide
// the iris, so those faces need a material of their own.
// Throws FileError naming the texture when it cannot be read or has no alpha channel.
std::vector<bool> transparentAtUvCentre(const ThreeModel& model,
                                        const std::vector<int>& faceIndices,
                                        const std::string& texturePath);

}  // namespace lacrima::rigging
