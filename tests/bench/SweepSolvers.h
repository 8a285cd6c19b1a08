#pragma once
// The pressure solvers the accuracy benchmarks compare (lacrima-bench tears-sweep and
// tears-slide). Each listed solver gets its own rows, its own converged reference, a thread-axis
// check and its own sliding-drop fit; a further solver is one line in kSolvers.
#include <lacrima/tears/SimulationOptions.h>

#include <iterator>

namespace lacrima::bench {

struct SolverEntry {
  const char* name;  // as tables and legends show it
  const char* key;   // as CSV and JSON write it
  tears::PressureMethod method;
};

inline constexpr SolverEntry kSolvers[] = {
    {"WCSPH", "wcsph", tears::PressureMethod::Wcsph},
    {"DFSPH", "dfsph", tears::PressureMethod::Dfsph},
    {"PBF", "pbf", tears::PressureMethod::Pbf},
};
// The solver of the common reference every sweep row is measured against: the default.
inline constexpr const SolverEntry& kReferenceSolver = kSolvers[0];

inline const SolverEntry& solverOf(tears::PressureMethod method) {
  for (const SolverEntry& s : kSolvers)
    if (s.method == method) return s;
  return kReferenceSolver;  // only listed solvers are run
}

}  // namespace lacrima::bench
