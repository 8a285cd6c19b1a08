#include "OdeHandles.h"

#include <mutex>

namespace lacrima::tears {
namespace {
std::mutex gMutex;
int gUsers = 0;
}  // namespace

OdeLibrary::OdeLibrary() {
  const std::lock_guard lock(gMutex);
  if (gUsers++ == 0) dInitODE2(0);
  dAllocateODEDataForThread(dAllocateMaskAll);
}

OdeLibrary::~OdeLibrary() {
  const std::lock_guard lock(gMutex);
  if (--gUsers == 0) dCloseODE();
}

}  // namespace lacrima::tears
