#pragma once
// A member that copies of its owner do not take: working buffers kept between calls only for
// their capacity. A checkpoint is a copy of the solver's state (TearCheckpoint.cpp); copying
// the pair list's and the cell index's buffers made a checkpoint at 10,000 particles on two
// threads twice the size of one on one thread (8.2 against 4.2 MB; 3.3 MB without them). A copy
// starts empty, an assignment keeps the buffers it has, a move moves them.
#include <utility>

namespace lacrima::tears {

template <class T>
class Scratch {
 public:
  Scratch() = default;
  Scratch(const Scratch&) {}
  Scratch& operator=(const Scratch&) { return *this; }
  Scratch(Scratch&&) noexcept = default;
  Scratch& operator=(Scratch&&) noexcept = default;
  ~Scratch() = default;

  T& operator*() { return value_; }
  const T& operator*() const { return value_; }
  T* operator->() { return &value_; }
  const T* operator->() const { return &value_; }

 private:
  T value_{};
};

}  // namespace lacrima::tears
