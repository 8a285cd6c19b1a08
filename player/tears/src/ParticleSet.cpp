#include <lacrima/tears/ParticleSet.h>

#include <cassert>

namespace lacrima::tears {
namespace {

template <typename T>
void compactVector(std::vector<T>& v, std::span<const std::uint8_t> keep) {
  std::size_t out = 0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (keep[i]) {
      if (out != i) v[out] = std::move(v[i]);
      ++out;
    }
  }
  v.resize(out);
}

// v[s] = old v[order[s]]. The gathered copy is swapped in, so `scratch` keeps the old buffer
// for the next attribute of the same type: reordering allocates nothing once sizes settle.
template <typename T>
void gather(std::vector<T>& v, std::span<const int> order, std::vector<T>& scratch) {
  scratch.resize(v.size());
  for (std::size_t s = 0; s < v.size(); ++s) scratch[s] = v[static_cast<std::size_t>(order[s])];
  v.swap(scratch);
}

}  // namespace

void ParticleSet::permute(std::span<const int> order) {
  assert(order.size() == position.size());
  gather(position, order, scratch_.vectors);
  gather(velocity, order, scratch_.vectors);
  gather(acceleration, order, scratch_.vectors);
  gather(mass, order, scratch_.scalars);
  gather(density, order, scratch_.scalars);
  gather(pressure, order, scratch_.scalars);
  gather(viscosityRate, order, scratch_.scalars);
  gather(id, order, scratch_.ids);
  gather(age, order, scratch_.scalars);
  gather(travelled, order, scratch_.scalars);
  gather(eye, order, scratch_.eyes);
  gather(contact, order, scratch_.contacts);
  gather(clearance, order, scratch_.scalars);
}

int ParticleSet::add(const Eigen::Vector3d& x, double m, std::uint64_t newId, Eye e) {
  position.push_back(x);
  velocity.emplace_back(Eigen::Vector3d::Zero());
  acceleration.emplace_back(Eigen::Vector3d::Zero());
  mass.push_back(m);
  density.push_back(0.0);
  pressure.push_back(0.0);
  viscosityRate.push_back(0.0);
  id.push_back(newId);
  age.push_back(0.0);
  travelled.push_back(0.0);
  eye.push_back(e);
  contact.emplace_back();
  clearance.push_back(0.0);  // unknown: the first collision pass queries the skin
  return size() - 1;
}

void ParticleSet::reset(int i, const Eigen::Vector3d& x, double m, std::uint64_t newId, Eye e) {
  const auto s = static_cast<std::size_t>(i);
  position[s] = x;
  velocity[s].setZero();
  acceleration[s].setZero();
  mass[s] = m;
  density[s] = 0.0;
  pressure[s] = 0.0;
  viscosityRate[s] = 0.0;
  id[s] = newId;
  age[s] = 0.0;
  travelled[s] = 0.0;
  eye[s] = e;
  contact[s] = {};
  clearance[s] = 0.0;
}

void ParticleSet::compact(std::span<const std::uint8_t> keep) {
  assert(keep.size() == position.size());
  compactVector(position, keep);
  compactVector(velocity, keep);
  compactVector(acceleration, keep);
  compactVector(mass, keep);
  compactVector(density, keep);
  compactVector(pressure, keep);
  compactVector(viscosityRate, keep);
  compactVector(id, keep);
  compactVector(age, keep);
  compactVector(travelled, keep);
  compactVector(eye, keep);
  compactVector(contact, keep);
  compactVector(clearance, keep);
}

void ParticleSet::clear() {
  std::vector<std::uint8_t> none(position.size(), 0);
  compact(none);
}

std::uint64_t stateHash(const ParticleSet& p) {
  std::uint64_t hash = 0xcbf29ce484222325ull;
  const auto mix = [&hash](const void* data, std::size_t bytes) {
    const auto* b = static_cast<const unsigned char*>(data);
    for (std::size_t k = 0; k < bytes; ++k) hash = (hash ^ b[k]) * 0x100000001b3ull;
  };
  for (int i = 0; i < p.size(); ++i) {
    const auto s = static_cast<std::size_t>(i);
    mix(&p.id[s], sizeof p.id[s]);
    mix(p.position[s].data(), 3 * sizeof(double));
    mix(p.velocity[s].data(), 3 * sizeof(double));
  }
  return hash;
}

}  // namespace lacrima::tears
