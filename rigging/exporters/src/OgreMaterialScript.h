#pragma once
// The OGRE material script for a head's materials, and the texture files it refers to.
#include <lacrima/common/HeadMesh.h>

#include <string>
#include <vector>

namespace lacrima::exporters {

struct OgreMaterialScript {
  // Script name of each HeadMaterial, by index: "<prefix>/<material name>", made unique.
  std::vector<std::string> names;
  // The whole .material file.
  std::string text;
  // Textures to copy beside the script: the script refers to them by `fileName` alone, which is
  // the source's file name unless two different sources share one (then "_2", "_3", ...).
  struct TextureCopy {
    std::string source;
    std::string fileName;
  };
  std::vector<TextureCopy> textures;
};

// One material per HeadMaterial: lit diffuse colour (times the texture), specular colour and
// shininess; transparent materials blend by alpha and do not write depth, so what lies behind
// eyelashes still shows; a cornea is an additive, glossy layer (black diffuse, strong specular)
// because the eyeball underneath already gives the colour.
OgreMaterialScript makeOgreMaterialScript(const HeadMesh& head, const std::string& prefix);

}  // namespace lacrima::exporters
