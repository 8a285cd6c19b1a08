#pragma once
// RAII owners for the ODE handles the tear simulation uses. ODE is a C API with manual
// create/destroy pairs; each wrapper owns exactly one handle, is move-only, and releases it in
// its destructor, so no early return or exception can leak a geom or a trimesh data object.
// Private to the library: ODE headers never reach users of lacrima_tears.
#include <ode/ode.h>

#include <utility>

namespace lacrima::tears {

// dInitODE2 / dCloseODE, reference counted so several simulations can coexist. Also allocates
// ODE's per-thread collision data; ODE is used from the constructing thread only (Debian's
// build has no thread-local storage, so trimesh queries from two threads would corrupt it).
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
    if (id_) Destroy(std::exchange(id_, nullptr));
  }

 private:
  Id id_ = nullptr;
};

using OdeGeom = OdeHandle<dGeomID, dGeomDestroy>;
using OdeTriMeshData = OdeHandle<dTriMeshDataID, dGeomTriMeshDataDestroy>;

}  // namespace lacrima::tears
