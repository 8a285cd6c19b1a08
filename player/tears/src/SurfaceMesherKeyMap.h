#pragma once
// Open-addressing hash map from 64-bit lattice keys to dense indices (linear probing, load
// factor <= 1/2, Fibonacci hashing). The mesher keys its active blocks by their packed
// integer coordinates; the map keeps its slots between frames, so a steady drop
// meshes without allocating. clear() costs the capacity, which follows the largest use.
#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

namespace lacrima::tears::detail {

class SurfaceMesherKeyMap {
 public:
  // Empties the map and makes room for `expected` keys without growing.
  void reset(std::size_t expected) {
    std::size_t capacity = 16;
    while (capacity < 2 * expected) capacity *= 2;
    if (capacity > slotKey_.size()) {
      slotKey_.assign(capacity, 0);
      slotValue_.resize(capacity);
      bits_ = log2(capacity);
    } else {
      std::fill(slotKey_.begin(), slotKey_.end(), 0);
    }
    size_ = 0;
  }
  std::size_t size() const { return size_; }

  // The value stored for `key`, or -1.
  std::int32_t find(std::uint64_t key) const {
    const std::uint64_t stored = key + 1;  // 0 marks an empty slot
    const std::size_t mask = slotKey_.size() - 1;
    for (std::size_t s = slot(key);; s = (s + 1) & mask) {
      if (slotKey_[s] == stored) return slotValue_[s];
      if (slotKey_[s] == 0) return -1;
    }
  }
  // Stores `value` for `key` unless the key is present; returns the stored value and whether
  // it was inserted now.
  std::pair<std::int32_t, bool> insert(std::uint64_t key, std::int32_t value) {
    if (2 * (size_ + 1) > slotKey_.size()) grow();
    const std::uint64_t stored = key + 1;
    const std::size_t mask = slotKey_.size() - 1;
    for (std::size_t s = slot(key);; s = (s + 1) & mask) {
      if (slotKey_[s] == stored) return {slotValue_[s], false};
      if (slotKey_[s] == 0) {
        slotKey_[s] = stored;
        slotValue_[s] = value;
        ++size_;
        return {value, true};
      }
    }
  }

 private:
  static int log2(std::size_t v) {
    int b = 0;
    while ((std::size_t{1} << b) < v) ++b;
    return b;
  }
  std::size_t slot(std::uint64_t key) const {
    return static_cast<std::size_t>((key * 0x9E3779B97F4A7C15ull) >> (64 - bits_));
  }
  void grow() {
    std::vector<std::uint64_t> oldKey = std::move(slotKey_);
    std::vector<std::int32_t> oldValue = std::move(slotValue_);
    const std::size_t capacity = oldKey.empty() ? 16 : 2 * oldKey.size();
    slotKey_.assign(capacity, 0);
    slotValue_.resize(capacity);
    bits_ = log2(capacity);
    size_ = 0;
    for (std::size_t s = 0; s < oldKey.size(); ++s)
      if (oldKey[s] != 0) insert(oldKey[s] - 1, oldValue[s]);
  }

  std::vector<std::uint64_t> slotKey_;  // key + 1, 0 = empty
  std::vector<std::int32_t> slotValue_;
  std::size_t size_ = 0;
  int bits_ = 4;
};

}  // namespace lacrima::tears::detail
