#include "PressureSolver.h"
#include "PressureSolver_DFSPH.h"
#include "PressureSolver_PBF.h"
#include "PressureSolver_WCSPH.h"

#include <algorithm>

namespace lacrima::tears {

std::unique_ptr<PressureSolver> PressureSolver::create(PressureMethod method,
                                                       const ScaledParameters& p,
                                                       const TearSettings& settings,
                                                       const SimulationOptions& options) {
  if (method == PressureMethod::Wcsph)
    return std::make_unique<PressureSolver_WCSPH>(p.stiffness, p.restDensity, p.soundSpeed,
                                                  options.clampNegativePressure);
  if (method == PressureMethod::Pbf) {
    PositionBasedSettings pbf;
    pbf.iterations = std::max(1, options.pbfIterations);
    pbf.relaxation = options.pbfRelaxation;
    pbf.artificialPressure = options.pbfArtificialPressure;
    return std::make_unique<PressureSolver_PBF>(p.h, pbf);
  }
  // The pressure parameter sets how tight the solves are: ten times the default pressure, ten
  // times tighter (SimulationOptions::dfsphTolerance).
  DivergenceFreeSettings dfsph;
  const double stiffness =
      settings.pressure > 0 ? TearSettings{}.pressure / settings.pressure : 1e3;
  dfsph.densityTolerance = std::clamp(options.dfsphTolerance * stiffness, 1e-4, 0.1);
  dfsph.divergenceTolerance = dfsph.densityTolerance;
  dfsph.maxIterations = std::max(2, options.dfsphMaxIterations);
  return std::make_unique<PressureSolver_DFSPH>(p.h, dfsph);
}

void contactNormals(const ParticleSet& p, const SkinView& skin,
                    std::vector<Eigen::Vector3d>& normals) {
  normals.resize(p.velocity.size());
  for (std::size_t i = 0; i < normals.size(); ++i) {
    const int t = p.contact[i].triangle;
    normals[i] = t >= 0 ? skin.faces[static_cast<std::size_t>(t)].normal : Eigen::Vector3d::Zero();
  }
}

}  // namespace lacrima::tears
