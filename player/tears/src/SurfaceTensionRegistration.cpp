// The surface tension models users can choose, in the order the apps and the bench list them;
// the default (SimulationOptions::surfaceTension) is the first.
#include "SurfaceTension.h"
#include "SurfaceTension_Akinci2013.h"
#include "SurfaceTension_Mueller2003.h"

namespace lacrima::tears {

SurfaceTensionRegistry& surfaceTensionRegistry() {
  static SurfaceTensionRegistry registry(
      MethodFamily::SurfaceTension,
      {
          {SurfaceTension_Mueller2003::info(), &SurfaceTension_Mueller2003::create},
          {SurfaceTension_Akinci2013::info(), &SurfaceTension_Akinci2013::create},
      });
  return registry;
}

}  // namespace lacrima::tears
