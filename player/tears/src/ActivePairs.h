#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

namespace lacrima::tears {

// The pairs within h this sub-step, i < j, with their squared distance, and the positions
// DensitySolver measured them with (single precision, relative to one origin). A pass recomputes
// a pair's offset as position i - position j, the same float operation, so it gets the density
// pass's bits; the offsets are not stored (16 bytes a pair, written every sub-step and read
// back, where the positions are 16 bytes a particle that stay in cache).
//
// Particle i's pairs are k in [begin(i), end(i)). The pairs of one chunk of particles
// (kParticleChunk, ParallelChunks.h) lie together, from where the chunk's candidates start:
// chunks filled by different threads need not know how many pairs the others keep, and the
// room their unkept candidates leave stays unused (size per-pair arrays by indexLimit()).
struct ActivePairs {
  std::vector<std::uint32_t> first, last;  // size n: [first[i], last[i]) are i's pairs
  std::vector<std::uint32_t> partner;      // indexLimit() long
  std::vector<float> r2;                   // |x_i - x_j|^2
  std::vector<float> position;             // 4 per particle: x, y, z, 0 (one SSE register)
  std::size_t kept = 0;                    // pairs in all

  int particleCount() const { return static_cast<int>(first.size()); }
  std::uint32_t begin(std::size_t i) const { return first[i]; }
  std::uint32_t end(std::size_t i) const { return last[i]; }
  std::size_t pairCount() const { return kept; }
  // One past the largest pair index in use or reserved: the length of a per-pair array.
  std::size_t indexLimit() const { return partner.size(); }
};

}  // namespace lacrima::tears
