#include <lacrima/scene/OgreRuntime.h>

#include "ShaderLibrary.h"

#include <OgreLogManager.h>
#include <OgreRenderWindow.h>
#include <OgreResourceGroupManager.h>
#include <OgreRoot.h>

#include <QDir>
#include <QStandardPaths>

#include <cstdlib>
#include <mutex>
#include <stdexcept>

namespace lacrima::scene {
namespace {

std::mutex gMutex;
std::weak_ptr<OgreRuntime> gCurrent;

std::string ogreLogPath() {
  QString dir = QStandardPaths::writableLocation(QStandardPaths::GenericCacheLocation);
  if (dir.isEmpty()) dir = QDir::tempPath();
  dir += QStringLiteral("/lacrima");
  QDir().mkpath(dir);
  return (dir + QStringLiteral("/ogre.log")).toStdString();
}

}  // namespace

struct OgreRuntime::Parts {
  std::string logPath;
  std::string group = "Lacrima";
  std::unique_ptr<Ogre::LogManager> log;
  std::unique_ptr<Ogre::Root> root;
  Ogre::RenderWindow* primary = nullptr;
  bool groupCreated = false;
  unsigned long long nextName = 0;

  ~Parts() {
    // Resources first (their GL objects need the context), then the Root (windows, render
    // system, plugins), then the log the Root writes to while it shuts down.
    if (root && groupCreated)
      Ogre::ResourceGroupManager::getSingleton().destroyResourceGroup(group);
    root.reset();
    log.reset();
  }
};

std::shared_ptr<OgreRuntime> OgreRuntime::acquire() {
  std::lock_guard lock(gMutex);
  if (auto current = gCurrent.lock()) return current;
  std::shared_ptr<OgreRuntime> runtime(new OgreRuntime);
  gCurrent = runtime;
  return runtime;
}

bool OgreRuntime::running() {
  std::lock_guard lock(gMutex);
  return !gCurrent.expired();
}

OgreRuntime::OgreRuntime() : parts_(std::make_unique<Parts>()) {
  const char* display = std::getenv("DISPLAY");
  if (!display || !*display)
    throw std::runtime_error(
        "3-D rendering needs an X display (OGRE renders through GLX): set DISPLAY, "
        "or run headless under xvfb-run -a");
  if (Ogre::Root::getSingletonPtr())
    throw std::runtime_error("3-D rendering: another OGRE Root already runs in this process");

  Parts& p = *parts_;
  p.logPath = ogreLogPath();
  try {
    if (!Ogre::LogManager::getSingletonPtr()) {
      p.log = std::make_unique<Ogre::LogManager>();
      p.log->createLog(p.logPath, true, false, false);  // file only: nothing on stdout
    }
    p.root = std::make_unique<Ogre::Root>("", "", "");
    p.root->loadPlugin(LACRIMA_OGRE_PLUGIN_DIR "/RenderSystem_GL3Plus");
    Ogre::RenderSystem* gl = p.root->getRenderSystemByName("OpenGL 3+ Rendering Subsystem");
    if (!gl) throw std::runtime_error("3-D rendering: OGRE's GL3Plus render system did not load");
    p.root->setRenderSystem(gl);
    p.root->initialise(false);

    Ogre::NameValuePairList misc;
    misc["hidden"] = "true";
    misc["vsync"] = "false";
    p.primary = p.root->createRenderWindow("lacrima-primary", 1, 1, false, &misc);
    p.primary->setAutoUpdated(false);

    auto& groups = Ogre::ResourceGroupManager::getSingleton();
    groups.createResourceGroup(p.group, false);
    p.groupCreated = true;
    groups.initialiseResourceGroup(p.group);
    detail::loadShaderLibrary(p.group, p.logPath);
  } catch (const Ogre::Exception& e) {
    throw std::runtime_error("3-D rendering could not start: " + e.getDescription() +
                             " (OGRE log: " + p.logPath + ")");
  }
}

OgreRuntime::~OgreRuntime() = default;

Ogre::Root& OgreRuntime::root() const { return *parts_->root; }
const std::string& OgreRuntime::resourceGroup() const { return parts_->group; }
const std::string& OgreRuntime::logPath() const { return parts_->logPath; }

std::string OgreRuntime::uniqueName(const std::string& stem) {
  return "lacrima/" + stem + "#" + std::to_string(parts_->nextName++);
}

}  // namespace lacrima::scene
