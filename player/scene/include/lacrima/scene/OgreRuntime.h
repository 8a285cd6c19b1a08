#pragma once
// One OGRE per process, shared by every face scene (the off-screen FaceRenderer and the
// on-screen FaceViewport): whoever needs OGRE holds a shared_ptr from acquire(); the last
// holder to let go shuts OGRE down, and a later acquire() starts it again.
//
// Start-up (50-90 ms here): a LogManager writing to a file in the cache folder (never to
// stdout), a Root with no config files, the GL3Plus render system, and a hidden 1x1 window
// that owns the GL context every other window and render texture shares (so closing a
// viewport never takes the context with it). Then Lacrima's GLSL 330 programs and material
// scripts, compiled into the library from media/shaders and media/materials, are loaded into
// their own resource group and checked: a shader that does not compile is an error here, not
// a black frame later. No RT Shader System: every material has its own programs.
//
// Shut-down runs in the order that does not crash (docs/stack.md, "OGRE start-up and
// shut-down"): holders destroy their scene managers and release their resources first (they hold
// the shared_ptr, so they are gone before this object), then the resource group, the Root and
// last the log.
//
// Needs an X display (OGRE on Debian is GLX only): acquire() throws std::runtime_error saying
// so when there is none, and when another OGRE Root already runs in this process.
#include <memory>
#include <string>

namespace Ogre {
class Root;
}  // namespace Ogre

namespace lacrima::scene {

class OgreRuntime {
 public:
  static std::shared_ptr<OgreRuntime> acquire();
  // Whether a runtime exists now (tests prove that a widget without X never started one).
  static bool running();

  ~OgreRuntime();
  OgreRuntime(const OgreRuntime&) = delete;
  OgreRuntime& operator=(const OgreRuntime&) = delete;

  Ogre::Root& root() const;
  // The resource group holding Lacrima's programs, materials and every scene's resources.
  const std::string& resourceGroup() const;
  // A process-unique resource name starting with `stem`.
  std::string uniqueName(const std::string& stem);
  // Where OGRE writes its log.
  const std::string& logPath() const;

 private:
  OgreRuntime();
  struct Parts;
  std::unique_ptr<Parts> parts_;
};

}  // namespace lacrima::scene
