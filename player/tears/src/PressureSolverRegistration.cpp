// The pressure solvers users can choose, in the order the apps and the bench list them. The
// default (SimulationOptions::pressureSolver) is the first: the measured best for tears
// (docs/decisions/0009).
#include "PressureSolver.h"
#include "PressureSolver_DFSPH.h"
#include "PressureSolver_PBF.h"
#include "PressureSolver_WCSPH.h"

namespace lacrima::tears {

PressureSolverRegistry& pressureSolverRegistry() {
  static PressureSolverRegistry registry(
      MethodFamily::PressureSolver,
      {
          {PressureSolver_WCSPH::info(), &PressureSolver_WCSPH::create},
          {PressureSolver_DFSPH::info(), &PressureSolver_DFSPH::create},
          {PressureSolver_PBF::info(), &PressureSolver_PBF::create},
      });
  return registry;
}

}  // namespace lacrima::tears
