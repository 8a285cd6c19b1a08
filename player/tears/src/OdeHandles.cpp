#include "OdeHandles.h"

#include <mutex>

namespace lacrima::tears {
namespace {
std::mutex gMutex;
int gUsers = 0;
}  // namespace

std::unique_lock<std::recursive_mutex> lockOde() {
  static std::recursive_mutex odeMutex;
  return std::unique_lock(odeMutex);
}

OdeLibrary::OdeLibrary() {
  const std::lock_guard lock(gMutex);
  const auto ode = lockOde();
  if (gUsers++ == 0) dInitODE2(0);
  dAllocateODEDataForThread(dAllocateMaskAll);
}

OdeLibrary::~OdeLibrary() {
  const std::lock_guard lock(gMutex);
  const auto ode = lockOde();
  if (--gUsers == 0) dCloseODE();
}

}  // namespace lacrima::tears
