#pragma once
// RAII owners for the ODE handles the tear simulation uses. ODE is a C API with manual
// create/destroy pairs; each wrapper owns exactly one handle, is move-only, and releases it in
// its destructor, so no early return or exception can leak a geom or a trimesh data object.
// Private to the library: ODE headers never reach users of lacrima_tears.
#include <ode/ode.h>

#include <mutex>
#include <utility>

namespace lacrima::tears {

// Every ODE call holds this lock. Debian's ODE is built without thread-local storage: its
// trimesh collision caches are process-wide, so two simulations stepping on two threads at once
// (the editor's preview finishing one head's step on its worker while the next head's worker
// starts) corrupted each other (ODE's "fetchMeshTriangle: index out of range" assertion). With
// one simulation the lock is uncontended and costs nanoseconds per query; with several they
// take turns for ODE only. Recursive, so a handle released while the lock is held is fine.
[[nodiscard]] std::unique_lock<std::recursive_mutex> lockOde();

// dInitODE2 / dCloseODE, reference counted so several simulations can coexist. Also allocates
// ODE's collision data (process-wide in Debian's build; see lockOde).
class OdeLibrary {
 public:
  OdeLibrary();
  ~OdeLibrary();
  OdeLibrary(const OdeLibrary&) = delete;
  OdeLibrary& operator=(const OdeLibrary&) = delete;
};

template <typename Id, void (*Destroy)(Id)>
class OdeHandle {
 public:
  OdeHandle() = default;
  explicit OdeHandle(Id id) : id_(id) {}
  ~OdeHandle() { reset(); }
  OdeHandle(OdeHandle&& other) noexcept : id_(std::exchange(other.id_, nullptr)) {}
  OdeHandle& operator=(OdeHandle&& other) noexcept {
    if (this != &other) {
      reset();
      id_ = std::exchange(other.id_, nullptr);
    }
    return *this;
  }
  OdeHandle(const OdeHandle&) = delete;
  OdeHandle& operator=(const OdeHandle&) = delete;

  Id get() const { return id_; }
  explicit operator bool() const { return id_ != nullptr; }
  void reset() {
    if (!id_) return;
    const auto lock = lockOde();
    Destroy(std::exchange(id_, nullptr));
  }

 private:
  Id id_ = nullptr;
};

using OdeGeom = OdeHandle<dGeomID, dGeomDestroy>;
using OdeTriMeshData = OdeHandle<dTriMeshDataID, dGeomTriMeshDataDestroy>;

}  // namespace lacrima::tears
