#include "TearSimulationInternals.h"

#include <lacrima/tears/TearCheckpoint.h>

#include <stdexcept>

namespace lacrima::tears {

// Everything restore() needs to make the future repeat. Left out on purpose: the pair geometry
// of a sub-step (ActivePairs, the force pass's float copies), which every sub-step rebuilds
// before reading, and the exposed grid, rebuilt on demand. The cell index is kept: the pair
// list searches its cells for strays until the next rebuild.
struct TearCheckpoint::State {
  std::uint64_t instance = 0;
  ParticleSet particles;
  VerletPairs candidates;  // when the pair list is next rebuilt decides the particle order
  CellIndex cells;         // the list's cells (stray searches)
  Emitter emitter;
  SkinCollider::Surface skin;
  bool skinStale = true;
  std::array<Eigen::Vector3d, 2> sources;
  Eigen::AlignedBox3d box;
  std::array<double, 2> trailVolume{0, 0};
  PressureHistory pressure;  // what the pressure solver carries between sub-steps
};

TearCheckpoint::TearCheckpoint() = default;
TearCheckpoint::~TearCheckpoint() = default;
TearCheckpoint::TearCheckpoint(const TearCheckpoint&) = default;
TearCheckpoint& TearCheckpoint::operator=(const TearCheckpoint&) = default;
TearCheckpoint::TearCheckpoint(TearCheckpoint&&) noexcept = default;
TearCheckpoint& TearCheckpoint::operator=(TearCheckpoint&&) noexcept = default;

int TearCheckpoint::particleCount() const { return state_ ? state_->particles.size() : 0; }

std::size_t TearCheckpoint::bytes() const {
  if (!state_) return 0;
  const ParticleSet& p = state_->particles;
  const std::size_t n = static_cast<std::size_t>(p.size());
  const std::size_t perParticle = 3 * sizeof(Eigen::Vector3d) + 7 * sizeof(double) +
                                  sizeof(std::uint64_t) + sizeof(Eye) + sizeof(SkinContact);
  const std::size_t pairs = (n + 1 + state_->candidates.pairCount()) * sizeof(std::uint32_t) +
                            n * sizeof(Eigen::Vector3d) + n * (sizeof(int) + 3 * sizeof(double)) +
                            state_->cells.cellCount() * 4 * sizeof(std::uint64_t);
  const std::size_t skin = static_cast<std::size_t>(state_->skin.vertices.size()) * sizeof(double) +
                           state_->skin.normals.size() * (sizeof(Eigen::Vector3d) + 1);
  return sizeof(State) + n * perParticle + pairs + skin;
}

TearCheckpoint TearSimulation::checkpoint() const {
  const Internals& in = *internals_;
  auto state = std::make_shared<TearCheckpoint::State>(TearCheckpoint::State{
      instance_, particles_, in.candidates, in.cellIndex, in.emitter, in.collider->surface(),
      skinStale_, sources_, box_, trailVolume_, in.pressure->history()});
  TearCheckpoint c;
  c.state_ = std::move(state);
  return c;
}

void TearSimulation::restore(const TearCheckpoint& checkpoint) {
  if (checkpoint.empty()) throw std::invalid_argument("restoring an empty tear checkpoint");
  const TearCheckpoint::State& s = *checkpoint.state_;
  if (s.instance != instance_)
    throw std::invalid_argument("the tear checkpoint was taken from another simulation");
  Internals& in = *internals_;
  CollisionCounters c;
  in.collider->restoreSurface(s.skin, c);
  addCollisionCounters(counters_, c);
  particles_ = s.particles;  // assignment: the buffers keep their capacity
  in.candidates = s.candidates;
  in.cellIndex = s.cells;
  in.emitter = s.emitter;
  skinStale_ = s.skinStale;
  sources_ = s.sources;
  box_ = s.box;
  trailVolume_ = s.trailVolume;
  in.pressure->restoreHistory(s.pressure);
  exposedGridStale_ = true;
  times_ = {};
}

}  // namespace lacrima::tears
