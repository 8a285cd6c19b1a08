#pragma once
// Particle state as a structure of arrays: one contiguous vector per attribute, so each solver
// pass streams only the attributes it reads (SPlisHSPlasH's layout). Index i is the same particle
// in every array; removal compacts all arrays in order, which keeps iteration (and so every
// floating-point sum) deterministic.
#include <Eigen/Core>

#include <cstdint>
#include <span>
#include <vector>

namespace lacrima::tears {

enum class Eye : std::uint8_t { Left = 0, Right = 1 };

// Contact with the skin, tracked on one triangle by barycentric coordinates so the particle
// can be carried along when the face deforms.
struct SkinContact {
  std::int32_t triangle = -1;            // skin triangle index, -1 = not touching
  Eigen::Vector3d barycentric{0, 0, 0};  // of the contact point on that triangle
};

class ParticleSet {
 public:
  int size() const { return static_cast<int>(position.size()); }
  bool empty() const { return position.empty(); }

  // Appends one particle at rest; returns its index.
  int add(const Eigen::Vector3d& x, double mass, std::uint64_t id, Eye eye);
  // Makes slot i a new particle at rest (as add() would, without moving any other particle).
  void reset(int i, const Eigen::Vector3d& x, double mass, std::uint64_t id, Eye eye);
  // Keeps particles with keep[i] != 0, in their order.
  void compact(std::span<const std::uint8_t> keep);
  // Reorders every array: particle order[s] moves to index s (order is a permutation).
  void permute(std::span<const int> order);
  void clear();

  // Kinematics
  std::vector<Eigen::Vector3d> position;
  std::vector<Eigen::Vector3d> velocity;
  std::vector<Eigen::Vector3d> acceleration;  // non-contact forces of the current sub-step
  // SPH fields
  std::vector<double> mass;
  std::vector<double> density;
  std::vector<double> pressure;
  std::vector<double> viscosityRate;  // sum of viscosity weights, 1/s (stability limit)
  // Bookkeeping
  std::vector<std::uint64_t> id;  // unique, increasing with emission time: oldest = smallest
  std::vector<double> age;        // seconds since emission
  std::vector<double> travelled;  // distance slid over the skin (mass loss)
  std::vector<Eye> eye;
  // Skin contact
  std::vector<SkinContact> contact;
  std::vector<double> clearance;  // free particles: guaranteed gap to the skin (lower bound)

 private:
  // permute's buffers, one per attribute type, kept so reordering does not allocate. They hold
  // no state: copying a ParticleSet (a checkpoint) leaves them behind.
  struct Scratch {
    Scratch() = default;
    Scratch(const Scratch&) {}
    Scratch& operator=(const Scratch&) { return *this; }
    Scratch(Scratch&&) = default;
    Scratch& operator=(Scratch&&) = default;

    std::vector<Eigen::Vector3d> vectors;
    std::vector<double> scalars;
    std::vector<std::uint64_t> ids;
    std::vector<Eye> eyes;
    std::vector<SkinContact> contacts;
  } scratch_;
};

// FNV-1a (64 bits) over the bits of every particle's id, position and velocity, in particle
// order: two runs that agree bit for bit give the same hash, and one differing bit almost
// surely changes it (lacrima-bench tears prints it to compare thread counts).
std::uint64_t stateHash(const ParticleSet& particles);

}  // namespace lacrima::tears
