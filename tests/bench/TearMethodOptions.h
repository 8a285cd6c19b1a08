#pragma once
// The tear method options of a bench sub-command, read from the simulation's registries
// (tears/TearMethods.h): --solver, --tension and --neighbours take any registered key, and every
// registered method's parameters become --<method>-<parameter> (--pbf-iterations,
// --dfsph-tolerance, ...), usable only with that method chosen. A method registered later
// gets its options without a change here.
#include "BenchCommandLine.h"

#include <lacrima/tears/SimulationOptions.h>

namespace lacrima::bench {

// Writes into `options`' method choices, which start as the defaults the help names.
void addTearMethodOptions(BenchCommandLine& line, tears::SimulationOptions& options);

// "PBF (iterations 4, relaxation 1, artificial-pressure 0)": the method's label and the
// values it runs with, for printouts.
std::string describeMethod(tears::MethodFamily family, const tears::MethodChoice& choice);

}  // namespace lacrima::bench
