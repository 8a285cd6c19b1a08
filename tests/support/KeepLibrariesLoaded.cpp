// LD_PRELOAD'ed into a program under LeakSanitizer (packaging/lacrima.sh leaks): dlclose()
// does nothing, so that a library unloaded at exit (an OGRE plugin, the Mesa driver) keeps its
// data mapped and the memory it still references is not reported as leaked by a scan that can
// no longer see it, or name its module.
#include <dlfcn.h>

extern "C" int dlclose(void* handle) {
  (void)handle;
  return 0;
}
