#pragma once
// A saved state of one TearSimulation: everything that shapes the future (particles with their
// contacts, the Verlet pair list and hence the particle order, the emitter's next id, the skin
// the collider holds, sources, box, trail volumes, the pressure solver's memory of the last
// sub-step). TearSimulation::restore() puts it back, after which the same inputs give the same
// particles, bit for bit, as the run that took it. The copy is plain vectors (about 0.2 KB per
// particle plus the skin), so a player can keep one per second of animation and seek by
// restoring the nearest and stepping forward.
#include <cstddef>
#include <memory>

namespace lacrima::tears {

class TearSimulation;

// Copyable and cheap to copy (the state is shared and immutable); empty() until assigned from
// TearSimulation::checkpoint().
class TearCheckpoint {
 public:
  TearCheckpoint();
  ~TearCheckpoint();
  TearCheckpoint(const TearCheckpoint&);
  TearCheckpoint& operator=(const TearCheckpoint&);
  TearCheckpoint(TearCheckpoint&&) noexcept;
  TearCheckpoint& operator=(TearCheckpoint&&) noexcept;

  bool empty() const { return !state_; }
  int particleCount() const;
  std::size_t bytes() const;  // memory held by the saved state

 private:
  friend class TearSimulation;
  struct State;
  std::shared_ptr<const State> state_;
};

}  // namespace lacrima::tears
