#include "TextureUpload.h"

#include <OgreImage.h>
#include <OgreTextureManager.h>

namespace lacrima::scene::detail {

Ogre::TexturePtr uploadTexture(const QImage& image, const std::string& name,
                               const std::string& group, bool mipmaps) {
  QImage pixels = image.isNull() ? QImage(1, 1, QImage::Format_RGBA8888)
                                 : image.convertToFormat(QImage::Format_RGBA8888);
  if (image.isNull()) pixels.fill(Qt::white);
  // Rows must be tightly packed for Ogre::Image.
  if (pixels.bytesPerLine() != pixels.width() * 4) pixels = pixels.copy();
  Ogre::Image ogreImage;
  ogreImage.loadDynamicImage(pixels.bits(), static_cast<Ogre::uint32>(pixels.width()),
                             static_cast<Ogre::uint32>(pixels.height()), 1, Ogre::PF_BYTE_RGBA,
                             false);
  return Ogre::TextureManager::getSingleton().loadImage(name, group, ogreImage, Ogre::TEX_TYPE_2D,
                                                        mipmaps ? Ogre::MIP_DEFAULT : 0);
}

}  // namespace lacrima::scene::detail
