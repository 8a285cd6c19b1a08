#pragma once
// The pressure solvers the accuracy benchmarks compare (lacrima-bench tears-sweep and
// tears-slide): every registered one (tears/TearMethods.h), the default first, since every
// sweep row is also measured against the default solver's reference. Each gets its own rows,
// its own converged reference, a thread-axis check and its own sliding-drop fit, so a solver
// registered in the simulation is swept without a change here.
#include <lacrima/tears/SimulationOptions.h>
#include <lacrima/tears/TearMethods.h>

#include <algorithm>
#include <string>
#include <vector>

namespace lacrima::bench {

struct SolverEntry {
  std::string name;  // as tables and legends show it (the registry's label)
  std::string key;   // as CSV and JSON write it
};

inline std::vector<SolverEntry> sweepSolvers() {
  const std::string reference = tears::SimulationOptions{}.pressureSolver.key;
  std::vector<SolverEntry> solvers;
  for (const tears::MethodInfo& method :
       tears::registeredMethods(tears::MethodFamily::PressureSolver))
    solvers.push_back({method.label, method.key});
  std::stable_partition(solvers.begin(), solvers.end(),
                        [&reference](const SolverEntry& s) { return s.key == reference; });
  return solvers;
}

}  // namespace lacrima::bench
