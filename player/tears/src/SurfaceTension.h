#pragma once
// Surface tension, chosen by SimulationOptions::surfaceTension (a key of the registry below,
// TearMethods.h): a force that pulls the fluid's surface together, so drops stay round and
// trails thin instead of spreading into a film. Each model is its own class named after its
// paper, listed once in SurfaceTensionRegistration.cpp:
//   SurfaceTension_Mueller2003.h  the colour-field curvature force (the default);
//   SurfaceTension_Akinci2013.h   cohesion plus curvature minimisation.
// A sub-step calls prepare() before the force pass (FluidForcePass.h), which sums the colour
// field's gradient and Laplacian along the way for a model that asks for them, and then
// addAccelerations() on each chunk of particles as the force pass finishes it, in the pass's
// last shared loop.
#include "ActivePairs.h"
#include "FluidForcePass.h"
#include "MethodRegistry.h"

#include <lacrima/tears/ParticleSet.h>
#include <lacrima/tears/TearSettings.h>

#include <memory>

namespace lacrima::tears {

class SurfaceTension {
 public:
  virtual ~SurfaceTension() = default;

  // Whether the force pass is to sum the colour field's gradient and Laplacian.
  virtual bool needsColourField() const = 0;
  // Work over the sub-step's pairs that the per-particle part needs (none by default).
  virtual void prepare(const ParticleSet& /*particles*/, const ActivePairs& /*pairs*/) {}
  // Adds the tension's accelerations to particles [begin, end); `pass` is the sub-step's force
  // pass, done for those particles. Writes nothing outside the range, so chunks may run on any
  // thread.
  virtual void addAccelerations(ParticleSet& particles, const FluidForcePass& pass,
                                std::size_t begin, std::size_t end) = 0;
};

// Every surface tension model, made from its values and the scaled parameters (which carry its
// strength).
using SurfaceTensionRegistry = MethodRegistry<SurfaceTension, const ScaledParameters&>;
SurfaceTensionRegistry& surfaceTensionRegistry();

}  // namespace lacrima::tears
