#pragma once
// An allocator whose resize() leaves new elements of trivial types uninitialised, for buffers
// that are grown and then overwritten: the Verlet candidate lists are resized ahead of every
// build, and std::allocator zeroed the megabytes about to be written (a memset per build, and
// a page fault per page of it on a fresh allocation). Elements built with arguments (push_back,
// insert) are constructed as usual.
#include <memory>
#include <new>
#include <type_traits>
#include <utility>

namespace lacrima::tears {

template <class T>
struct UninitialisedAllocator : std::allocator<T> {
  static_assert(std::is_trivially_default_constructible_v<T>);
  template <class U>
  struct rebind {
    using other = UninitialisedAllocator<U>;
  };
  UninitialisedAllocator() noexcept = default;
  template <class U>
  UninitialisedAllocator(const UninitialisedAllocator<U>&) noexcept {}

  template <class U>
  void construct(U* p) noexcept {
    ::new (static_cast<void*>(p)) U;  // default-initialisation: no value for a trivial type
  }
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};

// A vector of trivial values whose resize() does not zero what it adds.
template <class T>
using UninitialisedVector = std::vector<T, UninitialisedAllocator<T>>;

}  // namespace lacrima::tears
