#pragma once
// QImage -> OGRE texture. Textures go through Qt rather than an OGRE codec plugin because the
// overlay layers are computed from the pixels on the CPU anyway (OverlayTextures.h), and Qt
// reads every format a head may bring.
#include <OgreTexture.h>

#include <QImage>

#include <string>

namespace lacrima::scene::detail {

// A 2-D RGBA texture with a full mip chain (`mipmaps`) or one level (masks).
Ogre::TexturePtr uploadTexture(const QImage& image, const std::string& name,
                               const std::string& group, bool mipmaps);

}  // namespace lacrima::scene::detail
