#pragma once
// OGRE without a window: enough of OGRE to build, write and read .mesh and .material files on a
// machine with no display (the rigging CLI, tests, an export from the editor).
//
// It creates whichever of these does not exist yet and destroys only what it created:
//   a silent LogManager (no log file, nothing on stdout), a Root with no plugins and no render
//   system, a DefaultHardwareBufferManager (system-memory buffers) and a DefaultTextureManager
//   (lets material scripts with texture units parse; textures are never decoded).
// So inside an application that already runs OGRE it borrows that Root and its managers.
// Only one object should own the singletons at a time; nesting one inside another just borrows.
//
// Tear-down follows the order that does not crash: every MeshPtr and TexturePtr held by the
// caller must be gone before this object is destroyed; it then removes all meshes, materials and
// textures, deletes the texture manager, the buffer manager, the Root, and last the LogManager.
#include <memory>

namespace Ogre {
class DefaultHardwareBufferManager;
class DefaultTextureManager;
class LogManager;
class Root;
}  // namespace Ogre

namespace lacrima::exporters {

class HeadlessOgre {
 public:
  HeadlessOgre();
  ~HeadlessOgre();
  HeadlessOgre(const HeadlessOgre&) = delete;
  HeadlessOgre& operator=(const HeadlessOgre&) = delete;

  // Whether this object created the Root (false: it runs inside someone else's OGRE).
  bool ownsRoot() const { return root_ != nullptr; }

 private:
  std::unique_ptr<Ogre::LogManager> log_;
  std::unique_ptr<Ogre::Root> root_;
  std::unique_ptr<Ogre::DefaultHardwareBufferManager> buffers_;
  std::unique_ptr<Ogre::DefaultTextureManager> textures_;
};

}  // namespace lacrima::exporters
