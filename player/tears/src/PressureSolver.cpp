#include "PressureSolver.h"

namespace lacrima::tears {

void contactNormals(const ParticleSet& p, const SkinView& skin,
                    std::vector<Eigen::Vector3d>& normals) {
  normals.resize(p.velocity.size());
  for (std::size_t i = 0; i < normals.size(); ++i) {
    const int t = p.contact[i].triangle;
    normals[i] = t >= 0 ? skin.faces[static_cast<std::size_t>(t)].normal : Eigen::Vector3d::Zero();
  }
}

}  // namespace lacrima::tears
