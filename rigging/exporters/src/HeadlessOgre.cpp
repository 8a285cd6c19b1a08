#include <lacrima/exporters/HeadlessOgre.h>

#include <OgreDefaultHardwareBufferManager.h>
#include <OgreLogManager.h>
#include <OgreMaterialManager.h>
#include <OgreMeshManager.h>
#include <OgreRoot.h>
#include <OgreTextureManager.h>

namespace lacrima::exporters {

HeadlessOgre::HeadlessOgre() {
  if (!Ogre::LogManager::getSingletonPtr()) {
    log_ = std::make_unique<Ogre::LogManager>();
    // Default log, no debugger/stdout echo, no file: a command-line tool or a test run must not
    // leave Ogre.log files in whatever directory it was started from.
    log_->createLog("lacrima-headless-ogre", true, false, true);
  }
  if (!Ogre::Root::getSingletonPtr()) {
    // No plugins.cfg, no ogre.cfg, no log file name: nothing is read from or written to disk.
    root_ = std::make_unique<Ogre::Root>("", "", "");
  }
  // A render system would provide both managers; without one, .mesh serialisation needs
  // system-memory buffers and material scripts need somewhere to register texture names.
  if (!Ogre::HardwareBufferManager::getSingletonPtr())
    buffers_ = std::make_unique<Ogre::DefaultHardwareBufferManager>();
  if (!Ogre::TextureManager::getSingletonPtr())
    textures_ = std::make_unique<Ogre::DefaultTextureManager>();
}

HeadlessOgre::~HeadlessOgre() {
  // Meshes keep buffers of buffers_ and materials keep textures of textures_; deleting a
  // manager while its resources live segfaults, so the resources go first.
  if (buffers_) Ogre::MeshManager::getSingleton().removeAll();
  if (textures_) {
    Ogre::MaterialManager::getSingleton().removeAll();
    textures_->removeAll();
  }
  textures_.reset();
  buffers_.reset();
  root_.reset();
  log_.reset();
}

}  // namespace lacrima::exporters
